// make_study_engine, and the study's own engines: the two elastic engines of the library's table
// (engine/engine_factory.hpp) with the textbook contact root, for float, double and long double (6). The
// engine template stays in the library (engine/engine_core.hpp); only these instantiations live here, so
// the product library carries no study code. __float128 has none: its rows in the accuracy study are
// about how far round-off can be pushed, and the two roots differ by round-off alone.
#include "study/study_engine.hpp"

#include <type_traits>

#include "ede/internal/engine_template.hpp"
#include "study/textbook_contact.hpp"

namespace ede::study {

namespace {

template <class T>
using EngineResult = Result<std::unique_ptr<EngineApi<T>>>;

template <class T>
EngineResult<T> make_textbook_engine(const InitialState& init, const EngineOptions& o, const ResumePoint<T>* resume) {
  constexpr bool kBuilt = std::is_same_v<T, float> || std::is_same_v<T, double> || std::is_same_v<T, long double>;
  if constexpr (!kBuilt) {
    return Error{"the textbook contact root is built for float, double and long double only"};
  } else {
    const Result<GridShape> shape = check_engine_start(init, o, resume);
    if (!shape) return shape.error();
    switch (engine_kind_for(o)) {
      case EngineKind::PeriodicElastic:
        return std::unique_ptr<EngineApi<T>>(std::make_unique<Engine<T, PeriodicBoundary, Elastic, NoField, TextbookContact>>(
            init, o, shape.value(), resume));
      case EngineKind::WallsElastic:
        return std::unique_ptr<EngineApi<T>>(std::make_unique<Engine<T, WallsBoundary, Elastic, NoField, TextbookContact>>(
            init, o, shape.value(), resume));
      default:
        return Error{"the textbook contact root is built for elastic scenes without gravity only"};
    }
  }
}

}  // namespace

template <class T>
EngineResult<T> make_study_engine(const InitialState& init, const EngineOptions& o, EngineVariant variant,
                                  const ResumePoint<T>* resume) {
  if (variant.all_effects && variant.contact != ContactRoot::Stable)
    return Error{"the all-effects engine has the stable contact root only"};
  if (variant.all_effects) return make_engine_as<T>(EngineKind::WallsGravity, init, o, resume);
  if (variant.contact == ContactRoot::Textbook) return make_textbook_engine<T>(init, o, resume);
  return make_engine<T>(init, o, resume);
}

template EngineResult<float> make_study_engine<float>(const InitialState&, const EngineOptions&, EngineVariant,
                                                      const ResumePoint<float>*);
template EngineResult<double> make_study_engine<double>(const InitialState&, const EngineOptions&, EngineVariant,
                                                        const ResumePoint<double>*);
template EngineResult<long double> make_study_engine<long double>(const InitialState&, const EngineOptions&,
                                                                  EngineVariant, const ResumePoint<long double>*);
#if EDE_HAVE_FLOAT128
template EngineResult<__float128> make_study_engine<__float128>(const InitialState&, const EngineOptions&,
                                                                EngineVariant, const ResumePoint<__float128>*);
#endif

}  // namespace ede::study
