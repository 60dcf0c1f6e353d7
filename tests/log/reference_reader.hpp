// A reference reader of the chunk columns and state of an ede log (format versions 1, 2 and 3), written from
// schema/FORMAT.md alone, as the test oracle for the fast reader (log/chunk_decode.cpp, replay/replay.cpp).
//
// Plain on purpose: no engine or library code for the columns, predictions or state updates (only the
// framing, LogReader::load_message, and Cap'n Proto to open a message); straightforward loops over every
// event from the first keyframe, no cursors, no checks beyond what a valid log needs. Where it and the fast
// reader disagree, one of them does not do what FORMAT.md says.
// Rejected: calling the library's predictors (then the oracle could not catch a predictor that drifted
// from the document, which is what an independent reader is for).
#pragma once

#include <capnp/serialize.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <vector>

#include "ede_log.capnp.h"
#include "log/log_messages.hpp"
#include "log/log_reader.hpp"

namespace ede::reference {

using U128 = unsigned __int128;
using I128 = __int128;

template <class T>
constexpr int kBits = sizeof(T) == 4 ? 32 : sizeof(T) == 8 ? 64 : 80;
template <class T>
constexpr std::size_t kWidth = std::size_t(kBits<T> / 8);

template <class T>
struct Record {
  T x{}, y{}, vx{}, vy{}, t{}, r{}, m{};
  std::uint32_t species = 0;
  T w{}, inertia{};  // rough logs (FORMAT.md, "Rotation")
};

template <class T>
T scalar_at(const unsigned char* p) {
  T v{};
  std::memcpy(&v, p, kWidth<T>);
  return v;
}

// n values of w bytes stored byte plane by byte plane: byte b of value k is at b n + k.
inline std::vector<unsigned char> unshuffle(const unsigned char* in, std::size_t size, std::size_t w) {
  const std::size_t n = size / w;
  std::vector<unsigned char> out(size);
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t b = 0; b < w; ++b) out[k * w + b] = in[b * n + k];
  return out;
}

template <class T>
std::vector<T> shuffled_scalars(const unsigned char* in, std::size_t size) {
  const std::vector<unsigned char> raw = unshuffle(in, size, kWidth<T>);
  std::vector<T> out;
  for (std::size_t k = 0; k < raw.size(); k += kWidth<T>) out.push_back(scalar_at<T>(raw.data() + k));
  return out;
}

template <class T>
U128 key_of(T v) {
  U128 bits = 0;
  std::memcpy(&bits, &v, kWidth<T>);
  const U128 sign = U128(1) << (kBits<T> - 1);
  const U128 mask = (sign << 1) - 1;
  bits &= mask;
  return (bits & sign) ? (~bits & mask) : (bits | sign);
}

template <class T>
T value_of_key(U128 key) {
  const U128 sign = U128(1) << (kBits<T> - 1);
  const U128 mask = (sign << 1) - 1;
  const U128 bits = (key & sign) ? (key & ~sign & mask) : (~key & mask);
  T v{};
  std::memcpy(&v, &bits, kWidth<T>);
  return v;
}

inline I128 unzig(U128 v) { return I128(v >> 1) ^ -I128(v & 1); }

struct Bytes {
  const unsigned char* p;
  const unsigned char* end;
  U128 varint() {
    U128 v = 0;
    for (int shift = 0; p < end; shift += 7) {
      const unsigned char b = *p++;
      v |= U128(b & 0x7F) << shift;
      if (!(b & 0x80)) break;
    }
    return v;
  }
  unsigned char byte() { return *p++; }
};

