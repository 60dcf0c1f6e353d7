// The local pool (see local_pool.hpp).
#include "local_pool.hpp"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <mutex>
#include <thread>

#include "ede/number_text.hpp"

namespace ede::sweep {

void report_run(const Sweep& s, const RunRow& row, std::size_t done) {
  if (!s.progress) return;
  std::fprintf(stderr, "%s: %zu/%zu %s %s%s%s\n", s.tool.c_str(), done, s.runs.size(), row.name.c_str(), row.status.c_str(),
               row.reused ? " (reused)" : (" (" + brief(row.wall_seconds, 3) + " s)").c_str(),
               row.error.empty() ? "" : (": " + row.error).c_str());
}

std::vector<RunRow> run_local(const Sweep& s, std::size_t jobs) {
  std::vector<RunRow> rows;
  for (std::size_t k = 0; k < s.runs.size(); ++k) rows.push_back(pending_row(s, k));
  std::atomic<std::size_t> next{0};
  std::mutex report;  // guards rows: on_rows reads them all
  std::size_t done = 0;
  if (s.on_rows) s.on_rows(rows);
  const auto work = [&] {
    for (;;) {
      const std::size_t k = next++;
      if (k >= s.runs.size()) return;
      RunRow row = execute_run(s, k);
      const std::lock_guard<std::mutex> lock(report);
      rows[k] = std::move(row);
      report_run(s, rows[k], ++done);
      if (s.on_rows) s.on_rows(rows);
    }
  };
  std::vector<std::thread> workers;
  for (std::size_t w = 0; w < std::max<std::size_t>(1, std::min(jobs, s.runs.size())); ++w) workers.emplace_back(work);
  for (std::thread& w : workers) w.join();
  return rows;
}

}  // namespace ede::sweep
