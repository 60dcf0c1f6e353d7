// Reading a sweep file with toml++ and expanding it to runs (see sweep_file.hpp).
//
// Values are kept as TOML text: numbers print in their shortest round-trip form (std::to_chars), so a
// range's 0.1 is "0.1", not 17 digits, and reads back to the same double in the override. Rejected:
// toml++'s own printer for values (its float format is not the shortest round trip on every version).
#include "sweep_file.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <toml++/toml.h>

namespace ede::sweep {

namespace {

std::string shortest(double v) {
  char b[64];
  const auto r = std::to_chars(b, b + sizeof b, v);
  std::string s(b, r.ptr);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // stays a TOML float
  return s;
}

Result<std::string> value_text(const toml::node& n, const std::string& where) {
  if (auto v = n.as_integer()) return std::to_string(v->get());
  if (auto v = n.as_floating_point()) return shortest(v->get());
  if (auto v = n.as_boolean()) return std::string(v->get() ? "true" : "false");
  if (auto v = n.as_string()) {
    std::string out = "\"";
    for (char c : v->get()) {
      if (c == '"' || c == '\\') out += '\\';
      out += c;
    }
    return out + "\"";
  }
  if (auto a = n.as_array()) {
    std::string out = "[";
    for (std::size_t i = 0; i < a->size(); ++i) {
      auto t = value_text(*a->get(i), where);
      if (!t) return t;
      out += (i ? "," : "") + t.value();
    }
    return out + "]";
  }
  return Error{where + ": a parameter value must be a number, a string, a boolean or an array. Fix: write it "
                       "as it would appear in the scene file"};
}

std::string at(const toml::node& n) {
  const auto& s = n.source();
  return s.begin ? ":" + std::to_string(s.begin.line) : "";
}

Result<std::vector<std::string>> range_values(const toml::table& r, const std::string& where) {
  const auto from = r["from"].value<double>(), to = r["to"].value<double>();
  const auto count = r["count"].value<std::int64_t>();
  const std::string scale = r["scale"].value_or(std::string("linear"));
  if (!from || !to || !count || *count < 1)
    return Error{where + ": a range needs from, to (numbers) and count (>= 1). Fix: range = { from = 1.0, to = 2.0, "
                         "count = 5 } (scale = \"log\" for a geometric range)"};
  if (scale != "linear" && scale != "log")
    return Error{where + ": scale = \"" + scale + "\" is not known. Fix: \"linear\" or \"log\""};
  if (scale == "log" && (*from <= 0 || *to <= 0))
    return Error{where + ": a log range needs from > 0 and to > 0. Fix: positive ends, or scale = \"linear\""};
  std::vector<std::string> out;
  for (std::int64_t k = 0; k < *count; ++k) {
    const double f = *count == 1 ? 0.0 : double(k) / double(*count - 1);
    const double v = k == *count - 1 ? *to
                     : scale == "log" ? *from * std::pow(*to / *from, f)
                                      : (double(*count - 1 - k) * *from + double(k) * *to) / double(*count - 1);
    out.push_back(shortest(v));
  }
  return out;
}

Result<Parameter> read_parameter(const toml::table& t, const std::string& where) {
  for (auto&& [k, v] : t)
    if (k != "key" && k != "keys" && k != "values" && k != "range")
      return Error{where + ": unknown key '" + std::string(k.str()) + "'. Fix: key (or keys), values or range"};
  Parameter p;
  if (auto key = t["key"].value<std::string>()) p.keys.push_back(*key);
  if (auto keys = t["keys"].as_array())
    for (auto&& k : *keys)
      if (auto s = k.value<std::string>()) p.keys.push_back(*s);
  if (p.keys.empty() || (t.contains("key") && t.contains("keys")))
    return Error{where + ": name the scene key: key = \"physics.restitution\", or keys = [\"a\", \"b\"] for values "
                         "varied together"};
  const bool zipped = t.contains("keys");
  if (t.contains("range") == t.contains("values"))
    return Error{where + ": give either values = [...] or range = { from, to, count }"};
  if (auto r = t["range"].as_table()) {
    if (zipped) return Error{where + ": a range varies one key. Fix: key = \"...\" with the range"};
    auto vals = range_values(*r, where + ".range");
    if (!vals) return vals.error();
    for (std::string& v : vals.value()) p.values.push_back({v});
    return p;
  }
  const toml::array* values = t["values"].as_array();
  if (!values || values->empty()) return Error{where + ": values must be a non-empty array"};
  for (std::size_t i = 0; i < values->size(); ++i) {
    const toml::node& v = *values->get(i);
    const std::string vw = where + ".values[" + std::to_string(i) + "]" + at(v);
    std::vector<std::string> row;
    if (zipped) {
      const toml::array* a = v.as_array();
      if (!a || a->size() != p.keys.size())
        return Error{vw + ": with keys = [...] each value is an array of " + std::to_string(p.keys.size()) +
                     " values, one per key"};
      for (auto&& e : *a) {
        auto text = value_text(e, vw);
        if (!text) return text.error();
        row.push_back(text.value());
      }
    } else {
      auto text = value_text(v, vw);
      if (!text) return text.error();
      row.push_back(text.value());
    }
    p.values.push_back(row);
  }
  return p;
}

Result<std::vector<std::string>> string_list(const toml::table& t, const char* key, const std::string& file) {
  std::vector<std::string> out;
  if (!t.contains(key)) return out;
  const toml::array* a = t[key].as_array();
  if (!a) return Error{file + ": " + key + " must be an array of strings"};
  for (auto&& e : *a) {
    auto s = e.value<std::string>();
    if (!s) return Error{file + at(e) + ": " + key + " must be an array of strings"};
    out.push_back(*s);
  }
  return out;
}

Result<std::vector<std::uint64_t>> read_seeds(const toml::table& t, const std::string& file) {
  std::vector<std::uint64_t> seeds;
  if (!t.contains("seeds")) return seeds;
  if (auto n = t["seeds"].value<std::int64_t>(); n && t["seeds"].is_integer()) {
    if (*n < 1) return Error{file + ": seeds = " + std::to_string(*n) + ": give a count >= 1 or a list of seeds"};
    for (std::int64_t s = 1; s <= *n; ++s) seeds.push_back(std::uint64_t(s));
    return seeds;
  }
  const toml::array* a = t["seeds"].as_array();
  if (!a || a->empty()) return Error{file + ": seeds must be a count (seeds = 5: seeds 1..5) or a list of integers"};
  for (auto&& e : *a) {
    auto s = e.value<std::int64_t>();
    if (!s || *s < 0) return Error{file + at(e) + ": every seed must be an integer >= 0"};
    seeds.push_back(std::uint64_t(*s));
  }
  return seeds;
}

}  // namespace

Result<SweepSpec> load_sweep_file(const std::string& path) {
  toml::table t;
  try {
    t = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    return Error{path + ":" + std::to_string(e.source().begin.line) + ":" + std::to_string(e.source().begin.column) +
                 ": " + std::string(e.description())};
  }
  for (auto&& [k, v] : t)
    if (k != "scene" && k != "results" && k != "set" && k != "seeds" && k != "collect" && k != "timeout" &&
        k != "retries" && k != "parameter")
      return Error{path + at(v) + ": unknown key '" + std::string(k.str()) +
                   "'. Fix: scene, results, set, seeds, collect, timeout, retries or [[parameter]] (docs/sweeps.md)"};
  SweepSpec spec;
  spec.path = path;
  auto scene = t["scene"].value<std::string>();
  if (!scene) return Error{path + ": no scene. Fix: scene = \"base.toml\" (relative to the sweep file)"};
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  spec.scene_path = std::filesystem::path(*scene).is_absolute() ? *scene : (dir / *scene).string();
  spec.results = t["results"].value_or(std::string("sweep-results"));
  auto set = string_list(t, "set", path);
  if (!set) return set.error();
  spec.base_overrides = set.value();
  auto collect = string_list(t, "collect", path);
  if (!collect) return collect.error();
  spec.collect = collect.value();
  auto seeds = read_seeds(t, path);
  if (!seeds) return seeds.error();
  spec.seeds = seeds.value();
  spec.timeout = t["timeout"].value_or(0.0);
  spec.retries = int(t["retries"].value_or(std::int64_t(2)));
  if (spec.timeout < 0 || spec.retries < 0) return Error{path + ": timeout and retries must be >= 0"};
  if (t.contains("parameter")) {
    const toml::array* ps = t["parameter"].as_array();
    if (!ps) return Error{path + ": parameters are [[parameter]] tables"};
    for (std::size_t i = 0; i < ps->size(); ++i) {
      const toml::table* pt = ps->get(i)->as_table();
      const std::string where = path + at(*ps->get(i)) + ": parameter[" + std::to_string(i) + "]";
      if (!pt) return Error{where + " must be a table ([[parameter]])"};
      auto p = read_parameter(*pt, where);
      if (!p) return p.error();
      spec.parameters.push_back(p.value());
    }
  }
  return spec;
}

std::vector<std::string> parameter_columns(const SweepSpec& spec) {
  std::vector<std::string> out;
  for (const Parameter& p : spec.parameters) out.insert(out.end(), p.keys.begin(), p.keys.end());
  return out;
}

std::size_t point_count(const SweepSpec& spec) {
  std::size_t n = 1;
  for (const Parameter& p : spec.parameters) n *= p.values.size();
  return n;
}

std::vector<PlannedRun> expand_runs(const SweepSpec& spec) {
  std::vector<PlannedRun> runs;
  const std::size_t points = point_count(spec);
  const int width = int(std::to_string(points ? points - 1 : 0).size());
  std::vector<std::optional<std::uint64_t>> seeds;
  for (std::uint64_t s : spec.seeds) seeds.push_back(s);
  if (seeds.empty()) seeds.push_back(std::nullopt);
  for (std::size_t point = 0; point < points; ++point) {
    PlannedRun base;
    base.point = point;
    base.overrides = spec.base_overrides;
    std::size_t rest = point;
    std::vector<std::size_t> choice(spec.parameters.size());
    for (std::size_t q = spec.parameters.size(); q-- > 0;) {  // the last parameter varies fastest
      choice[q] = rest % spec.parameters[q].values.size();
      rest /= spec.parameters[q].values.size();
    }
    for (std::size_t q = 0; q < spec.parameters.size(); ++q)
      for (std::size_t i = 0; i < spec.parameters[q].keys.size(); ++i) {
        const std::string& v = spec.parameters[q].values[choice[q]][i];
        base.columns.push_back(v);
        base.overrides.push_back(spec.parameters[q].keys[i] + "=" + v);
      }
    std::string p = std::to_string(point);
    p.insert(0, std::size_t(width) - p.size(), '0');
    for (const auto& seed : seeds) {
      PlannedRun r = base;
      r.index = runs.size();
      r.seed = seed;
      r.name = "p" + p + (seed ? "-s" + std::to_string(*seed) : "");
      if (seed) r.overrides.push_back("seed=" + std::to_string(*seed));
      runs.push_back(std::move(r));
    }
  }
  return runs;
}

}  // namespace ede::sweep