template <class T>
class Reader {
 public:
  explicit Reader(const LogReader& log) : log_(log) {
    const LogHeaderInfo& h = log.header();
    const std::vector<T> radius = shuffled_scalars<T>(h.radius.data(), h.radius.size());
    const std::vector<T> mass = shuffled_scalars<T>(h.mass.data(), h.mass.size());
    disk_.resize(h.disks);
    for (std::size_t i = 0; i < disk_.size(); ++i) disk_[i].r = radius[i], disk_[i].m = mass[i], disk_[i].species = h.species[i];
    lx_ = T(h.lx), ly_ = T(h.ly);
    periodic_ = h.boundary == BoundaryKind::Periodic;
    gx_ = T(h.gx), gy_ = T(h.gy);
    version_ = h.column_encoding;
    species_ = std::max<std::size_t>(1, h.species_names.size());
    for (std::size_t k = 0; k < h.pair_one_plus_xi.size(); k += kWidth<T>)
      one_plus_xi_.push_back(scalar_at<T>(h.pair_one_plus_xi.data() + k));
    for (std::size_t k = 0; k < h.wall_restitution.size(); k += kWidth<T>)
      xi_wall_.push_back(scalar_at<T>(h.wall_restitution.data() + k));
    // After the four walls, five values per wall segment: ax, ay, bx, by, xi (FORMAT.md, "Wall segments").
    for (std::size_t k = 4; k + 5 <= xi_wall_.size(); k += 5) {
      Seg g;
      g.ax = xi_wall_[k], g.ay = xi_wall_[k + 1], g.bx = xi_wall_[k + 2], g.by = xi_wall_[k + 3];
      const T dx = g.bx - g.ax, dy = g.by - g.ay;
      g.len = std::sqrt(dx * dx + dy * dy);
      g.ux = dx / g.len, g.uy = dy / g.len;
      g.nx = -g.uy, g.ny = g.ux;
      g.k = T(1) + xi_wall_[k + 4];
      seg_.push_back(g);
    }
    rough_ = !h.inertia.empty();
    if (rough_) {
      const std::vector<T> inertia = shuffled_scalars<T>(h.inertia.data(), h.inertia.size());
      for (std::size_t i = 0; i < disk_.size(); ++i) disk_[i].inertia = inertia[i];
      for (std::size_t k = 0; k < h.one_plus_beta.size(); k += kWidth<T>)
        one_plus_beta_.push_back(scalar_at<T>(h.one_plus_beta.data() + k));
    }
  }

  // Replays the whole log from its first keyframe; after each chunk, `check(events so far, records)`.
  void run(const std::function<void(std::uint64_t, const std::vector<Record<T>>&)>& check) {
    load_first_keyframe();
    std::uint64_t events = 0;
    for (const LogRecordRef& ref : log_.chunks()) {
      auto words = log_.load_message(ref.offset, ref.payload_size);
      capnp::FlatArrayMessageReader message(as_words(words.value()), reader_options(words.value()));
      const auto c = message.getRoot<logschema::Chunk>();
      decode_chunk(c, std::uint32_t(ref.count));
      events += ref.count;
      check(events, disk_);
    }
  }

 private:
  void load_first_keyframe() {
    const LogRecordRef& ref = log_.keyframes().front();
    auto words = log_.load_message(ref.offset, ref.payload_size);
    capnp::FlatArrayMessageReader message(as_words(words.value()), reader_options(words.value()));
    const auto k = message.getRoot<logschema::Keyframe>();
    const auto col = [](capnp::Data::Reader d) { return shuffled_scalars<T>(d.begin(), d.size()); };
    const std::vector<T> x = col(k.getX()), y = col(k.getY()), vx = col(k.getVx()), vy = col(k.getVy()), t = col(k.getT());
    for (std::size_t i = 0; i < disk_.size(); ++i)
      disk_[i].x = x[i], disk_[i].y = y[i], disk_[i].vx = vx[i], disk_[i].vy = vy[i], disk_[i].t = t[i];
    if (rough_) {
      const std::vector<T> w = col(k.getOmega());
      for (std::size_t i = 0; i < disk_.size(); ++i) disk_[i].w = w[i];
    }
  }

  // "Bring a disk to t", with gravity g along each axis (none: x + v (t - t_disk)).
  T pos(T x, T v, T g, T t0, T t) const {
    if (g == T(0)) return x + v * (t - t0);
    const T dt = t - t0;
    return x + v * dt + g * dt * dt / T(2);
  }
  T vel(T v, T g, T t0, T t) const { return g == T(0) ? v : v + g * (t - t0); }
  void bring(Record<T>& d, T t) const {
    const T x = pos(d.x, d.vx, gx_, d.t, t), y = pos(d.y, d.vy, gy_, d.t, t);
    d.vx = vel(d.vx, gx_, d.t, t), d.vy = vel(d.vy, gy_, d.t, t);
    d.x = x, d.y = y, d.t = t;
  }

