// LogStates for each scalar type: Replay<T> underneath, Frames of doubles out; see log_states.hpp.
//
// Time text is parsed in the log's type (exact_text.hpp: the strto* of T) and checked against
// Replay::final_time(); "end" of an incomplete log seeks by event count (exact in every type, as
// ede-replay does). Rejected: parsing times as double for every log (a long double log's times would be
// rounded).
#include "log_states.hpp"
#include "open_log.hpp"

#include <algorithm>
#include <cmath>

#include "log/log_reader.hpp"
#include "replay/replay.hpp"
#include "exact_text.hpp"
#include "core/scalar_dispatch.hpp"

namespace ede::render {

namespace {

template <class T>
class TypedLogStates final : public LogStates {
 public:
  TypedLogStates(std::shared_ptr<LogReader> log, std::unique_ptr<Replay<T>> replay)
      : log_(std::move(log)), replay_(std::move(replay)) {}

  Status load_initial() {
    if (Status s = replay_->seek_event(0); !s) return s;
    const Particles<T>& p = replay_->particles();
    const T t0 = replay_->time();
    double sum = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      x0_.push_back(double(p.x_at(i, t0)));
      y0_.push_back(double(p.y_at(i, t0)));
      sum += std::hypot(double(p.disk[i].vx), double(p.disk[i].vy));
    }
    mean_speed0_ = p.size() ? sum / double(p.size()) : 0;
    return Ok{};
  }

  Result<TimePoint> parse_time(const std::string& text, const char* what) const override {
    const T end = replay_->final_time();
    const tools::ReadTime<T> t = tools::read_time<T>(text);
    switch (t.kind) {
      case tools::TimeText::End: return TimePoint{static_cast<long double>(end), true};
      case tools::TimeText::NotANumber:
        return Error{std::string(what) + " '" + text + "' is not a number (a time such as 0.5 or 1e-3, or 'end')"};
      case tools::TimeText::Negative: return Error{std::string(what) + " '" + text + "' is negative"};
      case tools::TimeText::Number: break;
    }
    if (t.value > end)
      return Error{log_->path() + ": " + what + " " + text + " is after the end of the log (t = " + tools::exact(end) +
                   (log_->complete() ? "" : "; the log is incomplete") + "); 'end' gives the last state"};
    return TimePoint{static_cast<long double>(t.value), false};
  }

  TimePoint between(const TimePoint& a, const TimePoint& b, long double fraction) const override {
    if (fraction >= 1) return b;
    if (fraction <= 0) return a;
    const T t = static_cast<T>(a.t + (b.t - a.t) * fraction);
    return TimePoint{std::clamp(static_cast<long double>(t), a.t, b.t), false};
  }

  Status seek(const TimePoint& t) override {
    if (t.end && !log_->complete()) return replay_->seek_event(log_->total_events());
    return replay_->seek_time(static_cast<T>(t.t));
  }

  Frame frame() const override {
    const LogHeaderInfo& h = log_->header();
    const Particles<T>& p = replay_->particles();
    const T t = replay_->time();
    Frame f;
    f.time = double(t);
    f.lx = h.lx, f.ly = h.ly;
    f.periodic = h.boundary == BoundaryKind::Periodic;
    f.species_names = h.species_names;
    f.initial_mean_speed = mean_speed0_;
    for (std::size_t i = 0; i < p.size(); ++i) {
      double x = double(p.x_at(i, t)), y = double(p.y_at(i, t));
      double dx = x - x0_[i], dy = y - y0_[i];
      if (f.periodic) {
        x = wrap(x, f.lx), y = wrap(y, f.ly);
        dx -= f.lx * std::round(dx / f.lx), dy -= f.ly * std::round(dy / f.ly);
      }
      f.x.push_back(x);
      f.y.push_back(y);
      f.r.push_back(double(p.disk[i].r));
      f.speed.push_back(std::hypot(double(p.vx_at(i, t)), double(p.vy_at(i, t))));
      f.displacement.push_back(std::hypot(dx, dy));
      f.species.push_back(p.species[i]);
    }
    return f;
  }

  std::string time_text(long double t) const override { return tools::exact(static_cast<T>(t)); }

 private:
  static double wrap(double v, double l) {
    const double w = v - l * std::floor(v / l);
    return w >= l ? 0 : w;
  }

  std::shared_ptr<LogReader> log_;
  std::unique_ptr<Replay<T>> replay_;
  std::vector<double> x0_, y0_;
  double mean_speed0_ = 0;
};

}  // namespace

Result<std::unique_ptr<LogStates>> LogStates::open(const std::string& path) {
  auto log = ede::tools::open_log_warning("ede-render", path);
  if (!log) return log.error();
  std::shared_ptr<LogReader> reader = log.value();
  return with_scalar(reader->header().scalar, [&]<class T>() -> Result<std::unique_ptr<LogStates>> {
    auto replay = Replay<T>::create(reader);
    if (!replay) return replay.error();
    auto states = std::make_unique<TypedLogStates<T>>(reader, std::move(replay).value());
    if (Status s = states->load_initial(); !s) return s.error();
    return std::unique_ptr<LogStates>(std::move(states));
  });
}

}  // namespace ede::render
