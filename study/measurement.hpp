// What the studies and benchmarks share: running a measurement in a child and reading the key=value text
// it sends back, medians, scene overrides, and formatting.
#pragma once

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "ede/scene.hpp"
#include "process.hpp"  // tools/common: run_in_child

namespace ede::study {

using KeyValues = std::map<std::string, double>;

// "events=123 wall=0.5 ..." -> {events: 123, wall: 0.5}; unknown text is skipped.
inline KeyValues parse_key_values(const std::string& text) {
  KeyValues kv;
  std::istringstream in(text);
  for (std::string item; in >> item;) {
    const auto eq = item.find('=');
    if (eq != std::string::npos) kv[item.substr(0, eq)] = std::strtod(item.c_str() + eq + 1, nullptr);
  }
  return kv;
}

inline double get(const KeyValues& kv, const std::string& key) { return kv.count(key) ? kv.at(key) : 0.0; }

// A measurement run in a child process (run_in_child): the key=value pairs it sent back, or why it failed.
struct ChildMeasurement {
  bool ok = false;
  std::string failure;  // why not ok, then what the child said
  KeyValues values;
  double peak_rss = 0;  // bytes
};

inline ChildMeasurement run_child_measurement(const std::function<int(std::string& output)>& body) {
  const tools::ChildResult r = tools::run_in_child(body);
  ChildMeasurement m;
  m.ok = r.ok;
  m.peak_rss = double(r.peak_rss_bytes);
  if (r.ok)
    m.values = parse_key_values(r.output);
  else
    m.failure = r.failure + (r.output.empty() ? "" : ": " + r.output);
  return m;
}

// --set texts as the scene loader's overrides.
inline std::vector<Override> as_overrides(const std::vector<std::string>& texts) {
  std::vector<Override> all;
  for (const std::string& t : texts) all.push_back({t});
  return all;
}

// The machines are noisy: benchmarks report medians of repeats.
inline double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

inline std::string fmt(double v, int digits = 3) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

// "examples/bench/gas-N1000-phi0.5-walls.toml" -> "gas-N1000-phi0.5-walls"
inline std::string scene_label(const std::string& path) {
  const auto slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  if (name.size() > 5 && name.substr(name.size() - 5) == ".toml") name.resize(name.size() - 5);
  return name;
}

}  // namespace ede::study
