// State: every disk at one time, as plain columns in the precision the run computed in.
//
// A State comes from a log (Log::state_at, exact: bit-identical to the engine's state at that time) or
// from a running Simulation (Simulation::state). Columns keep the run's own scalar type, so nothing is
// rounded on the way out; column[i] reads any of them as a double (exact for float and double runs),
// values<T>() gives the stored array for code that wants the run's own numbers (numpy does). Positions
// are those at `time`, computed with the engine's own drift function.
// Rejected: a State templated on the scalar type (every user would need four code paths) and a State in
// double only (long double runs would lose their extra digits).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <variant>
#include <vector>

#include "ede/error.hpp"
#include "ede/events.hpp"
#include "ede/scene.hpp"

namespace ede {

// A column of numbers in one scalar type: float, double or long double.
class Column {
 public:
  Column() = default;
  explicit Column(std::vector<float> v) : data_(std::move(v)) {}
  explicit Column(std::vector<double> v) : data_(std::move(v)) {}
  explicit Column(std::vector<long double> v) : data_(std::move(v)) {}

  ScalarKind scalar() const;
  std::size_t size() const;
  bool empty() const { return size() == 0; }
  // Element i as a double (exact for float and double columns, rounded for long double).
  double operator[](std::size_t i) const;
  // Element i exactly, widened to long double.
  long double exact(std::size_t i) const;
  // The whole column as doubles.
  std::vector<double> to_doubles() const;
  // The stored array; T must be the column's own type (else throws ede::Exception).
  template <class T>
  const std::vector<T>& values() const;
  // The raw storage, for bindings that hand the buffer on (numpy).
  const void* data() const;

 private:
  std::variant<std::vector<double>, std::vector<float>, std::vector<long double>> data_;
};

struct State {
  Time time = 0;                            // the time positions are given at
  std::uint64_t events = 0;                 // events of the log applied (from a log), or processed (a run)
  ScalarKind scalar = ScalarKind::Double;   // the run's scalar type (a float128 run's state is long double)
  double lx = 1, ly = 1;
  BoundaryKind boundary = BoundaryKind::Walls;
  // A Lees-Edwards (sheared) box: the x-shift of the periodic image above the box at `time` (the one below
  // is shifted by minus it), as the run had it; 0 in every other box. The nearest image of a disk across
  // the top or bottom edge is then shifted by it (docs/physics.md, "Lees-Edwards shear").
  double shear_offset = 0;
  Column x, y, vx, vy, radius, mass;        // one entry per disk, in id order
  std::vector<std::int32_t> species;        // index into species_names
  std::vector<std::string> species_names;
  // Rough or spinning disks only (else empty): angular velocity (counter-clockwise positive; constant
  // between collisions) and moment of inertia per disk.
  Column omega, inertia;

  std::size_t size() const { return species.size(); }
  bool rotates() const { return !omega.empty(); }
};

// The state as CSV: header id,species,x,y,vx,vy,radius,mass (then omega,inertia for rough or spinning
// disks), one row per disk in id order, every number
// with the digits that read back to the identical value of its type (float 9, double 17, long double 21),
// so a CSV is an exact snapshot (ede-replay --at and ede-sim --final-state write it).
void write_state_csv(std::FILE* out, const State& state);
Status write_state_csv(const std::string& path, const State& state);

// A number's text that reads back to the identical value of the scalar type (the digits above); the
// value is converted to that type first.
std::string exact_text(long double value, ScalarKind scalar);
// A number typed by a person, read exactly in the scalar type (strtof, strtod or strtold): "0.1" in a float
// log is the float nearest 0.1. Fails unless the whole text is one finite number.
Result<Time> parse_exact(const std::string& text, ScalarKind scalar);

}  // namespace ede
