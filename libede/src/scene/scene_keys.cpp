// The allowed keys of each scene table, typed reads of TOML nodes, and the error message format.
//
// A read either returns a value that is what the key promises (finite, in range, the right type) or throws
// one SceneError naming the key path and its line. Integers are accepted wherever numbers are, and
// integral floats (1e6) wherever integers are, because users write both. Rejected: toml++'s
// node.value<T>(), which converts silently (a float to an integer, nan through) and cannot say why not.
#include "scene/scene_keys.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace ede::scene_detail {

namespace {

constexpr std::string_view kRootKeys[] = {"seed", "box",  "physics",  "engine", "log",
                                          "species", "grow", "stop", "sampling", "actions", "start", "walls",
                                          "thermostat"};
constexpr std::string_view kWallsKeys[] = {"segments", "polygons"};
constexpr std::string_view kSegmentKeys[] = {"from", "to", "restitution"};
constexpr std::string_view kPolygonKeys[] = {"points", "closed", "restitution"};
constexpr std::string_view kBoxKeys[] = {"size", "boundary", "shear_rate"};
constexpr std::string_view kPhysicsKeys[] = {"restitution", "wall_restitution", "tc", "gravity", "pairs",
                                             "roughness",   "wall_roughness",   "steps"};
constexpr std::string_view kWallRestitutionKeys[] = {"left", "right", "bottom", "top"};
constexpr std::string_view kPairKeys[] = {"species", "restitution", "roughness"};
constexpr std::string_view kStepKeys[] = {"species", "radius", "energy"};
constexpr std::string_view kEngineKeys[] = {"scalar", "rebuild_interval"};
constexpr std::string_view kLogKeys[] = {"keyframe_interval", "chunk_events", "compression_level"};
constexpr std::string_view kSpeciesKeys[] = {"name",    "count",     "radius",  "mass",
                                             "density", "placement", "velocity", "inertia_factor",
                                             "omega",   "spin_temperature", "thermostat"};
constexpr std::string_view kRadiusKeys[] = {"min", "max"};
constexpr std::string_view kPlacementKeys[] = {"kind", "region", "packing_fraction", "lattice", "sampling",
                                               "positions"};
constexpr std::string_view kVelocityKeys[] = {"kind", "speed", "vector", "temperature", "values"};
constexpr std::string_view kGrowKeys[] = {"packing_fraction", "pressure", "rate"};
constexpr std::string_view kStopKeys[] = {"time", "events", "collisions_per_particle", "energy_fraction"};
constexpr std::string_view kSamplingKeys[] = {"interval", "collisions_per_disk"};
constexpr std::string_view kActionKeys[] = {"time", "collisions_per_disk", "kind"};
constexpr std::string_view kThermostatKeys[] = {"temperature", "rate", "species"};
constexpr std::string_view kSpeciesThermostatKeys[] = {"temperature", "rate"};
constexpr std::string_view kStartKeys[] = {"from", "at", "csv", "digest", "zero_momentum", "reverse_velocities"};

}  // namespace

namespace sections {
const Section root{"the top level", kRootKeys};
const Section box{"[box]", kBoxKeys};
const Section physics{"[physics]", kPhysicsKeys};
const Section wall_restitution{"physics.wall_restitution = { left, right, bottom, top }", kWallRestitutionKeys};
const Section pair{"[[physics.pairs]]", kPairKeys};
const Section steps{"[[physics.steps]]", kStepKeys};
const Section engine{"[engine]", kEngineKeys};
const Section log{"[log]", kLogKeys};
const Section species{"[[species]]", kSpeciesKeys};
const Section radius{"species.radius = { min, max }", kRadiusKeys};
const Section placement{"[species.placement]", kPlacementKeys};
const Section velocity{"[species.velocity]", kVelocityKeys};
const Section grow{"[grow]", kGrowKeys};
const Section stop{"[stop]", kStopKeys};
const Section sampling{"[sampling]", kSamplingKeys};
const Section action{"[[actions]]", kActionKeys};
const Section start{"[start]", kStartKeys};
const Section walls{"[walls]", kWallsKeys};
const Section segment{"[[walls.segments]]", kSegmentKeys};
const Section polygon{"[[walls.polygons]]", kPolygonKeys};
const Section thermostat{"[thermostat]", kThermostatKeys};
const Section species_thermostat{"[species.thermostat]", kSpeciesThermostatKeys};
}  // namespace sections

