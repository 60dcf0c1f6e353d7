// --set key=value: parse the key path and the value, walk the tree, replace one node.
//
// The walk is a loop over path steps on toml++ nodes: a step into a table takes a key (creating the table
// when it is missing, so "sampling.interval=0.1" works without [sampling]); a step into an array takes an
// index or, for a word, the element whose name is that word. Copies of the parsed value go into the tree:
// toml++ does not copy source positions, so errors on an overridden value name the --set, not a line of
// the one-line value text. Rejected: toml++'s at_path(), which cannot create tables or select by name.
#include "scene/scene_override.hpp"

#include <charconv>
#include <optional>
#include <string_view>

namespace ede::scene_detail {

namespace {

struct Step {
  std::string key;                   // a key, an element name, or the digits of species.1
  std::optional<std::size_t> index;  // species[1] or species.1
  bool bracketed = false;            // written [n]: only an array index, never a key
};

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

bool is_key_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
}

std::optional<std::size_t> parse_index(std::string_view digits) {
  std::size_t value = 0;
  if (digits.empty() || digits.size() > 9) return std::nullopt;
  auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec != std::errc() || end != digits.data() + digits.size()) return std::nullopt;
  return value;
}

class Applier {
 public:
  Applier(const std::string& source_name, int number, const std::string& text)
      : origin_{source_name, {}}, number_(number), text_(text) {}

  AppliedOverride apply(toml::table& root) {
    const auto eq = text_.find('=');
    if (eq == std::string::npos) fail("missing '='", "write key=value, e.g. --set physics.restitution=0.9");
    const std::string_view key = trim(std::string_view(text_).substr(0, eq));
    const std::string_view value = trim(std::string_view(text_).substr(eq + 1));
    if (key.empty()) fail("empty key before '='", "name the key to set, e.g. --set box.size=[2.0,1.0]");
    if (value.empty()) fail("missing value after '='", "give a value, e.g. --set stop.time=10");
    const std::vector<Step> steps = parse_path(key);
    const toml::table holder = parse_value(value);
    toml::node* parent = &root;
    for (std::size_t i = 0; i + 1 < steps.size(); ++i) parent = descend(*parent, steps[i], steps[i + 1]);
    assign(*parent, steps.back(), *holder.get("v"));
    return {number_, text_, path_};
  }

 private:
  [[noreturn]] void fail(std::string_view what, std::string_view fix) const {
    fail_at(origin_, {}, "--set #" + std::to_string(number_) + " " + user_quoted(text_), {}, what, fix);
  }

  std::vector<Step> parse_path(std::string_view key) const {
    std::vector<Step> steps;
    std::size_t pos = 0;
    while (pos <= key.size()) {
      const std::size_t dot = std::min(key.find('.', pos), key.size());
      parse_part(key.substr(pos, dot - pos), steps);
      pos = dot + 1;
    }
    return steps;
  }

  void parse_part(std::string_view part, std::vector<Step>& steps) const {
    const std::size_t bracket = std::min(part.find('['), part.size());
    const std::string_view name = part.substr(0, bracket);
    if (name.empty()) {
      fail("empty key in " + user_quoted(part), "write keys as a.b.c and elements as species[1]");
    }
    for (char c : name) {
      if (!is_key_char(c) && static_cast<unsigned char>(c) < 0x80) {  // UTF-8: a species named in another script
        fail("invalid character " + user_quoted(std::string(1, c)) + " in the key",
             "keys use letters, digits, '_' and '-'; elements are written species[1]");
      }
    }
    steps.push_back({std::string(name), parse_index(name), false});
    std::string_view rest = part.substr(bracket);
    while (!rest.empty()) {
      const std::size_t close = rest.find(']');
      const auto index =
          close == std::string_view::npos ? std::nullopt : parse_index(rest.substr(1, close - 1));
      if (rest.front() != '[' || !index) {
        fail("bad element index in " + user_quoted(part), "write an index as [0], [1], ...");
      }
      steps.push_back({std::string(rest.substr(0, close + 1)), index, true});
      rest = rest.substr(close + 1);
    }
  }

  // Digits with an optional sign, point, exponent or underscores: a number, however badly formed.
  static bool looks_numeric(std::string_view v) {
    if (v.empty()) return false;
    const char c = v.front() == '+' || v.front() == '-' ? (v.size() > 1 ? v[1] : 'x') : v.front();
    if (!(c >= '0' && c <= '9') && c != '.') return false;
    for (const char d : v)
      if (!((d >= '0' && d <= '9') || d == '.' || d == 'e' || d == 'E' || d == '+' || d == '-' || d == '_'))
        return false;
    return true;
  }

