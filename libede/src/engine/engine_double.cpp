// The six engines (walls/periodic x elastic/inelastic/inelastic+TC) for scalar type double.
#include "engine/engine_factory.hpp"

namespace ede {
template Result<std::unique_ptr<EngineApi<double>>> make_engine<double>(const InitialState&, const EngineOptions&,
                                                                  const ResumePoint<double>*);
}  // namespace ede