namespace {

const Section* const kAllSections[] = {&sections::root,      &sections::box,      &sections::physics,
                                       &sections::wall_restitution, &sections::pair, &sections::steps,
                                       &sections::engine,    &sections::log,      &sections::species,
                                       &sections::radius,
                                       &sections::placement, &sections::velocity, &sections::grow, &sections::stop,
                                       &sections::sampling,  &sections::action, &sections::start,
                                       &sections::walls,     &sections::segment, &sections::polygon,
                                       &sections::thermostat, &sections::species_thermostat};

bool contains(std::span<const std::string_view> list, std::string_view word) {
  return std::find(list.begin(), list.end(), word) != list.end();
}

std::string join(std::span<const std::string_view> words, std::string_view quote) {
  std::string out;
  for (std::string_view w : words) {
    if (!out.empty()) out += ", ";
    out.append(quote).append(w).append(quote);
  }
  return out;
}

// An override covers a path when it set that path or a table or array element above it.
bool covers(std::string_view set_path, std::string_view path) {
  if (path.substr(0, set_path.size()) != set_path) return false;
  return path.size() == set_path.size() || path[set_path.size()] == '.' || path[set_path.size()] == '[';
}

std::string sentence(std::string_view text) {  // text with one closing punctuation mark
  std::string out(text);
  if (!out.empty() && out.back() != '.' && out.back() != '?') out += '.';
  return out;
}

}  // namespace

void fail_at(const Origin& origin, toml::source_position at, std::string_view path, std::string_view label,
             std::string_view what, std::string_view fix) {
  std::string msg = origin.source_name;
  if (at.line > 0) msg += ":" + std::to_string(at.line) + ":" + std::to_string(at.column);
  msg += ": error: ";
  msg.append(path.empty() ? std::string_view("scene") : path);
  if (!label.empty()) msg.append(" (").append(label).append(")");
  msg.append(": ").append(what);
  for (auto it = origin.overrides.rbegin(); it != origin.overrides.rend(); ++it) {
    if (!covers(it->path, path)) continue;
    msg += " (set by --set #" + std::to_string(it->number) + " " + user_quoted(it->text) + ")";
    break;
  }
  msg = sentence(msg);
  if (!fix.empty()) msg += " Fix: " + sentence(fix);
  throw SceneError{msg};
}

std::string printable(std::string_view text) {
  std::string out;
  for (char c : text.substr(0, 80)) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      out += hex;
    } else {
      out += c;
    }
  }
  if (text.size() > 80) out += "...";
  return out;
}


std::string user_quoted(std::string_view user_text) { return "'" + printable(user_text) + "'"; }

std::string number_text(double value) {
  char buf[64];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
  return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

std::string describe(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return std::to_string(node.as_integer()->get());
    case toml::node_type::floating_point: return number_text(node.as_floating_point()->get());
    case toml::node_type::boolean: return node.as_boolean()->get() ? "true" : "false";
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    default: return "nothing";
  }
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Optimal string alignment: insertions, deletions, substitutions and swaps of neighbours cost 1 each.
  auto low = [](char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; };
  std::vector<std::size_t> prev2(b.size() + 1), prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t cost = low(a[i - 1]) == low(b[j - 1]) ? 0 : 1;
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + cost});
      if (i > 1 && j > 1 && low(a[i - 1]) == low(b[j - 2]) && low(a[i - 2]) == low(b[j - 1])) {
        cur[j] = std::min(cur[j], prev2[j - 2] + 1);
      }
    }
    std::swap(prev2, prev);
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::optional<std::string_view> closest(std::string_view word, std::span<const std::string_view> candidates) {
  if (word.empty() || word.size() > 64) return std::nullopt;
  const std::size_t limit = std::max<std::size_t>(1, word.size() / 3);
  std::optional<std::string_view> best;
  std::size_t best_distance = limit + 1;
  for (std::string_view c : candidates) {
    std::size_t d = edit_distance(word, c);
    if (d < best_distance && d < c.size()) {
      best = c;
      best_distance = d;
    }
  }
  return best;
}

