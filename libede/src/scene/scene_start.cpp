// The [start] table and continuation scenes; see scene_start.hpp.
#include "scene/scene_start.hpp"

namespace ede::scene_detail {

namespace {

bool flag(const Reader& r, std::string_view key) {
  const toml::node* node = r.get(key);
  if (!node) return false;
  if (const auto* b = node->as_boolean()) return b->get();
  r.fail(key, "expected true or false, got " + describe(*node), "write " + std::string(key) + " = true");
}

}  // namespace

std::optional<StartSpec> read_start(const Reader& top) {
  if (!top.has("start")) return std::nullopt;
  if (!top.get("start")->is_table())
    top.fail("start", "expected a table, got " + describe(*top.get("start")),
             "write [start] with from = \"run.ede\" (and at = 2.5) or csv = \"state.csv\"");
  const Reader s = top.section("start");
  s.check_keys(sections::start);
  StartSpec out;
  out.from = s.string("from").value_or("");
  out.csv = s.string("csv").value_or("");
  out.at = s.number("at", Bounds::non_negative(), "give a time within the log, e.g. at = 2.5");
  out.digest = s.string("digest").value_or("");
  out.zero_momentum = flag(s, "zero_momentum");
  out.reverse_velocities = flag(s, "reverse_velocities");
  if (out.from.empty() == out.csv.empty())
    s.fail_here(out.from.empty() ? "neither from nor csv is given, so there is no state to start from"
                                 : "both from and csv are given",
                "give one: from = \"run.ede\" (an event log, with at = TIME) or csv = \"state.csv\"");
  if (out.at && out.from.empty()) s.fail("at", "a time only makes sense in an event log", "remove at, or use from");
  if (top.has("species"))
    top.fail("species", "a scene with [start] takes its disks from the state, so it has no [[species]]",
             "remove the [[species]] tables, or remove [start]");
  return out;
}

}  // namespace ede::scene_detail

namespace ede {

Result<std::string> continuation_scene_text(const std::string& scene_text, const std::string& scene_name,
                                            const std::string& log_path, std::optional<double> at) {
  try {
    toml::table root = toml::parse(std::string_view(scene_text), std::string_view(scene_name));
    root.erase("species");
    root.erase("grow");
    root.erase("actions");
    toml::table start;
    start.insert("from", log_path);
    if (at) start.insert("at", *at);
    root.insert_or_assign("start", std::move(start));
    return "# continues " + scene_detail::printable(log_path) + " (scene " + scene_detail::printable(scene_name) +
           ")\n" + scene_detail::to_toml(root);
  } catch (const toml::parse_error& e) {
    return Error{log_path + ": the scene in the log's header does not parse as TOML (" + std::string(e.description()) +
                 "); it cannot be continued"};
  }
}

}  // namespace ede
