// The sweep file (TOML, docs/sweeps.md) and the run list it expands to.
//
// A sweep is a base scene, parameters (lists, linear or log ranges, zipped lists of several keys), seeds
// per point and the quantities to collect. Every parameter value is a TOML value as typed and becomes a
// scene override (`key=value`, the same language as ede-sim --set), so a run's scene is exactly
// `ede-sim BASE --set ...` and the library checks it; nothing here knows scene keys. The runs are the
// Cartesian product of the parameters in file order (the first varies slowest), each point with every
// seed; a run's name (its files' stem) depends only on its point and seed. Rejected: a YAML or JSON sweep
// file (the scenes are TOML, and toml++ is already a dependency) and scene templates with placeholders
// (overrides are checked by the library like the file's own values; text substitution is not).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ede/error.hpp"

namespace ede::sweep {

struct Parameter {
  std::vector<std::string> keys;                 // one key, or several varied together (zipped)
  std::vector<std::vector<std::string>> values;  // values[k][i]: the k-th value of keys[i], as TOML text
};

struct SweepSpec {
  std::string path;                   // the sweep file
  std::string scene_path;             // the base scene (relative paths resolved against the sweep file)
  std::string results;                // the results folder (relative to the current directory)
  std::vector<std::string> base_overrides;  // `set = [...]` in the file, then --set
  std::vector<Parameter> parameters;
  std::vector<std::uint64_t> seeds;   // empty: every point runs once with the scene's own seed
  std::vector<std::string> collect;   // quantity names (quantities.hpp)
  double timeout = 0;                 // wall seconds per run, 0: none
  int retries = 2;                    // a run whose process died (killed) is run again this many times
};

struct PlannedRun {
  std::size_t index = 0;   // in sweep order
  std::size_t point = 0;   // which parameter point
  std::optional<std::uint64_t> seed;
  std::string name;        // p<point>-s<seed>: the stem of its files
  std::vector<std::string> columns;    // one per parameter key: the value as typed
  std::vector<std::string> overrides;  // the base overrides, then this point's, then seed=S
};

// Reads and checks the sweep file; errors name the file, the key and the fix.
Result<SweepSpec> load_sweep_file(const std::string& path);
// The parameter columns' names (every key of every parameter, in order).
std::vector<std::string> parameter_columns(const SweepSpec& spec);
// Every run, in sweep order.
std::vector<PlannedRun> expand_runs(const SweepSpec& spec);
std::size_t point_count(const SweepSpec& spec);

}  // namespace ede::sweep
