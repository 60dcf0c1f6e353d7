// Progress reporting; see progress.hpp.
#include "progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace ede::tools {

ProgressReporter::ProgressReporter(bool enabled, std::string label)
    : enabled_(enabled), terminal_(isatty(STDERR_FILENO) != 0), label_(std::move(label)),
      start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

void ProgressReporter::update(double fraction, std::uint64_t events, double sim_time) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const double since_draw = std::chrono::duration<double>(now - last_draw_).count();
  if (since_draw < (terminal_ ? 0.2 : 5.0)) return;
  last_draw_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double rate = elapsed > 0 ? double(events) / elapsed : 0;
  if (terminal_) {
    const int width = 30, filled = int(fraction * width + 0.5);
    std::fprintf(stderr, "\r%s [%.*s%*s] %5.1f%%  t=%-10.4g %.3g M events/s ", label_.c_str(), filled,
                 "##############################", width - filled, "", 100 * fraction, sim_time, rate / 1e6);
    drawn_ = true;
  } else {
    std::fprintf(stderr, "%s: %5.1f%%  t=%.6g  %llu events  %.3g M events/s\n", label_.c_str(), 100 * fraction,
                 sim_time, static_cast<unsigned long long>(events), rate / 1e6);
  }
  std::fflush(stderr);
}

void ProgressReporter::finish() {
  if (enabled_ && terminal_ && drawn_) std::fputs("\r\033[K", stderr);
}

}  // namespace ede::tools
