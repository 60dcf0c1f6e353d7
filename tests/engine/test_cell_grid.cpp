// The cell grid: membership bookkeeping and position -> cell mapping.
#include <catch2/catch.hpp>
#include <set>

#include "engine/cell_grid.hpp"
#include "engine/engine_core.hpp"

using namespace ede;

namespace {
std::set<int> members(const CellGrid<double>& g, int cell) {
  std::set<int> out;
  for (int k = g.head(cell); k != CellGrid<double>::kNone; k = g.next(k)) out.insert(k);
  return out;
}
}  // namespace

TEST_CASE("CellGrid: insert, move and remove keep every list consistent", "[cells]") {
  std::vector<Disk<double>> disks(6);
  CellGrid<double> g;
  g.reset(4, 3, 1.0, 0.75, disks);
  for (int i = 0; i < 6; ++i) g.insert(i, i % 2);
  CHECK(members(g, 0) == std::set<int>{0, 2, 4});
  CHECK(members(g, 1) == std::set<int>{1, 3, 5});
  g.move(2, 7);
  g.move(5, 7);
  g.move(4, 1);
  CHECK(members(g, 0) == std::set<int>{0});
  CHECK(members(g, 1) == std::set<int>{1, 3, 4});
  CHECK(members(g, 7) == std::set<int>{2, 5});
  CHECK(g.cell_of(5) == 7);
  g.remove(1);
  CHECK(members(g, 1) == std::set<int>{3, 4});
}

TEST_CASE("CellGrid: positions map to cells, clamped at the edges", "[cells]") {
  std::vector<Disk<double>> disks(1);
  CellGrid<double> g;
  g.reset(4, 2, 1.0, 1.0, disks);
  CHECK(g.cell_containing(0.1, 0.1) == 0);
  CHECK(g.cell_containing(0.3, 0.1) == 1);
  CHECK(g.cell_containing(0.99, 0.99) == g.cell_at(3, 1));
  CHECK(g.cell_containing(1.0 + 1e-17, 0.5) == g.cell_at(3, 1));  // a hair outside: last cell
  CHECK(g.cell_containing(-1e-17, 0.2) == 0);
  CHECK(g.boundary_x(4) == 1.0);
  CHECK(g.boundary_x(1) == 0.25);
}

TEST_CASE("grid shapes stay bounded for very elongated boxes", "[cells]") {
  // Found by fuzzing: a 1 x 1.7e16 box with 20 disks clamped nx at 1 and let ny grow to 5.8e8 cells.
  for (const bool periodic : {false, true}) {
    const GridShape g = grid_shape_for(1.0, 1.7e16, 0.03, 20, periodic, Algorithm::Cells);
    CHECK(double(g.nx) * double(g.ny) <= 4 * 20 + 16);
    CHECK(g.nx >= (periodic ? 3 : 1));
    const GridShape h = grid_shape_for(1.7e16, 1.0, 0.03, 20, periodic, Algorithm::Cells);
    CHECK(double(h.nx) * double(h.ny) <= 4 * 20 + 16);
  }
  // An ordinary box keeps cells one diameter wide.
  const GridShape u = grid_shape_for(1.0, 1.0, 0.005, 10000, true, Algorithm::Cells);
  CHECK(u.nx == 99);
}

TEST_CASE("big disks: only the few that stand out are kept out of the cell lists", "[cells][big]") {
  // A crater: 5000 bed disks of radius r and a projectile of 5 r.
  std::vector<double> crater(5000, 0.004);
  crater.push_back(0.02);
  const DiskSizeSplit c = split_disk_sizes(crater);
  CHECK(c.small_max_radius == 0.004);
  CHECK(c.big_radius > 0.004 * 1.9);
  CHECK(c.big_radius < 0.02 / 1.9);  // far from both radii: no scalar type's rounding moves a disk across
  // Polydisperse radii within a factor 2: nobody stands out.
  std::vector<double> poly;
  for (int i = 0; i < 1000; ++i) poly.push_back(0.01 * (1 + i / 1000.0));
  CHECK(split_disk_sizes(poly).big_radius == std::numeric_limits<double>::infinity());
  CHECK(split_disk_sizes(poly).small_max_radius == poly.back());
  // Fewer than 64 disks: no split (one grid is as good); more big disks than K = N / 64: no split either.
  std::vector<double> few(40, 0.001);
  few.push_back(0.1);
  CHECK(split_disk_sizes(few).big_radius == std::numeric_limits<double>::infinity());
  std::vector<double> many(640, 0.001);
  for (int i = 0; i < 11; ++i) many.push_back(0.1);  // K = 10
  CHECK(split_disk_sizes(many).big_radius == std::numeric_limits<double>::infinity());
  many.pop_back();  // now exactly K = 10 big ones
  CHECK(split_disk_sizes(many).big_radius < 0.1);
}

TEST_CASE("big disks: the grid is sized by the small ones, unless a periodic box is too small", "[cells][big]") {
  InitialState s;
  for (int i = 0; i < 100; ++i) s.add(0.05 + 0.1 * (i % 10), 0.05 + 0.1 * (i / 10), 0, 0, 0.004, 1, 0);
  s.radius[55] = 0.04;  // one big disk
  const GridShape walls = engine_grid_for(s, false, Algorithm::Cells);
  CHECK(walls.split.big_radius < 0.04);
  CHECK(walls.nx == 20);  // ~4 cells per disk bound the grid, not the big disk (it alone would allow 12)
  const GridShape periodic = engine_grid_for(s, true, Algorithm::Cells);
  CHECK(periodic.split.big_radius < 0.04);  // reach 3 cells of 0.05: 2 * 3 + 3 <= 20
  s.radius[55] = 0.3;                        // reach 7 cells: 2 * 7 + 3 = 17 <= 20 still fits
  CHECK(engine_grid_for(s, true, Algorithm::Cells).split.big_radius < 0.3);
  s.radius[55] = 0.45;  // reach 10 cells: too wide for a 20-cell periodic box: one grid for all
  CHECK(engine_grid_for(s, true, Algorithm::Cells).split.big_radius == std::numeric_limits<double>::infinity());
  CHECK(engine_grid_for(s, false, Algorithm::Cells).split.big_radius < 0.45);  // walls: any reach
}
