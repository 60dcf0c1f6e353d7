// LogFrames; see frames.hpp.
#include "frames.hpp"

#include <complex>

#include "open_log.hpp"

namespace ede::render {

Result<LogFrames> LogFrames::open(const std::string& path, const std::string& species) {
  auto log = tools::open_log_warning("ede-render", path);
  if (!log) return log.error();
  auto index = species_index(log.value().info(), species);
  if (!index) return Error{path + ": --species: " + index.error().message};
  auto initial = log.value().state_at_event(0);
  if (!initial) return initial.error();
  LogFrames frames(std::move(log).value(), std::move(initial).value(), index.value());
  // The wall segments, from the scene the log ran (a scene that no longer loads has none drawn).
  if (auto scene = frames.log_.scene())
    for (const SegmentSpec& s : scene.value().physics.segments)
      frames.segments_.push_back({s.from[0], s.from[1], s.to[0], s.to[1]});
  return frames;
}

Result<Frame> LogFrames::at(const tools::TimeOption& t, bool with_psi6) {
  auto state = t.end ? log_.state_at_end() : log_.state_at(t.t);
  if (!state) return state.error();
  Frame f{disk_frame(state.value(), initial_, species_), {}};
  f.segments = segments_;
  if (with_psi6) {
    const State& s = state.value();
    const std::vector<std::complex<double>> p = ede::psi6(s);
    for (std::size_t i = 0; i < p.size(); ++i)
      if (species_ == kAllSpecies || s.species[i] == species_) f.psi6.push_back(std::abs(p[i]));
  }
  return f;
}

}  // namespace ede::render
