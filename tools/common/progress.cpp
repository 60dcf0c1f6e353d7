// Progress reporting; see progress.hpp.
#include "progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ede::tools {

double progress_fraction(const StopSpec& stop, std::uint64_t disks, const ProgressInputs& now) {
  double f = 0;
  if (stop.time && *stop.time > 0) f = std::max(f, now.time / *stop.time);
  if (stop.events && *stop.events > 0) f = std::max(f, double(now.events) / double(*stop.events));
  if (stop.collisions_per_particle && disks > 0)
    f = std::max(f, 2.0 * double(now.pairs) / double(disks) / *stop.collisions_per_particle);
  if (stop.energy_fraction && *stop.energy_fraction < 1 && now.energy_ratio < 1)  // log scale: decay is ~exponential
    f = std::max(f, std::log(now.energy_ratio) / std::log(*stop.energy_fraction));
  return std::clamp(f, 0.0, 1.0);
}

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
