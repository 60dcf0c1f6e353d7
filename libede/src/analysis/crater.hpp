// The crater's log layer on a LogReader (ede/crater.hpp has the geometry, the types and the Log overloads).
#pragma once

#include <memory>
#include <string>

#include "ede/crater.hpp"
#include "log/log_reader.hpp"

namespace ede {

Result<EnergyFractionCurve> energy_fraction_curve(std::shared_ptr<const LogReader> log, double fraction,
                                                  std::size_t points = 501);
Result<BedSelection> select_bed(const LogHeaderInfo& header, const std::string& name);
Result<CraterMeasurement> measure_crater(std::shared_ptr<const LogReader> log, const CraterRequest& request);

}  // namespace ede
