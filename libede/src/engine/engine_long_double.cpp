// The six engines (walls/periodic x elastic/inelastic/inelastic+TC) for scalar type long double.
#include "engine/engine_factory.hpp"

namespace ede {
template Result<std::unique_ptr<EngineApi<long double>>> make_engine<long double>(const InitialState&, const EngineOptions&,
                                                                  const ResumePoint<long double>*);
}  // namespace ede
