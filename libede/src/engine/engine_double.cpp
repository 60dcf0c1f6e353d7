// The engines of the table (engine_factory.hpp) for scalar type double.
#include "engine/engine_factory.hpp"

namespace ede {
using Scalar = double;
template Result<std::unique_ptr<EngineApi<Scalar>>> make_engine_as<Scalar>(EngineKind, const InitialState&,
                                                                            const EngineOptions&,
                                                                            const ResumePoint<Scalar>*);
template Result<std::unique_ptr<EngineApi<Scalar>>> make_engine<Scalar>(const InitialState&, const EngineOptions&,
                                                                        const ResumePoint<Scalar>*);
}  // namespace ede
