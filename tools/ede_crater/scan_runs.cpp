// run_scans: the runs of a scan, in-process, a few at a time on std::thread workers (see scan.hpp).
//
// Independent runs are where DESIGN.md allows threads: each run is its own Simulation with its own log
// file, so nothing any run computes depends on timing; a worker takes the next run by index and stores
// its outcome at that index. The log of a run is byte-identical to what `ede-sim SCENE --set ... -o LOG`
// writes (the same library, the same scene). Rejected: ede-sim child processes (the previous design),
// which needed the ede-sim binary beside this one, a process pool of fork + exec, and exit codes and
// stderr files to learn what the library can say directly. Each worker measures its run's log right after
// the run (results stored by index, so nothing depends on which run finished first), which lets
// --no-logs delete each log at once: a scan's disk use is a few logs, not all (903 MB were seen).
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <mutex>
#include <thread>

#include "scan.hpp"

namespace ede::crater_tool {

namespace {

struct Outcome {
  bool started = false;
  std::string failure;  // empty if the run finished
  MeasuredLog measured;
};

Outcome run_one(const ScanRun& run, const std::string& dir, const MeasureOptions& measure, bool keep_log) {
  const std::string base = dir + "/" + run.name;
  SimulationOptions options;
  options.log_path = base + ".ede";
  auto sim = Simulation::create(run.scene, options);
  if (!sim) return {true, sim.error().message, {}};
  sim.value().run();  // Stalled and Collapsed are outcomes, not failures: the log is complete, the run marked
  if (Status closed = sim.value().close(); !closed) return {true, closed.error().message, {}};
  if (Status s = write_text_file(base + ".txt", to_text(sim.value().summary())); !s) return {true, s.error().message, {}};
  auto m = measure_log(options.log_path, measure);
  if (!keep_log) std::remove(options.log_path.c_str());
  if (!m) return {true, m.error().message, {}};
  return {true, "", std::move(m).value()};
}

}  // namespace

bool run_suspect(const std::string& status) {
  for (const char* word : {"collapse", "stalled", "non-finite", "incomplete"})
    if (status.find(word) != std::string::npos) return true;
  return false;
}

Result<std::vector<MeasuredLog>> run_scans(const std::vector<ScanRun>& runs, const std::string& dir, std::size_t jobs,
                                           bool progress, const MeasureOptions& measure, bool keep_logs) {
  std::vector<Outcome> outcomes(runs.size());
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::mutex report;
  std::size_t finished = 0;
  const auto work = [&] {
    while (!failed) {
      const std::size_t k = next++;
      if (k >= runs.size()) return;
      outcomes[k] = run_one(runs[k], dir, measure, keep_logs);
      const bool ok = outcomes[k].failure.empty();
      if (!ok) failed = true;
      if (!progress) continue;
      const std::lock_guard<std::mutex> lock(report);
      const std::string& status = outcomes[k].measured.run_status;
      std::fprintf(stderr, "ede-crater: %zu/%zu runs done (%s%s%s)\n", ++finished, runs.size(), runs[k].label.c_str(),
                   ok ? "" : ": failed", ok && run_suspect(status) ? (": " + status).c_str() : "");
    }
  };
  std::vector<std::thread> workers;
  for (std::size_t w = 0; w < std::max<std::size_t>(1, std::min(jobs, runs.size())); ++w) workers.emplace_back(work);
  for (std::thread& w : workers) w.join();
  std::vector<MeasuredLog> measured;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    if (!outcomes[k].failure.empty()) return Error{"the run " + runs[k].label + " failed: " + outcomes[k].failure};
    measured.push_back(std::move(outcomes[k].measured));
  }
  return measured;
}

}  // namespace ede::crater_tool
