// Comparing replayed events bit for bit, and describing them in words, for verify and diff.
//
// Two runs agree only if every bit agrees: scalars are compared by their bytes (long double: its 10
// significant bytes, not the padding), never with a tolerance.
#pragma once

#include <cstring>
#include <string>
#include <type_traits>

#include "core/state_of.hpp"
#include "ede/state.hpp"
#include "replay/replay.hpp"

namespace ede {

template <class T>
bool same_bits(T a, T b) {
  constexpr std::size_t width = std::is_same_v<T, long double> ? 10 : sizeof(T);
  return std::memcmp(&a, &b, width) == 0;
}

// The digits that read back to the same value of T.
template <class T>
std::string exact(T v) {
  return exact_text(static_cast<long double>(v), scalar_kind_of<T>());
}

inline bool has_disk(EventKind k) {
  return k == EventKind::Pair || k == EventKind::Wall || k == EventKind::Wrap || k == EventKind::Segment ||
         k == EventKind::Shear;
}
inline bool has_vi(EventKind k) {
  return k == EventKind::Pair || k == EventKind::Wall || k == EventKind::Segment || k == EventKind::Shear;
}

// An event in words, for reports: "t = 0.25, pair of disks 3 and 17, v_i = (1, 2), v_j = (3, 4)".
template <class T>
std::string describe(const ReplayedEvent<T>& e) {
  static const char* const walls[] = {"left", "right", "bottom", "top"};
  static const char* const wraps[] = {"right", "left", "top", "bottom"};
  std::string s = "t = " + exact(e.time) + ", " + to_string(e.kind);
  const bool known_j = e.j >= 0 && e.j < 4;
  switch (e.kind) {
    case EventKind::Pair: s += " of disks " + std::to_string(e.i) + " and " + std::to_string(e.j); break;
    case EventKind::Wall:
      s += " of disk " + std::to_string(e.i) + " on the " + (known_j ? walls[e.j] : std::to_string(e.j)) + " wall";
      break;
    case EventKind::Wrap:
    case EventKind::Shear:
      s += " of disk " + std::to_string(e.i) + " across the " + (known_j ? wraps[e.j] : std::to_string(e.j)) + " edge";
      break;
    case EventKind::Segment: s += " of disk " + std::to_string(e.i) + " on wall segment " + std::to_string(e.j); break;
    default: break;
  }
  if (has_vi(e.kind)) s += ", v_i = (" + exact(e.vix) + ", " + exact(e.viy) + ")";
  if (e.kind == EventKind::Pair) s += ", v_j = (" + exact(e.vjx) + ", " + exact(e.vjy) + ")";
  return s;
}

// The first field in which two events differ ("" if they are identical): time, kind and disks, then
// the post-event velocities the kind has, bitwise.
template <class T>
std::string first_difference(const ReplayedEvent<T>& a, const ReplayedEvent<T>& b) {
  if (!same_bits(a.time, b.time)) return "time";
  if (a.kind != b.kind) return "kind";
  if (a.i != b.i) return "disk i";
  if (a.j != b.j)
    return a.kind == EventKind::Pair      ? "disk j"
           : a.kind == EventKind::Wall    ? "wall"
           : a.kind == EventKind::Segment ? "segment"
                                          : "direction";
  if (has_vi(a.kind) && !same_bits(a.vix, b.vix)) return "vix";
  if (has_vi(a.kind) && !same_bits(a.viy, b.viy)) return "viy";
  if (a.kind == EventKind::Pair && !same_bits(a.vjx, b.vjx)) return "vjx";
  if (a.kind == EventKind::Pair && !same_bits(a.vjy, b.vjy)) return "vjy";
  // Rough logs: the spins after pair and wall events (0 on both sides for smooth disks).
  if ((a.kind == EventKind::Pair || a.kind == EventKind::Wall) && !same_bits(a.wi, b.wi)) return "omega_i";
  if (a.kind == EventKind::Pair && !same_bits(a.wj, b.wj)) return "omega_j";
  return "";
}

}  // namespace ede