  toml::table parse_value(std::string_view value) const {
    try {
      toml::table holder = toml::parse("v = " + std::string(value), std::string_view("--set"));
      if (holder.size() == 1 && holder.contains("v")) return holder;
    } catch (const toml::parse_error& e) {
      const char c = value.front();
      if (c == '[' || c == '{' || c == '"' || c == '\'') {
        fail("the value is not valid TOML (" + std::string(e.description()) + ")",
             "check brackets, commas and quotes, e.g. --set 'box.size=[2.0, 1.0]'");
      }
      if (looks_numeric(value))  // 1e400, 1_000_: meant as a number, so not taken for a word
        fail("the value " + user_quoted(std::string(value)) + " is not a number a scene can hold (" +
                 std::string(e.description()) + ")",
             "give a finite number within the range of a double (about 1.8e308), e.g. 1e6");
    }
    toml::table holder;
    holder.insert("v", std::string(value));  // a bare word: scalar=float, boundary=periodic
    return holder;
  }

  // Into the child at step; next tells whether a missing key may become a new table.
  toml::node* descend(toml::node& node, const Step& step, const Step& next) {
    if (toml::table* t = node.as_table()) {
      key_into_table(step);
      if (toml::node* child = t->get(step.key)) return child;
      if (next.index) {
        fail("there is no " + path_ + "[" + std::to_string(*next.index) + "] (the scene has no " + step.key + ")",
             "add the element to the scene file first");
      }
      return &t->insert_or_assign(step.key, toml::table{}).first->second;
    }
    if (toml::array* a = node.as_array()) return a->get(element(*a, step));
    fail(user_quoted(path_) + " is " + describe(node) + ", not a table",
         "set " + path_ + " itself, or remove the keys after it");
  }

  void assign(toml::node& node, const Step& step, const toml::node& value) {
    if (toml::table* t = node.as_table()) {
      key_into_table(step);
      value.visit([&](const auto& v) { t->insert_or_assign(step.key, v); });  // a copy: no source lines
      return;
    }
    if (toml::array* a = node.as_array()) {
      const std::size_t i = element(*a, step);
      value.visit([&](const auto& v) { a->replace(a->cbegin() + static_cast<std::ptrdiff_t>(i), v); });
      return;
    }
    fail(user_quoted(path_) + " is " + describe(node) + ", not a table",
         "set " + path_ + " itself, or remove the keys after it");
  }

  void key_into_table(const Step& step) {
    if (step.bracketed) {
      fail(user_quoted(path_) + " is a table, not an array", "select a key with '.', not " + step.key);
    }
    array_name_ = step.key;
    path_ += (path_.empty() ? "" : ".") + step.key;
  }

  // The index of the element a step selects in an array: [n], .n, or .NAME matching its name key.
  std::size_t element(const toml::array& a, const Step& step) {
    std::optional<std::size_t> index = step.index;
    if (!index) index = find_named(a, step.key);
    if (!index) {
      fail("there is no " + array_name_ + " named " + user_quoted(step.key) + " (" + inventory(a) + ")",
           "use one of those names or an index, e.g. " + path_ + "[0]");
    }
    if (*index >= a.size()) {
      fail("there is no " + path_ + "[" + std::to_string(*index) + "] (" + inventory(a) + ")",
           a.empty() ? "add one to the scene file first"
                     : "use an index from 0 to " + std::to_string(a.size() - 1) + " or a name");
    }
    path_ += "[" + std::to_string(*index) + "]";
    return *index;
  }

  static std::optional<std::size_t> find_named(const toml::array& a, std::string_view name) {
    for (std::size_t i = 0; i < a.size(); ++i) {
      const toml::table* t = a.get(i)->as_table();
      const toml::node* n = t ? t->get("name") : nullptr;
      if (n && n->as_string() && n->as_string()->get() == name) return i;
    }
    return std::nullopt;
  }

  std::string inventory(const toml::array& a) const {  // "the scene has 2 species: gas, projectile"
    std::string names;
    for (std::size_t i = 0; i < a.size() && i < 10; ++i) {
      const toml::table* t = a.get(i)->as_table();
      const toml::node* n = t ? t->get("name") : nullptr;
      if (n == nullptr || n->as_string() == nullptr) continue;
      names += (names.empty() ? ": " : ", ") + printable(n->as_string()->get());
    }
    if (a.size() > 10 && !names.empty()) names += ", ...";
    return "the scene has " + std::to_string(a.size()) + " " + array_name_ + names;
  }

  Origin origin_;
  int number_;
  const std::string& text_;
  std::string path_;        // canonical path walked so far: species[1].placement
  std::string array_name_;  // the key of the last table entry walked into, for messages
};

}  // namespace

std::vector<AppliedOverride> apply_overrides(toml::table& root, const std::vector<Override>& overrides,
                                             const std::string& source_name) {
  std::vector<AppliedOverride> applied;
  for (std::size_t i = 0; i < overrides.size(); ++i) {
    Applier applier(source_name, static_cast<int>(i + 1), overrides[i].text);
    applied.push_back(applier.apply(root));
  }
  return applied;
}

}  // namespace ede::scene_detail
