// measure_pressure on a LogReader (ede/pressure.hpp has the physics, the types and the Log overload).
#pragma once

#include <memory>

#include "ede/pressure.hpp"
#include "log/log_reader.hpp"

namespace ede {

Result<PressureReport> measure_pressure(const std::shared_ptr<const LogReader>& log, const PressureOptions& options);

}  // namespace ede