  static T never() { return std::numeric_limits<T>::infinity(); }
  static T reach(T x, T v, T target) {
    if (v > 0) return target - x > 0 ? (target - x) / v : T(0);
    if (v < 0) return x - target > 0 ? (x - target) / -v : T(0);
    return never();
  }
  // time_to_reach_accelerated(s, u, a, 0) as FORMAT.md names it (core/geometry.hpp, written out).
  static T reach_accelerated(T s, T u, T a) {
    const T z = T(0);
    const T s_now = s + u * z + a * z * z / T(2), u_now = u + a * z;
    const bool leaving = s_now < T(0) && (u_now < T(0) || (u_now == T(0) && a < T(0)));
    if (a == T(0)) {
      if (!(u < T(0))) return never();
      const T t = s / -u;
      return t >= z ? t : (leaving ? z : never());
    }
    const T d = u * u - T(2) * a * s;
    if (d < T(0) || (d == T(0) && a > T(0))) return leaving ? z : never();
    const T root = std::sqrt(d);
    const T q = u < T(0) ? (-u + root) / T(2) : -(u + root) / T(2);
    const T r1 = q / (a / T(2));
    const T r2 = q != T(0) ? s / q : r1;
    const T outward = a < T(0) ? std::max(r1, r2) : std::min(r1, r2);
    if (outward >= z) return outward;
    return leaving ? z : never();
  }

  struct Seg {
    T ax, ay, bx, by, ux, uy, nx, ny, len, k;
  };
  T height(const Seg& g, T x, T y) const { return (x - g.ax) * g.nx + (y - g.ay) * g.ny; }
  T along(const Seg& g, T x, T y) const { return (x - g.ax) * g.ux + (y - g.ay) * g.uy; }
  T floor2() const {
    const T floor = T(8) * std::numeric_limits<T>::epsilon() * std::max(lx_, ly_);
    return floor * floor;
  }
  // The pair contact time's tau for relative position (dx, dy), relative velocity (dvx, dvy), distance s.
  T contact(T dx, T dy, T dvx, T dvy, T s) const {
    const T bb = dx * dvx + dy * dvy;
    if (!(bb < 0)) return never();
    const T aa = dvx * dvx + dvy * dvy;
    if (bb * bb <= floor2() * aa) return never();
    const T c = (dx * dx + dy * dy) - s * s;
    if (c <= 0) return T(0);
    const T d = bb * bb - aa * c;
    if (!(d > 0)) return never();
    return c / (-bb + std::sqrt(d));
  }
  T segment_time(const Record<T>& d, const Seg& g) const {
    const T h = height(g, d.x, d.y), vn = d.vx * g.nx + d.vy * g.ny;
    const T dist = h < 0 ? -h : h;
    const T approach = h < 0 ? vn : -vn;
    const T b = dist * -approach;
    T best = never();
    if (b < 0 && b * b > floor2() * (d.vx * d.vx + d.vy * d.vy)) {
      const T tau = dist > d.r ? (dist - d.r) / approach : T(0);
      const T u = along(g, d.x + d.vx * tau, d.y + d.vy * tau);
      if (u >= 0 && u <= g.len) best = tau;
    }
    best = std::min(best, contact(g.ax - d.x, g.ay - d.y, -d.vx, -d.vy, d.r));
    best = std::min(best, contact(g.bx - d.x, g.by - d.y, -d.vx, -d.vy, d.r));
    return best == never() ? never() : d.t + best;
  }

