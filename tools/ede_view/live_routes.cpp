// Live-run routes; see live_routes.hpp. A scene's problems (a misspelt key, a radius too big to place the
// disks) come back as 400 with the library's own message, which names the key and the fix.
#include "live_routes.hpp"

#include <nlohmann/json.hpp>

#include "clusters.hpp"
#include "ede/ede.hpp"

namespace ede::view {
namespace {

// The parameters the page offers, read from a scene (the first species stands for the disks).
nlohmann::json scene_json(const std::string& name, const Scene& s) {
  const SpeciesSpec* sp = s.species.empty() ? nullptr : &s.species.front();
  std::uint64_t disks = 0;
  std::vector<std::string> names;
  for (const SpeciesSpec& x : s.species) disks += std::uint64_t(x.count), names.push_back(x.name);
  return {{"name", name},
          {"disks", disks},
          {"species", s.species.size()},
          {"count", sp ? sp->count : 0},
          {"radius", sp && !sp->radius.from_packing && sp->radius.min == sp->radius.max ? nlohmann::json(sp->radius.min)
                                                                                         : nlohmann::json(nullptr)},
          {"restitution", s.physics.restitution},
          {"tc", s.physics.tc},
          {"gravity", s.physics.gravity},
          {"boundary", to_string(s.boundary)},
          {"clusters_unavailable", clusters_unavailable(bond_radii(s.physics.steps, names))},
          {"box", {s.lx, s.ly}}};
}

// An override of the scene's [start] table: the keys that make a run start from a file (a log or a CSV
// state) the server would then read wherever it lies. The scene files themselves are the operator's.
bool names_a_file(const std::string& override_text) {
  std::string key = override_text.substr(0, override_text.find('='));
  key.erase(0, key.find_first_not_of(" \t"));
  key.erase(key.find_last_not_of(" \t") + 1);
  return key == "start" || key.rfind("start.", 0) == 0;
}

}  // namespace

void add_live_routes(httplib::Server& server, const std::vector<Root>& roots, LiveRuns& runs, FrameBudget& budget) {
  server.Get("/api/scenes", [roots](const httplib::Request&, httplib::Response& res) {
    send_json(res, nlohmann::json{{"scenes", list_files(roots, ".toml")}}.dump());
  });
  server.Get("/api/scene", [roots](const httplib::Request& req, httplib::Response& res) {
    const Resolved r = resolve_under(roots, req.get_param_value("name"), ".toml");
    if (r.status != 200) return send_error(res, r.status, r.error);
    auto scene = load_scene_file(r.path.string());
    if (!scene) return send_error(res, 400, scene.error().message);
    send_json(res, scene_json(req.get_param_value("name"), scene.value()).dump());
  });
  server.Post("/api/run/setup", [roots, &runs](const httplib::Request& req, httplib::Response& res) {
    const nlohmann::json body = nlohmann::json::parse(req.body, nullptr, false);
    if (body.is_discarded() || !body.is_object() || !body.contains("scene") || !body["scene"].is_string())
      return send_error(res, 400, "the body must be a JSON object {\"scene\": NAME, \"set\": [\"key=value\", ...]}");
    LiveSetup setup;
    setup.scene_label = body["scene"].get<std::string>();
    const Resolved r = resolve_under(roots, setup.scene_label, ".toml");
    if (r.status != 200) return send_error(res, r.status, r.error);
    setup.scene_path = r.path.string();
    if (body.contains("set")) {
      if (!body["set"].is_array()) return send_error(res, 400, "'set' must be a list of \"key=value\" texts");
      for (const auto& o : body["set"]) {
        if (!o.is_string()) return send_error(res, 400, "'set' must be a list of \"key=value\" texts");
        if (names_a_file(o.get<std::string>()))
          return send_error(res, 403, "'" + o.get<std::string>().substr(0, 100) +
                                          "': the page may not set start.* (start.from and start.csv name a file, "
                                          "which may lie outside the folders ede-view serves). Fix: a scene file "
                                          "under --scenes that starts from the state");
        setup.overrides.push_back(o.get<std::string>());
      }
    }
    if (body.contains("until")) {
      if (!body["until"].is_number() || !(body["until"].get<double>() > 0))
        return send_error(res, 400, "'until' must be a positive number (the run's stop.time)");
      setup.until = body["until"].get<double>();
    }
    auto status = runs.setup(setup);
    if (!status) return send_error(res, 400, status.error().message);
    send_json(res, status.value());
  });
  const auto control = [&runs](Status (LiveRuns::*act)()) {
    return [&runs, act](const httplib::Request&, httplib::Response& res) {
      if (Status s = (runs.*act)(); !s) return send_error(res, 409, s.error().message);
      send_json(res, runs.status_json());
    };
  };
  server.Post("/api/run/go", control(&LiveRuns::go));
  server.Post("/api/run/pause", control(&LiveRuns::pause));
  server.Post("/api/run/reverse", control(&LiveRuns::reverse));
  server.Post("/api/run/finish", control(&LiveRuns::finish));
  server.Post("/api/run/pace", [&runs](const httplib::Request& req, httplib::Response& res) {
    const auto pace = number_param(req, res, "pace");
    if (!pace) return;
    if (*pace < 0) return send_error(res, 400, "'pace' must be >= 0 (0: as fast as the engine goes)");
    runs.set_pace(*pace);
    send_json(res, runs.status_json());
  });
  server.Get("/api/run/status", [&runs](const httplib::Request&, httplib::Response& res) {
    send_json(res, runs.status_json());
  });
  server.Get("/api/run/frame", [&runs, &budget](const httplib::Request& req, httplib::Response& res) {
    const auto request = frame_request_param(req, res, 200000);
    if (!request) return;
    if (const std::string why = runs.refused(*request); !why.empty())
      return send_error(res, 400, "parameter 'colour': " + why);
    auto frame = runs.frame(*request);
    if (!frame) return send_error(res, 404, "no run: press SETUP first");
    send_frame(res, std::move(frame), budget);
  });
}

}  // namespace ede::view
