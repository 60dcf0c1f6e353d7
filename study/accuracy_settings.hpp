// The accuracy settings of ede-bench accuracy and what every measurement of it shares: the scalar type
// (float, double, long double, and __float128 where the build has it: EDE_HAVE_FLOAT128) and the pair
// contact root (stable or textbook); loading a study scene with a setting applied; the energy summed in a
// type at least as wide as the run's; one ulp up in the run's own type. The study keeps its own Precision
// (not ScalarKind) so that every switch over it is here.
// A setting is a (precision, contact) pair run through the same measurements, so the contact root is not
// a measurement file of its own. Rejected: a scene file per scalar type (the study applies every type
// to the same file, by override).
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ede/error.hpp"
#include "ede/internal/run.hpp"
#include "ede/scene.hpp"
#include "study/study_engine.hpp"

namespace ede::study {

enum class Precision { Float, Double, LongDouble, Float128 };

struct Setting {
  Precision precision = Precision::Double;
  ContactRoot contact = ContactRoot::Stable;
  std::string label() const;  // "double", "float, textbook root", ...
};

const char* precision_name(Precision p);  // "float", "double", "long double", "__float128"
bool precision_built(Precision p);        // __float128 only with EDE_HAVE_FLOAT128
bool has_log(Precision p);                // the log writer exists for every type but __float128
// Every precision this build has with the stable root, then the hardware types with the textbook root.
// __float128 (software arithmetic, 10-20x the time of double per event) runs the stable root only: its
// rows are there for how far round-off can be pushed, and the roots differ by round-off alone.
std::vector<Setting> study_settings();

// Calls f.template operator()<T>() with the setting's scalar type, like with_scalar.
template <class F>
decltype(auto) with_precision(Precision p, F&& f) {
  switch (p) {
    case Precision::Float: return f.template operator()<float>();
    case Precision::LongDouble: return f.template operator()<long double>();
#if EDE_HAVE_FLOAT128
    case Precision::Float128: return f.template operator()<__float128>();
#else
    case Precision::Float128: break;  // not built: refused by precision_built before we get here
#endif
    case Precision::Double: break;
  }
  return f.template operator()<double>();
}

// The scene override that records p in a scene ("engine.scalar=float", ..., "engine.scalar=float128").
std::string scalar_override(Precision p);

// A scene ready to run with a setting: its stop condition is the caller's to set (options.stop); the
// scene's own stop.events (after overrides) is how long the study's long runs are.
struct StudyScene {
  Scene scene;
  InitialState initial;
  EngineOptions options;
  EngineVariant variant;  // the setting's contact root

  template <class T>
  Result<std::unique_ptr<EngineApi<T>>> engine(const EngineOptions& o, const ResumePoint<T>* resume = nullptr) const {
    return make_study_engine<T>(initial, o, variant, resume);
  }
};
// Loads `path` with `overrides`, records the setting's scalar type in the scene (a log header names it; a
// float128 run writes no log) and sets the contact root.
Result<StudyScene> load_study_scene(const std::string& path, const Setting& setting,
                                    std::vector<std::string> overrides = {});

// The time at which the disks of a run of `s` have had `collisions` collisions each (a probe run).
template <class T>
Result<double> time_at_collisions(const StudyScene& s, double collisions) {
  EngineOptions o = s.options;
  o.stop = StopSpec{};
  o.stop.collisions_per_particle = collisions;
  auto e = s.engine<T>(o);
  if (!e) return e.error();
  if (e.value()->run() == RunStatus::Stalled) return Error{e.value()->stall_message()};
  return double(e.value()->time());
}

// Sums that must not round away what they measure: long double for float, double and long double runs,
// __float128 for __float128 runs.
template <class T>
struct Wide {
  using type = long double;
};
#if EDE_HAVE_FLOAT128
template <>
struct Wide<__float128> {
  using type = __float128;
};
#endif

// Kinetic energy from the records' velocities (no gravity in the study's scenes), in Wide<T> with
// compensated (Neumaier) summation: a plain sum of N terms in long double is only good to ~sqrt(N) eps,
// about the drift of a whole long double run, which it would hide.
template <class T>
typename Wide<T>::type kinetic_energy_wide(const Particles<T>& p) {
  using W = typename Wide<T>::type;
  W sum = 0, lost = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const W vx = W(p.disk[i].vx), vy = W(p.disk[i].vy);
    const W term = W(p.mass(i)) * (vx * vx + vy * vy);
    const W next = sum + term;
    lost += (sum > term ? sum - next + term : term - next + sum);  // sum >= 0, term >= 0: no abs needed
    sum = next;
  }
  return (sum + lost) / 2;
}

// |E - E0| / E0 as a double (the difference is taken in the wide type).
template <class W>
double relative_change(W e, W e0) {
  const W d = e > e0 ? e - e0 : e0 - e;
  return double(d / e0);
}

// The next representable number above x in T.
template <class T>
T one_ulp_up(T x) {
  return std::nextafter(x, std::numeric_limits<T>::infinity());
}
#if EDE_HAVE_FLOAT128
// x > 0 and itself a double (initial positions are): x lies in [2^(e-1), 2^e), where quad's ulp is 2^(e-113).
inline __float128 one_ulp_up(__float128 x) {
  int e = 0;
  (void)std::frexp(double(x), &e);
  return x + __float128(std::ldexp(1.0, e - 113));
}
#endif

// x's distance to 0 in a periodic box of side `length` (minimum image), or |x| with walls.
template <class T>
double image_distance(T x, T length, bool periodic) {
  double d = std::fabs(double(x));
  const double l = double(length);
  if (periodic && d > l / 2) d = l - d;
  return d;
}

}  // namespace ede::study