  T predict_time(int kind, std::int32_t i, std::int32_t j) const {
    if (kind == 7 || kind == 8) return never();  // a step, a redraw (version 3): no prediction
    if (kind == 9) kind = 3;                      // a shear crossing (version 3): the wrap's prediction
    if (kind == 6) return segment_time(disk_[std::size_t(i)], seg_[std::size_t(j)]);
    if (kind == 1) {
      const Record<T>& d = disk_[std::size_t(i)];
      if (gx_ == T(0) && gy_ == T(0)) {
        if (j == 1) return d.vx > 0 ? d.t + reach(d.x, d.vx, lx_ - d.r) : never();
        if (j == 0) return d.vx < 0 ? d.t + reach(d.x, d.vx, d.r) : never();
        if (j == 3) return d.vy > 0 ? d.t + reach(d.y, d.vy, ly_ - d.r) : never();
        return d.vy < 0 ? d.t + reach(d.y, d.vy, d.r) : never();
      }
      T tau = never();
      if (j == 0) tau = reach_accelerated(d.x - d.r, d.vx, gx_);
      if (j == 1) tau = reach_accelerated((lx_ - d.r) - d.x, -d.vx, -gx_);
      if (j == 2) tau = reach_accelerated(d.y - d.r, d.vy, gy_);
      if (j == 3) tau = reach_accelerated((ly_ - d.r) - d.y, -d.vy, -gy_);
      return tau == never() ? never() : d.t + tau;
    }
    if (kind == 3) {
      const Record<T>& d = disk_[std::size_t(i)];
      if (j == 0) return d.vx > 0 ? d.t + reach(d.x, d.vx, lx_) : never();
      if (j == 1) return d.vx < 0 ? d.t + reach(d.x, d.vx, T(0)) : never();
      if (j == 2) return d.vy > 0 ? d.t + reach(d.y, d.vy, ly_) : never();
      return d.vy < 0 ? d.t + reach(d.y, d.vy, T(0)) : never();
    }
    if (kind != 0) return never();
    const Record<T>* a = &disk_[std::size_t(i)];
    const Record<T>* b = &disk_[std::size_t(j)];
    if (b->t > a->t) std::swap(a, b);
    const T now = a->t;
    const T ax = pos(a->x, a->vx, gx_, a->t, now), ay = pos(a->y, a->vy, gy_, a->t, now);
    const T bx = pos(b->x, b->vx, gx_, b->t, now), by = pos(b->y, b->vy, gy_, b->t, now);
    T sx = 0, sy = 0;
    if (periodic_) {
      const T hx = lx_ / 2, hy = ly_ / 2;
      sx = (bx - ax) > hx ? -lx_ : (bx - ax) < -hx ? lx_ : T(0);
      sy = (by - ay) > hy ? -ly_ : (by - ay) < -hy ? ly_ : T(0);
    }
    const T dx = (bx + sx) - ax, dy = (by + sy) - ay;
    const T dvx = vel(b->vx, gx_, b->t, now) - vel(a->vx, gx_, a->t, now);
    const T dvy = vel(b->vy, gy_, b->t, now) - vel(a->vy, gy_, a->t, now);
    const T sigma = a->r + b->r;
    const T bb = dx * dvx + dy * dvy;
    if (!(bb < 0)) return never();
    const T aa = dvx * dvx + dvy * dvy;
    const T floor = T(8) * std::numeric_limits<T>::epsilon() * std::max(lx_, ly_);
    if (bb * bb <= floor * floor * aa) return never();
    const T c = (dx * dx + dy * dy) - sigma * sigma;
    if (c <= 0) return now;
    const T d = bb * bb - aa * c;
    if (!(d > 0)) return never();
    return now + c / (-bb + std::sqrt(d));
  }

  T read_residual(Bytes& col, T predicted) { return value_of_key<T>(key_of(predicted) + U128(unzig(col.varint()))); }

