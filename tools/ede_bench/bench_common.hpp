// What the benchmarks share: the key=value lines a measuring child sends back, medians, and formatting.
#pragma once

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace ede::bench {

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

}  // namespace ede::bench
