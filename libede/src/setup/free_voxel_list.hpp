// FreeVoxelList: the voxels of a BlockedVoxels map not yet marked, within a rectangle of voxel columns and
// rows, to draw random sequential addition's candidates from once most of the region is blocked
// (placement.sampling = "free-voxels"; the idea is Zhang and Torquato's, Phys. Rev. E 88, 053312 (2013)).
//
// Why the placed positions keep RSA's law: a candidate is a voxel uniform among those listed and a point
// uniform in it, so candidates are uniform over the listed voxels' union; the list holds every voxel of the
// rectangle that was unmarked when it was made, and marks only grow, so every point where a disk could still
// go is in that union; the usual overlap test then accepts exactly the free points, each with the same
// density. A voxel marked since the list was made holds no free point (blocked_voxels.hpp: a mark is never
// wrong), so drawing it is a rejection; when more than a quarter of the recent draws were such, the list is
// compacted. Voxels are equal in size, so no weighting is needed.
// Rejected: Zhang and Torquato's subdivision of partly free voxels (at an eighth of the exclusion radius about
// half of a listed voxel's candidates are accepted at phi = 0.5 already; finer levels cost memory and code).
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/rng.hpp"
#include "setup/blocked_voxels.hpp"

namespace ede::setup_detail {

class FreeVoxelList {
 public:
  // Lists the unmarked voxels with column in [ix0, ix1] and row in [iy0, iy1] (clamped to the map). Returns
  // false, listing nothing, if the map is disabled or has too many voxels for 32-bit indices.
  bool build(const BlockedVoxels& map, std::int64_t ix0, std::int64_t ix1, std::int64_t iy0, std::int64_t iy1) {
    map_ = &map;
    voxels_.clear();
    draws_ = stale_ = 0;
    const std::int64_t nx = map.voxels_x(), ny = map.voxels_y();
    if (!map.enabled() || std::int64_t(map.words()) * 64 > std::int64_t(std::numeric_limits<std::uint32_t>::max()))
      return false;
    ix0 = std::max<std::int64_t>(ix0, 0);
    iy0 = std::max<std::int64_t>(iy0, 0);
    ix1 = std::min<std::int64_t>(ix1, nx - 1);
    iy1 = std::min<std::int64_t>(iy1, ny - 1);
    if (ix0 > ix1 || iy0 > iy1) return true;
    // Word by word over the map's rows iy0..iy1: the unmarked bits are few once the list is worth making.
    const std::size_t first = std::size_t(map.code(0, iy0) >> 6), last = std::size_t(map.code(nx - 1, iy1) >> 6);
    for (std::size_t w = first; w <= last; ++w) {
      std::uint64_t free = ~map.word(w);
      while (free != 0) {
        const std::int64_t code = std::int64_t(w << 6) + __builtin_ctzll(free);
        free &= free - 1;
        std::int64_t ix, iy;
        map.voxel_of(code, ix, iy);
        if (ix >= ix0 && ix <= ix1 && iy >= iy0 && iy <= iy1) voxels_.push_back(std::uint32_t(code));
      }
    }
    return true;
  }

  std::size_t size() const { return voxels_.size(); }

  // One candidate (size() > 0): draws below(size()), then uniform01() for x and for y. Returns false if the
  // voxel drawn was marked since the list was made: no free point there, a rejected candidate.
  bool draw(Rng& rng, double& x, double& y) {
    const std::int64_t code = voxels_[std::size_t(rng.below(voxels_.size()))];
    const double u = rng.uniform01(), w = rng.uniform01();
    ++draws_;
    if (map_->marked(code)) {
      ++stale_;
      return false;
    }
    std::int64_t ix, iy;
    map_->voxel_of(code, ix, iy);
    x = map_->voxel_x(ix, u);
    y = map_->voxel_y(iy, w);
    return true;
  }

  // Drops the voxels marked since the list was made, once more than a quarter of at least 256 draws hit such.
  // Each compaction removes about a quarter of the list or more, so all of them together cost a few passes
  // over the first list.
  void compact_if_stale() {
    if (draws_ < 256 || 4 * stale_ <= draws_) return;
    std::size_t kept = 0;
    for (std::uint32_t v : voxels_)
      if (!map_->marked(v)) voxels_[kept++] = v;
    voxels_.resize(kept);
    draws_ = stale_ = 0;
  }

 private:
  const BlockedVoxels* map_ = nullptr;
  std::vector<std::uint32_t> voxels_;  // codes, ascending, so a compaction reads the map in order
  std::int64_t draws_ = 0, stale_ = 0;
};

}  // namespace ede::setup_detail