  void decode_chunk(logschema::Chunk::Reader c, std::uint32_t count) {
    Bytes times{c.getTimes().begin(), c.getTimes().end()}, kinds{c.getKinds().begin(), c.getKinds().end()};
    Bytes disks{c.getDisks().begin(), c.getDisks().end()}, partners{c.getPartners().begin(), c.getPartners().end()};
    Bytes residuals{c.getVelocityResiduals().begin(), c.getVelocityResiduals().end()};
    Bytes spins{c.getSpinResiduals().begin(), c.getSpinResiduals().end()};
    const std::vector<unsigned char> raw = unshuffle(c.getVelocitiesRaw().begin(), c.getVelocitiesRaw().size(), kWidth<T>);
    std::size_t raw_at = 0;
    U128 previous = 0;
    for (std::uint32_t e = 0; e < count; ++e) {
      T t{};
      if (version_ == 1) {
        previous += times.varint();
        t = value_of_key<T>(previous);
      }
      const unsigned char byte = kinds.byte();
      const int kind = version_ >= 2 ? (byte & ~16) : byte;
      const bool tc = version_ >= 2 && (byte & 16);
      std::int32_t i = -1, j = -1;
      if (kind == 0 || kind == 1 || kind == 3 || kind == 6 || kind == 7 || kind == 9) {
        i = std::int32_t(disks.varint());
        const U128 p = partners.varint();
        j = kind == 0 || kind == 7 ? std::int32_t(i + unzig(p)) : std::int32_t(p);
      } else if (kind == 8) {  // version 3, thermostat: a disk, no partner
        i = std::int32_t(disks.varint());
      }
      if (version_ >= 2) {
        const U128 code = times.varint();
        const U128 key = (code & 1) ? previous + (code >> 1) : key_of(predict_time(kind, i, j)) + U128(unzig(code >> 1));
        previous = key;
        t = value_of_key<T>(key);
      }
      if (kind == 0) {
        Record<T>& a = disk_[std::size_t(i)];
        Record<T>& b = disk_[std::size_t(j)];
        bring(a, t);
        bring(b, t);
        T v[4];
        if (version_ == 1) {
          v[0] = scalar_at<T>(raw.data() + raw_at), v[1] = scalar_at<T>(raw.data() + raw_at + kWidth<T>);
          raw_at += 2 * kWidth<T>;
          v[2] = read_residual(residuals, ((a.m * a.vx + b.m * b.vx) - a.m * v[0]) / b.m);
          v[3] = read_residual(residuals, ((a.m * a.vy + b.m * b.vy) - a.m * v[1]) / b.m);
        } else {
          T dx = b.x - a.x, dy = b.y - a.y;
          if (periodic_) {
            if (dx > lx_ / 2) dx = dx - lx_; else if (dx < -(lx_ / 2)) dx = dx + lx_;
            if (dy > ly_ / 2) dy = dy - ly_; else if (dy < -(ly_ / 2)) dy = dy + ly_;
          }
          const T k = tc ? T(2) : one_plus_xi_[a.species * species_ + b.species];
          const T dist = std::sqrt(dx * dx + dy * dy);
          const T nx = dx / dist, ny = dy / dist;
          const T vn = (b.vx - a.vx) * nx + (b.vy - a.vy) * ny;
          const T impulse = k * vn / (a.m + b.m);
          const T ki = impulse * b.m, kj = impulse * a.m;
          T p[4] = {a.vx + ki * nx, a.vy + ki * ny, b.vx - kj * nx, b.vy - kj * ny};
          T wa = a.w, wb = b.w;
          // Rough: the tangential impulse from the velocities and spins before, unless 1 + beta = 0.
          const T kb = tc || !rough_ ? T(0) : one_plus_beta_[a.species * species_ + b.species];
          if (kb != T(0)) {
            const T tx = -(dy / dist), ty = dx / dist;
            const T gt = ((b.vx - a.vx) * tx + (b.vy - a.vy) * ty) - (a.r * a.w + b.r * b.w);
            const T kk = ((T(1) / a.m + T(1) / b.m) + a.r * a.r / a.inertia) + b.r * b.r / b.inertia;
            const T pt = kb * gt / kk;
            p[0] = p[0] + (pt / a.m) * tx, p[1] = p[1] + (pt / a.m) * ty;
            p[2] = p[2] - (pt / b.m) * tx, p[3] = p[3] - (pt / b.m) * ty;
            wa = wa + a.r * pt / a.inertia, wb = wb + b.r * pt / b.inertia;
          }
          for (int q = 0; q < 4; ++q) v[q] = read_residual(residuals, p[q]);
          if (rough_) a.w = read_residual(spins, wa), b.w = read_residual(spins, wb);
        }
        a.vx = v[0], a.vy = v[1], b.vx = v[2], b.vy = v[3];
      } else if (kind == 7) {  // version 3, a step: both velocities against those before the event
        Record<T>& a = disk_[std::size_t(i)];
        Record<T>& b = disk_[std::size_t(j)];
        bring(a, t);
        bring(b, t);
        a.vx = read_residual(residuals, a.vx), a.vy = read_residual(residuals, a.vy);
        b.vx = read_residual(residuals, b.vx), b.vy = read_residual(residuals, b.vy);
      } else if (kind == 1) {
        Record<T>& a = disk_[std::size_t(i)];
        bring(a, t);
        const bool vertical = j == 0 || j == 1;
        T px, py;
        if (version_ == 1 || tc) {
          px = vertical ? -a.vx : a.vx, py = vertical ? a.vy : -a.vy;
        } else {
          const T xi = xi_wall_[std::size_t(j)];
          px = vertical ? -xi * a.vx : xi * a.vx, py = vertical ? xi * a.vy : -xi * a.vy;
        }
        if (rough_) {
          T wa = a.w;
          const T kb = tc ? T(0) : one_plus_beta_[species_ * species_ + std::size_t(j)];
          if (kb != T(0)) {
            const T nx = j == 0 ? T(-1) : j == 1 ? T(1) : T(0), ny = j == 2 ? T(-1) : j == 3 ? T(1) : T(0);
            const T tx = -ny, ty = nx;
            const T gt = (T(0) - (a.vx * tx + a.vy * ty)) - a.r * a.w;
            const T pt = kb * gt / (T(1) / a.m + a.r * a.r / a.inertia);
            px = px + (pt / a.m) * tx, py = py + (pt / a.m) * ty;
            wa = wa + a.r * pt / a.inertia;
          }
          a.w = read_residual(spins, wa);
        }
        const T vx = read_residual(residuals, px);
        a.vy = read_residual(residuals, py);
        a.vx = vx;
      } else if (kind == 6) {
        Record<T>& a = disk_[std::size_t(i)];
        bring(a, t);
        T px = a.vx, py = a.vy;
        if (version_ >= 2) {
          const Seg& g = seg_[std::size_t(j)];
          const T u = along(g, a.x, a.y);
          const bool below = height(g, a.x, a.y) < 0;
          const T bx = below ? g.nx : -g.nx, by = below ? g.ny : -g.ny;
          const bool body_in = a.vx * bx + a.vy * by > 0, on_body = u > 0 && u < g.len;
          T mx = 0, my = 0;
          bool hit = false;
          if (on_body && body_in) {
            mx = bx, my = by, hit = true;
          } else {
            const bool near_a = u < g.len / T(2);
            const T dx = (near_a ? g.ax : g.bx) - a.x, dy = (near_a ? g.ay : g.by) - a.y;
            const T dist = std::sqrt(dx * dx + dy * dy);
            const T ex = dx / dist, ey = dy / dist;
            if (a.vx * ex + a.vy * ey > 0) mx = ex, my = ey, hit = true;
            else if (!on_body && body_in) mx = bx, my = by, hit = true;
          }
          if (hit) {
            const T q = (tc ? T(2) : g.k) * ((T(0) - a.vx) * mx + (T(0) - a.vy) * my);
            px = a.vx + q * mx, py = a.vy + q * my;
          }
        }
        const T vx = read_residual(residuals, px);
        a.vy = read_residual(residuals, py);
        a.vx = vx;
      } else if (kind == 3) {
        Record<T>& a = disk_[std::size_t(i)];
        a.x = a.x + a.vx * (t - a.t);
        a.y = a.y + a.vy * (t - a.t);
        a.t = t;
        if (j == 0) a.x = a.x - lx_;
        if (j == 1) a.x = a.x + lx_;
        if (j == 2) a.y = a.y - ly_;
        if (j == 3) a.y = a.y + ly_;
      } else if (kind == 9) {  // version 3, a shear crossing: a wrap through the top or bottom, x and vx raw
        Record<T>& a = disk_[std::size_t(i)];
        a.x = a.x + a.vx * (t - a.t);
        a.y = a.y + a.vy * (t - a.t);
        a.t = t;
        a.y = j == 2 ? a.y - ly_ : a.y + ly_;
        a.x = scalar_at<T>(raw.data() + raw_at), a.vx = scalar_at<T>(raw.data() + raw_at + kWidth<T>);
        raw_at += 2 * kWidth<T>;
      } else if (kind == 8) {  // the redrawn velocity, raw
        Record<T>& a = disk_[std::size_t(i)];
        bring(a, t);
        a.vx = scalar_at<T>(raw.data() + raw_at), a.vy = scalar_at<T>(raw.data() + raw_at + kWidth<T>);
        raw_at += 2 * kWidth<T>;
      } else if (kind == 4) {
        for (Record<T>& d : disk_) {
          bring(d, t);
          d.vx = -d.vx, d.vy = -d.vy, d.w = -d.w;
        }
      }
    }
  }

  const LogReader& log_;
  std::vector<Record<T>> disk_;
  T lx_{}, ly_{}, gx_{}, gy_{};
  bool periodic_ = false;
  std::uint32_t version_ = 1;
  std::size_t species_ = 1;
  std::vector<T> one_plus_xi_, xi_wall_;
  bool rough_ = false;
  std::vector<T> one_plus_beta_;  // S x S pairs, then the 4 walls
  std::vector<Seg> seg_;
};

}  // namespace ede::reference
