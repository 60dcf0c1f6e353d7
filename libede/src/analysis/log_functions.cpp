// The analyses of ede/analysis.hpp, ede/pressure.hpp and ede/crater.hpp on a public Log: each forwards to
// its implementation on the log's reader (the tests and tools of the first version call those directly).
#include "analysis/crater.hpp"
#include "analysis/log_series.hpp"
#include "analysis/pressure.hpp"
#include "replay/log_impl.hpp"

namespace ede {

Result<LogOverview> log_overview(const Log& log) { return log_overview(reader_of(log)); }

Result<LogSeries> log_series(const Log& log, const std::vector<double>& times) {
  return log_series(reader_of(log), times);
}

Status for_each_snapshot(const Log& log, const std::vector<double>& times,
                         const std::function<void(const GasSnapshot&)>& f) {
  return for_each_snapshot(reader_of(log), times, f);
}

Result<PressureReport> measure_pressure(const Log& log, const PressureOptions& options) {
  return measure_pressure(reader_of(log), options);
}

Result<EnergyFractionCurve> energy_fraction_curve(const Log& log, double fraction, std::size_t points) {
  return energy_fraction_curve(reader_of(log), fraction, points);
}

Result<BedSelection> select_bed(const Log& log, const std::string& name) {
  return select_bed(reader_of(log)->header(), name);
}

Result<CraterMeasurement> measure_crater(const Log& log, const CraterRequest& request) {
  return measure_crater(reader_of(log), request);
}

}  // namespace ede
