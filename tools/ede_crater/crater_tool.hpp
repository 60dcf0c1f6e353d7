// What the ede-crater subcommands share: registration, messages, the measuring options, CSV output.
//
// Each subcommand lives in its own file and registers itself with add_*_command, which returns the function
// main calls once the command line is parsed (the pattern of ede-replay). Both subcommands measure logs
// through one function (measure_log), so a scan's numbers are exactly what `ede-crater LOG` prints for
// each of its logs. CSV files hold numbers with the digits that read back to the same double.
// Rejected: a scan that keeps the measurements of its runs from the runs themselves (the final state),
// which would tie the metric to each run's stop and make a scan's numbers differ from `ede-crater LOG`'s.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "ede/ede.hpp"
#include "ede/number_text.hpp"
#include "report_error.hpp"

namespace ede::crater_tool {

using Command = std::function<int()>;

Command add_measure_command(CLI::App& app);
Command add_scan_command(CLI::App& app);

// An error about the input: message on stderr, exit status 1.
inline int fail(const std::string& message) {
  ede::tools::report_error("ede-crater", message);
  return 1;
}

// A command line that parsed but asks for something impossible: exit status 2, like a parse error.
inline int usage_error(const std::string& message) {
  std::fprintf(stderr, "ede-crater: %s (see ede-crater --help)\n", message.c_str());
  return 2;
}


// The options of a measurement, as typed; shared by `measure` and `scan` (measure_options.cpp).
struct MeasureOptions {
  std::string at;                // --at T|end: a time, read exactly in the log's scalar type
  std::string before;            // --before T: the reference state's time (default: the log's start)
  double energy_fraction = 0.1;  // --energy-fraction F
  std::string species;           // --species NAME: the bed's species
  std::string threshold = "0.5r", bin_width = "2r", drop_threshold = "1r", link_gap = "2r";
  bool keep_detached = false;
  std::size_t points = 501;      // --curve-points
};

// Adds the measuring options to a (sub)command.
void add_measure_options(CLI::App& app, MeasureOptions& o);

// The options as library settings: a length "0.002" is in box units, "0.5r" in bed radii.
Result<CraterSettings> settings_from(const MeasureOptions& o);

// A log's crater and what the log says of its run.
struct MeasuredLog {
  CraterMeasurement crater;
  std::string run_status;  // "reached stop.energy_fraction", or "incomplete: ..." for a log cut short
  std::uint64_t disks = 0;
  std::string scalar;
};

// Opens the log and measures its crater.
Result<MeasuredLog> measure_log(const std::string& path, const MeasureOptions& o);

// CSV output (crater_csv.cpp). A field holding a comma or a quote is quoted.
std::string csv_field(const std::string& text);
// x_left,x_right,x,h_before,h_after,drop,in_crater,disks_before,disks_after: one row per bin.
Status write_profile_csv(const std::string& path, const CraterMeasurement& m);
// t,energy_fraction: the curve.
Status write_energy_csv(const std::string& path, const CraterMeasurement& m);
// A text file written whole; the error names the file.
Status write_text_file(const std::string& path, const std::string& text);

}  // namespace ede::crater_tool
