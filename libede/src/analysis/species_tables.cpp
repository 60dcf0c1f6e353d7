// species_index and species_tables (ede/analysis.hpp): species by name, and per-species statistics over
// time from a log's snapshots.
//
// A species is chosen by its name as the scene gave it; the error lists the log's species, so a typo is
// fixed from the message alone. The tables are species_stats of one snapshot each, in time order.
// Rejected: pooling the times into one table here (GasAverages does that for callers who want it; a table
// per time shows the approach to equilibrium).
#include "ede/analysis.hpp"

namespace ede {

Result<std::int32_t> species_index(const LogInfo& info, const std::string& name) {
  if (name.empty()) return kAllSpecies;
  std::string known;
  for (std::size_t k = 0; k < info.species_names.size(); ++k) {
    if (info.species_names[k] == name) return std::int32_t(k);
    known += (k ? ", " : "") + info.species_names[k];
  }
  return Error{"the log has no species '" + name + "'; its species are: " + known};
}

Result<std::vector<SpeciesTable>> species_tables(const Log& log, const std::vector<double>& times,
                                                 std::int32_t species) {
  std::vector<SpeciesTable> out;
  Status s = for_each_snapshot(log, times, [&](const GasSnapshot& snap) {
    SpeciesTable table{snap.time, species_stats(snap)};
    if (species != kAllSpecies) {
      const bool known = species >= 0 && std::size_t(species) + 1 < table.rows.size();
      table.rows = known ? std::vector<SpeciesStats>{table.rows[std::size_t(species)]} : std::vector<SpeciesStats>{};
    }
    out.push_back(std::move(table));
  });
  if (!s) return s.error();
  return out;
}

}  // namespace ede
