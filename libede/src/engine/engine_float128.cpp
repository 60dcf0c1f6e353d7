// The engines of the table (engine_factory.hpp) for scalar type __float128 (GCC's libquadmath), built
// only where EDE_HAVE_FLOAT128 is set: a fourth precision for the accuracy study, chosen by a scene's
// engine.scalar = "float128" (ede-sim, ede-bench speed). Such runs write no log: the log, replay and the
// analysis tools know float, double and long double only.
#include "engine/engine_factory.hpp"

namespace ede {
using Scalar = __float128;
template Result<std::unique_ptr<EngineApi<Scalar>>> make_engine_as<Scalar>(EngineKind, const InitialState&,
                                                                            const EngineOptions&,
                                                                            const ResumePoint<Scalar>*);
template Result<std::unique_ptr<EngineApi<Scalar>>> make_engine<Scalar>(const InitialState&, const EngineOptions&,
                                                                        const ResumePoint<Scalar>*);
}  // namespace ede
