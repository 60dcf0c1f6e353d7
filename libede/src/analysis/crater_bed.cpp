// select_bed: which disks of a log are the bed, by species.
//
// The default follows the scenes' convention (a species named "bed"), and otherwise takes every species of
// more than one disk, which leaves out one-disk species such as a projectile. Errors list the species the
// log has, with their sizes, so the fix is in the message.
// Rejected: guessing the bed from the state (the disks at rest at t = 0), which breaks for a bed that is
// stirred before the impact and cannot be stated in one line of a report.
#include <string>

#include "analysis/crater.hpp"
#include "replay/log_impl.hpp"

namespace ede {

namespace {

std::string disks_text(std::size_t n) { return std::to_string(n) + (n == 1 ? " disk" : " disks"); }

std::string species_list(const std::vector<std::string>& names, const std::vector<std::size_t>& counts) {
  std::string s;
  for (std::size_t k = 0; k < names.size(); ++k)
    s += (k ? ", '" : "'") + names[k] + "' (" + disks_text(counts[k]) + ")";
  return s.empty() ? "none" : s;
}

}  // namespace

Result<BedSelection> select_bed(const LogHeaderInfo& h, const std::string& name) {
  const std::vector<std::string>& names = h.species_names;
  std::vector<std::size_t> counts(names.size(), 0);
  for (const std::uint32_t s : h.species)
    if (s < counts.size()) ++counts[s];
  std::vector<bool> chosen(names.size(), false);
  BedSelection b;
  if (!name.empty()) {
    std::size_t k = 0;
    while (k < names.size() && names[k] != name) ++k;
    if (k == names.size())
      return Error{"there is no species '" + name + "' in the log; it has " + species_list(names, counts)};
    chosen[k] = true;
    b.reason = "species '" + name + "', as asked";
  } else {
    std::size_t k = 0;
    while (k < names.size() && names[k] != "bed") ++k;
    if (k < names.size()) {
      chosen[k] = true;
      b.reason = "the species named 'bed'";
    } else {
      for (std::size_t m = 0; m < names.size(); ++m) chosen[m] = counts[m] > 1;
      b.reason = "no species is named 'bed': every species of more than one disk";
    }
  }
  for (std::size_t k = 0; k < names.size(); ++k)
    if (chosen[k]) b.species.push_back(names[k]), b.disks += counts[k];
  if (b.disks == 0)
    return Error{"no bed: no species is named 'bed' and none has more than one disk (the log has " +
                 species_list(names, counts) + "); name one with --species"};
  b.is_bed.resize(h.species.size());
  for (std::size_t i = 0; i < h.species.size(); ++i) b.is_bed[i] = h.species[i] < chosen.size() && chosen[h.species[i]];
  return b;
}

Result<BedSelection> select_bed(const Log& log, const std::string& name) {
  return select_bed(reader_of(log)->header(), name);
}

}  // namespace ede
