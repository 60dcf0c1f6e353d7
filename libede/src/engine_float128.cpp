// The engines for scalar type __float128 (GCC's libquadmath), built only where EDE_HAVE_FLOAT128 is set:
// a fourth precision for the accuracy study (ede-bench accuracy), which runs it without a log. The log,
// replay and the tools know float, double and long double only; scenes never ask for __float128.
#include "engine_factory.hpp"

namespace ede {
template Result<std::unique_ptr<EngineApi<__float128>>> make_engine<__float128>(const InitialState&,
                                                                                const EngineOptions&,
                                                                                const ResumePoint<__float128>*);
}  // namespace ede
