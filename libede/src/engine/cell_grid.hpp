// The uniform cell grid for neighbour search: which disks can touch which.
//
// Cells are at least one largest diameter wide, so two disks can only touch if their cells are neighbours
// (3 x 3 block, wrapped in periodic boxes): a prediction looks at a bounded number of disks whatever N is.
// Membership is tracked, not recomputed from positions: a disk changes cell only at its crossing event,
// whose time comes from the same boundaries as here (boundary_x/_y), so round-off can leave a disk a hair
// outside its cell but never lets a pair be missed (cells are wider than a diameter by a relative margin
// far above round-off).
// Storage: intrusive singly linked lists. The link and the cell index live in the disk's own record
// (Disk::next_in_cell, Disk::cell), so walking a cell's list reads each neighbour's record once, the line
// the prediction needs anyway; the grid holds only the heads. A removal walks its cell's list to the disk
// (a cell holds ~1 disk on average, at most a handful, and those records are read by the crossing's scan
// anyway). Rejected: backward links (doubly linked lists, O(1) removal) cost 4 B/disk and gave the same
// lists in the same order (docs/performance.md, "Memory cuts").
// Rejected: fixed-capacity cell arrays (a polydisperse or clustered scene overflows them) and neighbour
// lists (Verlet lists need a skin and rebuilds, and their size grows with density).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/particles.hpp"
#include "core/scalar_math.hpp"

namespace ede {

template <class T>
class CellGrid {
 public:
  static constexpr std::int32_t kNone = -1;

  // nx * ny cells over [0, lx] x [0, ly], for the disks in `disks` (which must outlive the grid and not
  // be resized); every disk starts outside any cell.
  void reset(std::int32_t nx, std::int32_t ny, T lx, T ly, std::vector<Disk<T>>& disks) {
    nx_ = nx;
    ny_ = ny;
    lx_ = lx;
    ly_ = ly;
    wx_ = lx / T(nx);
    wy_ = ly / T(ny);
    disks_ = disks.data();
    head_.assign(std::size_t(nx) * std::size_t(ny), kNone);
    for (Disk<T>& d : disks) d.next_in_cell = d.cell = kNone;
  }

  std::int32_t nx() const { return nx_; }
  std::int32_t ny() const { return ny_; }
  std::int32_t cell_x(std::int32_t cell) const { return cell % nx_; }
  std::int32_t cell_y(std::int32_t cell) const { return cell / nx_; }
  std::int32_t cell_at(std::int32_t cx, std::int32_t cy) const { return cy * nx_ + cx; }
  std::int32_t cell_of(std::int32_t disk) const { return disks_[disk].cell; }
  std::int32_t head(std::int32_t cell) const { return head_[cell]; }
  const std::int32_t* head_data() const { return head_.data(); }
  std::int32_t next(std::int32_t disk) const { return disks_[disk].next_in_cell; }

  // The cell containing a position (clamped into the grid: round-off may put a disk a hair outside).
  std::int32_t cell_containing(T x, T y) const {
    return cell_at(index_of(x, wx_, nx_), index_of(y, wy_, ny_));
  }

  // Coordinate of the boundary between column c-1 and c (c in 0..nx): exact 0 and lx at the ends.
  T boundary_x(std::int32_t c) const { return c == nx_ ? lx_ : T(c) * wx_; }
  T boundary_y(std::int32_t c) const { return c == ny_ ? ly_ : T(c) * wy_; }

  void insert(std::int32_t disk, std::int32_t cell) {
    Disk<T>& d = disks_[disk];
    d.cell = cell;
    d.next_in_cell = head_[cell];
    head_[cell] = disk;
  }

  void remove(std::int32_t disk) {
    Disk<T>& d = disks_[disk];
    std::int32_t* link = &head_[d.cell];
    while (*link != disk) link = &disks_[*link].next_in_cell;
    *link = d.next_in_cell;
    d.cell = d.next_in_cell = kNone;
  }

  // Inlined into cross_cell on purpose: the library calls it from many engines per scalar type (thirteen
  // with the stepped and thermostat engines), and GCC then kept it out of line, 1 % more instructions for
  // the hard-disk gas (callgrind, ede-sim examples/gas.toml, 3*10^5 events).
  [[gnu::always_inline]] void move(std::int32_t disk, std::int32_t cell) {
    remove(disk);
    insert(disk, cell);
  }

  // A big disk (big_disks.hpp) has a cell, for its crossing events and its reach, but is in no list.
  void set_home(std::int32_t disk, std::int32_t cell) {
    disks_[disk].cell = cell;
    disks_[disk].next_in_cell = kNone;
  }

  std::size_t memory_bytes() const { return head_.capacity() * sizeof(std::int32_t); }

 private:
  static std::int32_t index_of(T x, T width, std::int32_t n) {
    const T f = ede::floor(x / width);
    if (!(f >= T(0))) return 0;  // also NaN
    if (f >= T(n - 1)) return n - 1;
    return static_cast<std::int32_t>(f);
  }

  std::int32_t nx_ = 1, ny_ = 1;
  T lx_ = 1, ly_ = 1, wx_ = 1, wy_ = 1;
  Disk<T>* disks_ = nullptr;
  std::vector<std::int32_t> head_;
};

}  // namespace ede
