// The six engines (walls/periodic x elastic/inelastic/inelastic+TC) for scalar type float.
#include "engine/engine_factory.hpp"

namespace ede {
template Result<std::unique_ptr<EngineApi<float>>> make_engine<float>(const InitialState&, const EngineOptions&,
                                                                  const ResumePoint<float>*);
}  // namespace ede