namespace {

const Section* section_for(std::string_view key) {  // the section of the table held under key, if any
  static const std::pair<std::string_view, const Section*> kTables[] = {
      {"box", &sections::box},           {"physics", &sections::physics}, {"engine", &sections::engine},
      {"log", &sections::log},           {"wall_restitution", &sections::wall_restitution},
      {"pairs", &sections::pair},        {"steps", &sections::steps},
      {"species", &sections::species},   {"radius", &sections::radius},   {"placement", &sections::placement},
      {"velocity", &sections::velocity}, {"grow", &sections::grow},     {"stop", &sections::stop},       {"sampling", &sections::sampling},
      {"actions", &sections::action},    {"start", &sections::start},     {"thermostat", &sections::thermostat}};
  for (const auto& [name, section] : kTables) {
    if (name == key) return section;
  }
  return nullptr;
}

// The entries of a table, those of its section first and in its order, then any others.
std::vector<std::pair<std::string_view, const toml::node*>> ordered(const toml::table& t, const Section* s) {
  std::vector<std::pair<std::string_view, const toml::node*>> out;
  if (s != nullptr) {
    for (std::string_view key : s->keys) {
      if (const toml::node* n = t.get(key)) out.emplace_back(key, n);
    }
  }
  for (auto&& [key, node] : t) {
    if (s == nullptr || !contains(s->keys, key.str())) out.emplace_back(key.str(), &node);
  }
  return out;
}

std::string toml_key(std::string_view key) {
  const bool bare = !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
  });
  if (bare) return std::string(key);
  std::ostringstream out;
  out << toml::toml_formatter(toml::value<std::string>(std::string(key)), toml::format_flags::none);
  return out.str();
}

bool is_header_table(const toml::node& n) { return n.is_table() && !n.as_table()->is_inline(); }
bool is_table_array(const toml::node& n) { return n.is_array_of_tables(); }

void write_value(std::ostream& out, const toml::node& node, const Section* section) {
  if (const auto* f = node.as_floating_point()) {
    std::string text = number_text(f->get());
    if (text.find_first_of(".en") == std::string::npos) text += ".0";  // keep it a float: 1 -> 1.0
    out << text;
  } else if (const toml::array* a = node.as_array()) {
    out << "[";
    for (std::size_t i = 0; i < a->size(); ++i) {
      out << (i ? ", " : "");
      write_value(out, *a->get(i), section);
    }
    out << "]";
  } else if (const toml::table* t = node.as_table()) {
    out << "{";
    const char* sep = " ";
    for (const auto& [key, child] : ordered(*t, section)) {
      out << sep << toml_key(key) << " = ";
      write_value(out, *child, section_for(key));
      sep = ", ";
    }
    out << " }";
  } else {
    out << toml::toml_formatter(node, toml::format_flags::none);  // integers, booleans, strings, dates
  }
}

void write_body(std::ostream& out, const toml::table& t, const Section* section, const std::string& header) {
  const auto entries = ordered(t, section);
  for (const auto& [key, node] : entries) {
    if (is_header_table(*node) || is_table_array(*node)) continue;
    out << toml_key(key) << " = ";
    write_value(out, *node, section_for(key));
    out << "\n";
  }
  for (const auto& [key, node] : entries) {
    const std::string path = (header.empty() ? "" : header + ".") + toml_key(key);
    if (is_header_table(*node)) {
      out << "\n[" << path << "]\n";
      write_body(out, *node->as_table(), section_for(key), path);
    } else if (is_table_array(*node)) {
      for (const toml::node& item : *node->as_array()) {
        out << "\n[[" << path << "]]\n";
        write_body(out, *item.as_table(), section_for(key), path);
      }
    }
  }
}

}  // namespace

std::string to_toml(const toml::table& root) {
  std::ostringstream out;
  write_body(out, root, &sections::root, "");
  return out.str();
}

bool Bounds::contains(double v) const {
  bool above = lo_open ? v > lo : v >= lo;
  bool below = hi_open ? v < hi : v <= hi;
  return above && below;
}

