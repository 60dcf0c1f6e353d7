// Reading a scene's TOML tree key by key, with errors that say where and how to fix them.
//
// What every part of the loader needs lives here: the keys each table may hold (a mistyped key is an error
// with a "did you mean" suggestion), typed reads (number, integer, string, choice, fixed-size arrays) that
// reject wrong types, NaN and infinities, the one message format
//   FILE:LINE:COL: error: KEYPATH: what is wrong. Fix: what to do.
// and the writer that turns a checked tree back into TOML with its keys in the same order as the tables.
// scene_loader.cpp then only says what each key means and which values are allowed.
// Errors are thrown as SceneError inside the loader and become ede::Error at its two entry points, so a
// failed check deep in a species table needs no plumbing. Rejected: Result<T> from every read, which
// tripled the checking code without making any message clearer.
#pragma once

#include <toml++/toml.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ede::scene_detail {

struct SceneError {
  std::string message;
};

struct AppliedOverride {
  int number = 0;    // 1-based position among the --set options
  std::string text;  // as the user wrote it
  std::string path;  // the canonical key path it set, e.g. species[1].mass
};

struct Origin {  // where a tree came from: the file, then the overrides applied to it
  std::string source_name;
  std::vector<AppliedOverride> overrides;
};

// Throws SceneError "FILE[:LINE:COL]: error: PATH (LABEL): WHAT (set by --set #k '...'). Fix: FIX."
// The line is left out when unknown (line 0: a value made by an override); the --set note is added when an
// override set PATH or a table above it.
[[noreturn]] void fail_at(const Origin& origin, toml::source_position at, std::string_view path,
                          std::string_view label, std::string_view what, std::string_view fix);

std::string printable(std::string_view user_text);    // control characters escaped, long text cut
std::string user_quoted(std::string_view user_text);  // 'text', control characters escaped, long text cut
std::string number_text(double value);                // shortest text that reads back to the same double
std::string describe(const toml::node& node);         // "a string", "an array", "2.5" (for "got ...")
std::size_t edit_distance(std::string_view a, std::string_view b);  // with transpositions, case-blind
std::optional<std::string_view> closest(std::string_view word, std::span<const std::string_view> candidates);

// The keys one kind of table may hold. name is how a user finds the table in a file: "[species.velocity]".
struct Section {
  std::string_view name;
  std::span<const std::string_view> keys;
};

namespace sections {
extern const Section root, box, physics, wall_restitution, pair, steps, engine, log, species, radius, placement, velocity,
    grow, stop, sampling, action, start, walls, segment, polygon, thermostat, species_thermostat;
}

// A checked scene tree as TOML text: keys in the order of the sections above (the order of the docs),
// doubles in their shortest form that reads back to the same value. Rejected: toml++'s formatter, which
// sorts keys alphabetically and writes 0.9 as 0.90000000000000002.
std::string to_toml(const toml::table& root);

// An allowed interval of numbers; text() is how messages say it ("> 0", "in [0, 1]").
struct Bounds {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;

  static Bounds any() { return {}; }
  static Bounds positive() { return {0, std::numeric_limits<double>::infinity(), true, false}; }
  static Bounds non_negative() { return {0, std::numeric_limits<double>::infinity(), false, false}; }
  static Bounds closed(double lo, double hi) { return {lo, hi, false, false}; }
  static Bounds open(double lo, double hi) { return {lo, hi, true, true}; }

  bool contains(double v) const;
  std::string text() const;
};

// One table of the tree with its key path ("species[1].placement") and a label for messages
// ("species 'projectile'"). Every read returns nullopt when the key is absent and throws on a bad value.
class Reader {
 public:
  Reader(const toml::table& table, std::string path, const Origin& origin, std::string label = {});

  const std::string& path() const { return path_; }
  const std::string& label() const { return label_; }
  const Origin& origin() const { return *origin_; }
  std::string path_of(std::string_view key) const;
  const toml::node* get(std::string_view key) const { return table_->get(key); }
  bool has(std::string_view key) const { return get(key) != nullptr; }

  void check_keys(const Section& section) const;  // every key is one of section.keys
  Reader section(std::string_view key) const;     // a sub-table, or an empty one when absent
  const toml::array* array(std::string_view key) const;

  std::optional<double> number(std::string_view key, Bounds bounds, std::string_view fix = {}) const;
  std::optional<std::int64_t> integer(std::string_view key, std::int64_t lo,
                                      std::int64_t hi = std::numeric_limits<std::int64_t>::max()) const;
  std::optional<std::string> string(std::string_view key) const;
  // The index of the value among names; "did you mean" for a near miss.
  std::optional<std::size_t> choice(std::string_view key,
                                    std::initializer_list<std::string_view> names) const;
  // An array of exactly n numbers, each within bounds; shape says it for messages ("[x0, y0, x1, y1]").
  std::optional<std::vector<double>> numbers(std::string_view key, std::size_t n, std::string_view shape,
                                             Bounds bounds) const;
  // An array of [a, b] pairs of finite numbers (positions, velocities); shape names one ("[x, y]").
  std::optional<std::vector<std::array<double, 2>>> pairs(std::string_view key, std::string_view shape) const;

  [[noreturn]] void fail(std::string_view key, std::string_view what, std::string_view fix) const;
  [[noreturn]] void fail_item(std::string_view key, std::size_t i, std::string_view what,
                              std::string_view fix) const;
  [[noreturn]] void fail_here(std::string_view what, std::string_view fix) const;  // at the table itself
  [[noreturn]] void fail_node(const toml::node* at, std::string_view path, std::string_view what,
                              std::string_view fix) const;

 private:
  double number_in(const toml::node& node, const std::string& path, Bounds bounds,
                   std::string_view fix) const;
  [[noreturn]] void unknown_key(const toml::key& key, const Section& section) const;

  const toml::table* table_;
  std::string path_;
  const Origin* origin_;
  std::string label_;
};

}  // namespace ede::scene_detail
