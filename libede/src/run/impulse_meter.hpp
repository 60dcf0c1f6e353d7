// ImpulseMeter<T>: a sink that sums, over every event of a run, the normal momentum each wall receives and
// the pair-collision virial W = sum r_ij . dp_i, for Simulation::impulses (a live pressure monitor).
//
// The formulas are those of the log's pressure pass (analysis/pressure_pass.cpp, ede/pressure.hpp), in
// long double: a wall event of disk i adds m_i |v' - v| (normal component: x for left and right, y for
// bottom and top), a pair event adds (r_i - r_j) . m_i (v_i' - v_i) with the positions at the event
// (minimum image in a periodic box). The velocities before the event come with the event (EventOutcome's
// vix0, viy0), so no mirror of the velocities is kept. Differences of two readings are a window's sums.
// Rejected: computing the pressure inside the engine (the engine knows nothing of observables; sinks are
// its read-only observers, and this one costs nothing unless asked for) and a ring of per-interval sums
// (the caller picks its window by keeping the readings it wants).
#pragma once

#include <cmath>
#include <cstdint>

#include "ede/simulation.hpp"
#include "core/sink.hpp"

namespace ede {

template <class T>
class ImpulseMeter final : public Sink<T> {
 public:
  ImpulseMeter(bool periodic, double lx, double ly) : periodic_(periodic), lx_(lx), ly_(ly) {}

  void on_event(const EventOutcome<T>& e, const Particles<T>& p) override {
    if (e.kind == EventKind::Pair || e.kind == EventKind::Step) {  // a step's impulse is a pair's too
      const std::size_t i = std::size_t(e.i), j = std::size_t(e.j);
      long double dx = (long double)p.disk[i].x - p.disk[j].x, dy = (long double)p.disk[i].y - p.disk[j].y;
      if (periodic_) {
        dx -= lx_ * std::nearbyint(dx / lx_);
        dy -= ly_ * std::nearbyint(dy / ly_);
      }
      const long double m = p.mass(i);
      virial_ += dx * m * ((long double)e.vix - e.vix0) + dy * m * ((long double)e.viy - e.viy0);
      if (e.kind == EventKind::Pair) ++pairs_;
    } else if (e.kind == EventKind::Wall && e.j >= 0 && e.j < 4) {
      const bool vertical = e.j == kWallLeft || e.j == kWallRight;
      const long double m = p.mass(std::size_t(e.i));
      const long double dv = vertical ? (long double)e.vix - e.vix0 : (long double)e.viy - e.viy0;
      wall_[e.j] += m * std::fabs(dv);
      ++walls_;
    }
  }

  ImpulseSums sums(double time) const {
    ImpulseSums s;
    s.time = time;
    for (int w = 0; w < 4; ++w) s.wall[std::size_t(w)] = double(wall_[w]);
    s.virial = double(virial_);
    s.pair_collisions = pairs_;
    s.wall_collisions = walls_;
    return s;
  }

 private:
  bool periodic_;
  long double lx_, ly_;
  long double wall_[4] = {}, virial_ = 0;
  std::uint64_t pairs_ = 0, walls_ = 0;
};

}  // namespace ede
