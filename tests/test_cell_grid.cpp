// The cell grid: membership bookkeeping and position -> cell mapping.
#include <catch2/catch.hpp>
#include <set>

#include "cell_grid.hpp"
#include "engine_core.hpp"

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