std::string Bounds::text() const {
  if (std::isinf(hi)) return std::string(lo_open ? "> " : ">= ") + number_text(lo);
  if (std::isinf(lo)) return std::string(hi_open ? "< " : "<= ") + number_text(hi);
  return std::string("in ") + (lo_open ? "(" : "[") + number_text(lo) + ", " + number_text(hi) +
         (hi_open ? ")" : "]");
}

Reader::Reader(const toml::table& table, std::string path, const Origin& origin, std::string label)
    : table_(&table), path_(std::move(path)), origin_(&origin), label_(std::move(label)) {}

std::string Reader::path_of(std::string_view key) const {
  return path_.empty() ? printable(key) : path_ + "." + printable(key);
}

void Reader::check_keys(const Section& section) const {
  for (auto&& [key, value] : *table_) {
    (void)value;
    if (!contains(section.keys, key.str())) unknown_key(key, section);
  }
}

void Reader::unknown_key(const toml::key& key, const Section& section) const {
  std::string what = "unknown key";  // the path ends with it
  std::string fix = "remove it or correct its spelling; the keys of " + std::string(section.name) + " are " +
                    join(section.keys, "");
  if (auto near = closest(key.str(), section.keys)) {
    what += "; did you mean '" + std::string(*near) + "'?";
    fix = "rename it to '" + std::string(*near) + "'";
  } else {
    for (const Section* other : kAllSections) {
      if (other == &section || !contains(other->keys, key.str())) continue;
      what += "; '" + std::string(key.str()) + "' belongs in " + std::string(other->name);
      fix = "move it to " + std::string(other->name);
      break;
    }
  }
  fail_at(*origin_, key.source().begin, path_of(key.str()), label_, what, fix);
}

Reader Reader::section(std::string_view key) const {
  static const toml::table empty;
  const toml::node* node = get(key);
  if (node == nullptr) return Reader(empty, path_of(key), *origin_, label_);
  if (const toml::table* t = node->as_table()) return Reader(*t, path_of(key), *origin_, label_);
  fail(key, "expected a table, got " + describe(*node),
       "make it a table: a [header] line followed by its keys, or an inline { key = value }");
}

const toml::array* Reader::array(std::string_view key) const {
  const toml::node* node = get(key);
  if (node == nullptr) return nullptr;
  if (const toml::array* a = node->as_array()) return a;
  fail(key, "expected an array, got " + describe(*node), "write it as [ ... ] (see docs/scene-format.md)");
}

double Reader::number_in(const toml::node& node, const std::string& path, Bounds bounds,
                         std::string_view fix) const {
  double v = 0;
  if (const auto* i = node.as_integer()) {
    v = static_cast<double>(i->get());
  } else if (const auto* f = node.as_floating_point()) {
    v = f->get();
  } else {
    fail_node(&node, path, "expected a number, got " + describe(node),
              "write a number without quotes, e.g. 0.5");
  }
  if (!std::isfinite(v)) {
    fail_node(&node, path, "must be a finite number, got " + describe(node), "use a finite value");
  }
  if (!bounds.contains(v)) {
    fail_node(&node, path, "must be " + bounds.text() + ", got " + number_text(v),
              fix.empty() ? "use a value " + bounds.text() : std::string(fix));
  }
  return v;
}

std::optional<double> Reader::number(std::string_view key, Bounds bounds, std::string_view fix) const {
  const toml::node* node = get(key);
  if (node == nullptr) return std::nullopt;
  return number_in(*node, path_of(key), bounds, fix);
}

std::optional<std::int64_t> Reader::integer(std::string_view key, std::int64_t lo, std::int64_t hi) const {
  const toml::node* node = get(key);
  if (node == nullptr) return std::nullopt;
  std::int64_t v = 0;
  if (const auto* i = node->as_integer()) {
    v = i->get();
  } else if (const auto* f = node->as_floating_point();
             f != nullptr && std::isfinite(f->get()) && std::trunc(f->get()) == f->get() &&
             f->get() >= -9223372036854775808.0 && f->get() < 9223372036854775808.0) {
    v = static_cast<std::int64_t>(f->get());  // in range and integral: exact
  } else {
    fail(key, "expected an integer, got " + describe(*node), "write a whole number, e.g. 1000");
  }
  if (v < lo) {
    fail(key, "must be >= " + std::to_string(lo) + ", got " + std::to_string(v),
         "use a value >= " + std::to_string(lo));
  }
  if (v > hi) {
    fail(key, "must be <= " + std::to_string(hi) + ", got " + std::to_string(v),
         "use a value <= " + std::to_string(hi));
  }
  return v;
}

