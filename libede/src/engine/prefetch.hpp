// The disks of the next few events (the queue's next buckets), fetched into the cache in three stages while
// the events before them run, each stage using what the one before brought in:
//   1. their records and predictions;
//   2. one event later, their partners' records and the cell heads of the 3 x 3 cells around them;
//   3. one event after that, the first disk's record in each of those cells (the neighbour scan's loads; a
//      cell's second disk is one more link away and not fetched).
// Only the cache changes: the events are the same with or without (tests/engine/test_engine_run.cpp).
// Cells on a periodic grid's edge are not wrapped here: those neighbours are just not fetched. On from
// EngineOptions::prefetch_upcoming_from disks (measured there).
#pragma once

#include <cstdint>

#include "engine/engine_state.hpp"

namespace ede {

class UpcomingPrefetch {
 public:
  template <class S>
  void run(S& s) {
    for (std::uint32_t k = 0; k < heads_ready_.count; ++k)
      for_each_cell_row_around(s, heads_ready_.disk[k], [&](std::int32_t row) {
        for (std::int32_t c = row; c < row + 3; ++c)
          if (const std::int32_t h = s.grid.head(c); h >= 0) __builtin_prefetch(&s.p.disk[std::size_t(h)]);
      });
    heads_ready_.count = 0;
    for (std::uint32_t k = 0; k < records_ready_.count; ++k) {
      const std::int32_t d = records_ready_.disk[k];
      const auto& pr = s.pred[std::size_t(d)];
      const std::int32_t partner = pr.partner();  // -1 for none (a disk at rest predicts nothing)
      if (partner >= 0 && pr.coll_kind() == EventKind::Pair) __builtin_prefetch(&s.p.disk[std::size_t(partner)]);
      for_each_cell_row_around(s, d, [&](std::int32_t row) {
        __builtin_prefetch(s.grid.head_data() + row);
        __builtin_prefetch(s.grid.head_data() + row + 2);
      });
      heads_ready_.add(d);
    }
    records_ready_.count = 0;
    s.queue.visit_ahead(kPrefetchBuckets, [&](std::int32_t d) {
      __builtin_prefetch(&s.p.disk[std::size_t(d)]);
      __builtin_prefetch(&s.pred[std::size_t(d)]);
      records_ready_.add(d);
    });
  }

 private:
  // f(first cell) for the rows below, at and above disk d's cell that lie wholly inside the grid's array.
  template <class S, class F>
  static void for_each_cell_row_around(const S& s, std::int32_t d, F&& f) {
    const std::int32_t cell = s.p.disk[std::size_t(d)].cell, nx = s.grid.nx(), cells = nx * s.grid.ny();
    if (cell < 0) return;
    for (const std::int32_t row : {cell - nx - 1, cell - 1, cell + nx - 1})
      if (row >= 0 && row + 2 < cells) f(row);
  }

  // Three buckets (about three events) ahead: 2, 3, 5 and 8 measured alike at 10^6 disks.
  static constexpr std::uint32_t kPrefetchBuckets = 3;
  struct UpcomingDisks {  // the disks one prefetch stage has handled, for the next stage
    static constexpr std::uint32_t kMax = 16;
    std::int32_t disk[kMax] = {};
    std::uint32_t count = 0;
    void add(std::int32_t d) {
      if (count < kMax) disk[count++] = d;
    }
  };
  UpcomingDisks records_ready_, heads_ready_;
};

}  // namespace ede
