// The state of a Stepped engine (effects.hpp): the stepped potential of every pair of species (square wells
// and shoulders outside the hard core, from [[physics.steps]]), and for every pair of disks inside at least
// one step how many steps deep it is (its "depth"), with the potential energy that follows. A HardCore
// engine holds NoSteps: nothing.
//
// The depth is kept, not derived from positions at each prediction: right after a pair crosses a step its
// distance equals the step's radius up to round-off, and a position test there could count the crossing
// twice (the energy changed twice) or not at all. The depth is derived from positions only where no event
// has just happened: at the start of a run and at a resumed run's rebuild point (init_depths). A rebuild
// point follows an event, which may have been a step's: that pair sits on the step's radius up to
// round-off, so a pair within 64 epsilon of a radius counts as inside when approaching (b < 0), which is
// exactly what each of a crossing and a bounce, inwards or outwards, leaves; any other pair is that close
// with a probability of ~1e-14 per rebuild. Storage: per disk a short list of (partner, depth), a few entries in a liquid; rejected: a hash
// map of pairs (a hash and a probe per neighbour per prediction, and an iteration order to pin down).
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "core/particles.hpp"
#include "core/scalar_math.hpp"
#include "ede/scene.hpp"

namespace ede {

struct NoSteps {};

template <class T>
struct StepTable {
  struct Bond {
    std::int32_t partner;
    std::int32_t depth;  // steps the pair is inside: 1 = inside the outermost only
  };
  // The steps of one species pair, outermost first: radius[first + k], k < count.
  struct Range {
    std::uint32_t first = 0, count = 0;
  };

  std::size_t species = 1;
  std::vector<Range> ranges;            // species pair (a, b) at a * species + b
  std::vector<T> radius;                // each pair's steps, outermost first
  std::vector<T> energy;                // the potential energy change on entering each of them
  std::vector<std::vector<Bond>> bonds;  // per disk: its partners with depth > 0, in no particular order
  double potential = 0;                 // the sum over bonded pairs of the energies of the steps they are inside
  double outermost = 0;                 // the largest step radius of any pair (the cells must cover it)
  bool depths_known = false;            // init_depths has run

  void setup(const std::vector<std::string>& names, const PhysicsSpec& ph, std::size_t disks) {
    species = std::max<std::size_t>(names.size(), 1);
    ranges.assign(species * species, Range{});
    const auto index_of = [&](const std::string& name) {
      return std::size_t(std::find(names.begin(), names.end(), name) - names.begin());
    };
    const auto add = [&](std::size_t a, std::size_t b, const PairSteps& st) {
      const Range r{std::uint32_t(radius.size()), std::uint32_t(st.radius.size())};
      for (std::size_t k = st.radius.size(); k-- > 0;) {
        radius.push_back(T(st.radius[k]));
        energy.push_back(T(st.energy[k]));
        outermost = std::max(outermost, st.radius[k]);
      }
      ranges[a * species + b] = ranges[b * species + a] = r;
    };
    for (const PairSteps& st : ph.steps)  // the default first, so that named pairs override it
      if (st.a.empty())
        for (std::size_t a = 0; a < species; ++a)
          for (std::size_t b = a; b < species; ++b) add(a, b, st);
    for (const PairSteps& st : ph.steps)
      if (!st.a.empty()) add(index_of(st.a), index_of(st.b), st);  // names checked by check_engine_input
    bonds.assign(disks, {});
  }

  Range steps_of(const Particles<T>& p, std::int32_t i, std::int32_t k) const {
    return ranges[std::size_t(p.species_of(std::size_t(i))) * species + std::size_t(p.species_of(std::size_t(k)))];
  }

  std::int32_t depth(std::int32_t i, std::int32_t k) const {
    for (const Bond& b : bonds[std::size_t(i)])
      if (b.partner == k) return b.depth;
    return 0;
  }

  // The pair's depth becomes `depth` (0: removed from both lists).
  void set_depth(std::int32_t i, std::int32_t k, std::int32_t depth) {
    set_one(bonds[std::size_t(i)], k, depth);
    set_one(bonds[std::size_t(k)], i, depth);
  }

  // The potential energy of a pair `depth` steps deep.
  double energy_at_depth(Range r, std::int32_t depth) const {
    double u = 0;
    for (std::int32_t m = 0; m < depth; ++m) u += double(energy[r.first + std::uint32_t(m)]);
    return u;
  }

  // How many of the pair's steps a distance squared d2 lies inside (on a radius, to round-off: inside when
  // approaching, b < 0, which is where a crossing or a bounce leaves a pair).
  std::int32_t depth_at(Range r, T d2, T b) const {
    std::int32_t q = 0;
    for (std::uint32_t m = 0; m < r.count; ++m) {
      const T rr = radius[r.first + m] * radius[r.first + m];
      const T gap = d2 - rr, tolerance = T(64) * scalar_limits<T>::epsilon() * rr;
      if (gap < -tolerance || (ede::abs(gap) <= tolerance && b < T(0))) q = std::int32_t(m) + 1;
    }
    return q;
  }

  std::size_t memory_bytes() const {
    std::size_t bytes = ranges.capacity() * sizeof(Range) + (radius.capacity() + energy.capacity()) * sizeof(T) +
                        bonds.capacity() * sizeof(std::vector<Bond>);
    for (const auto& b : bonds) bytes += b.capacity() * sizeof(Bond);
    return bytes;
  }

 private:
  static void set_one(std::vector<Bond>& list, std::int32_t partner, std::int32_t depth) {
    for (std::size_t n = 0; n < list.size(); ++n)
      if (list[n].partner == partner) {
        if (depth > 0) {
          list[n].depth = depth;
        } else {
          list[n] = list.back();
          list.pop_back();
        }
        return;
      }
    if (depth > 0) list.push_back({partner, depth});
  }
};

}  // namespace ede