std::optional<std::string> Reader::string(std::string_view key) const {
  const toml::node* node = get(key);
  if (node == nullptr) return std::nullopt;
  if (const auto* s = node->as_string()) return s->get();
  fail(key, "expected a string, got " + describe(*node),
       "put the text in quotes, e.g. " + std::string(key) + " = \"...\"");
}

std::optional<std::size_t> Reader::choice(std::string_view key,
                                          std::initializer_list<std::string_view> names) const {
  std::optional<std::string> value = string(key);
  if (!value) return std::nullopt;
  std::span<const std::string_view> list(names.begin(), names.size());
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (list[i] == *value) return i;
  }
  std::string what = "unknown value " + user_quoted(*value);
  if (auto near = closest(*value, list)) what += "; did you mean \"" + std::string(*near) + "\"?";
  fail(key, what, "use one of " + join(list, "\""));
}

std::optional<std::vector<double>> Reader::numbers(std::string_view key, std::size_t n,
                                                   std::string_view shape, Bounds bounds) const {
  const toml::node* node = get(key);
  if (node == nullptr) return std::nullopt;
  const toml::array* a = node->as_array();
  std::string expected = "expected an array of " + std::to_string(n) + " numbers " + std::string(shape);
  if (a == nullptr) {
    fail(key, expected + ", got " + describe(*node),
         "write " + std::string(key) + " = " + std::string(shape));
  }
  if (a->size() != n) {
    fail(key, expected + ", got " + std::to_string(a->size()),
         "write " + std::string(key) + " = " + std::string(shape));
  }
  std::vector<double> out;
  for (std::size_t j = 0; j < n; ++j) {
    out.push_back(number_in(*a->get(j), path_of(key) + "[" + std::to_string(j) + "]", bounds, {}));
  }
  return out;
}

std::optional<std::vector<std::array<double, 2>>> Reader::pairs(std::string_view key,
                                                                std::string_view shape) const {
  const toml::array* a = array(key);
  if (a == nullptr) return std::nullopt;
  std::vector<std::array<double, 2>> out;
  out.reserve(a->size());
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::node& item = *a->get(i);
    const std::string path = path_of(key) + "[" + std::to_string(i) + "]";
    const toml::array* p = item.as_array();
    if (p == nullptr || p->size() != 2) {
      fail_node(&item, path,
                "expected a pair " + std::string(shape) + ", got " +
                    (p ? "an array of " + std::to_string(p->size()) : describe(item)),
                "write each entry as " + std::string(shape));
    }
    out.push_back({number_in(*p->get(0), path + "[0]", Bounds::any(), {}),
                   number_in(*p->get(1), path + "[1]", Bounds::any(), {})});
  }
  return out;
}

void Reader::fail(std::string_view key, std::string_view what, std::string_view fix) const {
  // A missing key is reported at its table, except at the top level: line 1 would point nowhere useful.
  const toml::node* node = get(key);
  const toml::node* at = node ? node : (path_.empty() ? nullptr : table_);
  fail_node(at, path_of(key), what, fix);
}

void Reader::fail_item(std::string_view key, std::size_t i, std::string_view what,
                       std::string_view fix) const {
  const toml::node* node = get(key);
  const toml::array* a = node ? node->as_array() : nullptr;
  const toml::node* item = (a && i < a->size()) ? a->get(i) : node;
  fail_node(item, path_of(key) + "[" + std::to_string(i) + "]", what, fix);
}

void Reader::fail_here(std::string_view what, std::string_view fix) const {
  fail_at(*origin_, table_->source().begin, path_, label_, what, fix);
}

void Reader::fail_node(const toml::node* at, std::string_view path, std::string_view what,
                       std::string_view fix) const {
  fail_at(*origin_, at ? at->source().begin : toml::source_position{}, path, label_, what, fix);
}

}  // namespace ede::scene_detail
