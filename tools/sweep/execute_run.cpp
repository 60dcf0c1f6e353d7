// One run, from a worker's side (see sweep.hpp): reuse, or a child process with retries.
//
// Reuse needs all of: the row file, with the same overrides and a final status, and the log it names,
// complete, holding the scene the run would load now (an edited base scene makes old rows stale), whose
// content digest (a replay of the whole log: what it says, not how it is stored) equals the row's.
// Anything less and the run is done again (its log resumed if a killed process left one).
// A child that finds the sweep's inputs changed (sweep_inputs.hpp) makes every later run of this
// execution "changed" at once: they would all be refused the same way.
#include <sys/statvfs.h>

#include <atomic>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "process.hpp"
#include "stop_signal.hpp"
#include "ede/number_text.hpp"
#include "sweep.hpp"
#include "sweep_inputs.hpp"

namespace ede::sweep {

namespace {

std::atomic<bool> g_inputs_changed{false};

std::string inputs_changed_error(const Sweep& s) {
  return "not run: " + s.spec.path + " or its scene " + s.spec.scene_path +
         " changed while the sweep ran, so this run would not be the one planned. Fix: run the sweep again "
         "(finished runs are reused where they still match)";
}

// The last line of the child's stderr, or what the disk says when there is none (a full disk keeps even
// that from being written).
std::string why_no_result(const Sweep& s, const std::string& err_path) {
  std::ifstream in(err_path);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  if (!last.empty()) return ": " + last.substr(0, 2000);
  struct statvfs fs {};
  if (::statvfs(runs_dir(s).c_str(), &fs) == 0) {
    // Less than a log's first frame free: the disk is the likely cause; with room to spare it is not.
    const unsigned long long free_bytes = (unsigned long long)fs.f_bavail * fs.f_frsize;
    return " and wrote nothing on stderr; " + runs_dir(s) + " has " + std::to_string(free_bytes) + " bytes free now" +
           (free_bytes < (1u << 20) ? " (the disk is full)" : "");
  }
  return " and wrote nothing on stderr";
}

}  // namespace

RunRow pending_row(const Sweep& s, std::size_t k) {
  RunRow row;
  row.index = k, row.name = s.runs[k].name, row.overrides = s.runs[k].overrides, row.status = "pending";
  row.values.assign(s.spec.collect.size(), std::numeric_limits<double>::quiet_NaN());
  row.error = "not finished when this table was written: the sweep was still running, or was stopped (killed, a "
              "rank lost, the disk full) before this run ended. Fix: run the sweep again to finish it";
  return row;
}

std::string runs_dir(const Sweep& s) { return s.runs_folder.empty() ? s.results : s.results + "/" + s.runs_folder; }
std::string log_path(const Sweep& s, const PlannedRun& r) { return runs_dir(s) + "/" + r.name + ".ede"; }
std::string row_path(const Sweep& s, const PlannedRun& r) { return runs_dir(s) + "/" + r.name + ".json"; }
std::string log_cell(const Sweep& s, const PlannedRun& r) {
  return (s.runs_folder.empty() ? "" : s.runs_folder + "/") + r.name + ".ede";
}

std::vector<std::string> own_command_line() {
  std::vector<std::string> argv = {std::filesystem::read_symlink("/proc/self/exe").string()};
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  std::string arg;
  for (bool first = true; std::getline(in, arg, '\0'); first = false)
    if (!first) argv.push_back(arg);
  return argv;
}

std::optional<RunRow> reusable_row(const Sweep& s, const PlannedRun& r) {
  auto row = read_row_file(row_path(s, r));
  if (!row || row.value().overrides != r.overrides || !final_status(row.value().status) ||
      row.value().collect != s.spec.collect || row.value().values.size() != s.spec.collect.size() ||
      row.value().measured_with != s.measured_with || row.value().digest.empty())
    return std::nullopt;
  auto log = Log::open(log_path(s, r));
  if (!log || !log.value().info().complete) return std::nullopt;
  auto scene = scene_of(s, r);
  if (!scene || scene.value().source_text != log.value().info().scene_text) return std::nullopt;
  auto digest = log.value().content_digest();
  if (!digest || digest.value() != row.value().digest) return std::nullopt;
  RunRow out = std::move(row).value();
  out.index = r.index;
  out.reused = true;
  return out;
}

RunRow execute_run(const Sweep& s, std::size_t k) {
  const PlannedRun& r = s.runs[k];
  if (auto row = reusable_row(s, r)) return *row;
  if (g_inputs_changed) {
    RunRow none = pending_row(s, k);
    none.status = "changed";
    none.error = inputs_changed_error(s);
    return none;
  }
  if (stop_requested()) {
    RunRow none;
    none.index = r.index, none.name = r.name, none.overrides = r.overrides, none.status = "interrupted";
    none.values.assign(s.spec.collect.size(), std::numeric_limits<double>::quiet_NaN());
    none.error = "not run: the sweep was interrupted";
    return none;
  }
  std::vector<std::string> argv = s.child_argv;
  argv.push_back("--child");
  argv.push_back(std::to_string(k));
  const std::string err_path = runs_dir(s) + "/" + r.name + ".err";
  RunRow row;
  row.index = r.index;
  row.name = r.name;
  row.overrides = r.overrides;
  row.collect = s.spec.collect;
  row.log = log_cell(s, r);
  row.values.assign(s.spec.collect.size(), std::numeric_limits<double>::quiet_NaN());
  const auto no_log = [&](RunRow& out) {
    if (!std::filesystem::exists(log_path(s, r))) out.log.clear();
    return out;
  };
  for (int attempt = 0; attempt <= s.spec.retries; ++attempt) {
    auto end = tools::run_program({argv, false, "", err_path, s.spec.timeout});
    if (!end) {
      row.status = "failed";
      row.error = end.error().message;
      return row;
    }
    if (auto written = read_row_file(row_path(s, r)); written && end.value().exit_status == 0) {
      std::error_code ignored;
      if (std::filesystem::file_size(err_path, ignored) == 0) std::filesystem::remove(err_path, ignored);
      return std::move(written).value();
    }
    row.wall_seconds = end.value().wall_seconds;
    if (!end.value().signalled && end.value().exit_status == kInputsChanged) {
      g_inputs_changed = true;
      no_log(row);
      row.status = "changed";
      row.error = inputs_changed_error(s);
      return row;
    }
    if (stop_requested()) {
      row.status = "interrupted";
      row.error = "the sweep was interrupted (its log is kept: a rerun resumes it)";
      return row;
    }
    if (end.value().timed_out) {
      no_log(row);
      row.status = "timeout";
      row.error = "stopped after the sweep's timeout of " + brief(s.spec.timeout) +
                  " s (its log is kept: a rerun resumes it; raise timeout = ... to let it finish)";
      return row;  // a stalled run is not retried: it would stall again
    }
    const int code = end.value().signalled ? end.value().exit_status - 128 : end.value().exit_status;
    row.status = end.value().signalled ? "killed" : "crashed";
    row.error = "the run's process " +
                (end.value().signalled ? "was killed by signal " + std::to_string(code) + " (" + strsignal(code) + ")"
                                       : "exited with status " + std::to_string(code)) +
                " without a result, " + std::to_string(attempt + 1) + " time" + (attempt ? "s" : "") + " (stderr in " +
                err_path + ")" + why_no_result(s, err_path);
  }
  return no_log(row);
}

}  // namespace ede::sweep
