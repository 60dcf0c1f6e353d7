// The log-series functions on a LogReader (ede/analysis.hpp has the types and the Log overloads). See
// log_series.cpp for how the walk works.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "ede/analysis.hpp"
#include "log/log_reader.hpp"

namespace ede {

Result<LogOverview> log_overview(const std::shared_ptr<const LogReader>& log);
Result<LogSeries> log_series(const std::shared_ptr<const LogReader>& log, const std::vector<double>& times);
Status for_each_snapshot(const std::shared_ptr<const LogReader>& log, const std::vector<double>& times,
                         const std::function<void(const GasSnapshot&)>& f);

}  // namespace ede
