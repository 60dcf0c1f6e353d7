// Log routes; see log_routes.hpp. Opened logs stay open (at most kOpenLogs, the oldest closed first), each
// with its own mutex: a Log is one thread at a time, and several tabs may scrub the same file. The time
// asked for is read with ede::parse_exact in the log's own scalar type, exactly as `ede-replay --at`
// reads it, so the page shows the very state that command prints. Rejected: one global lock (two tabs on
// two logs would wait for each other) and a copy of the Log per request (reopening costs the index read).
#include "log_routes.hpp"

#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>

#include "ede/ede.hpp"
#include "crater_view.hpp"
#include "frame.hpp"

namespace ede::view {
namespace {

constexpr std::size_t kOpenLogs = 16;
constexpr std::size_t kDefaultMaxDisks = 200000;

struct OpenLog {
  std::mutex mutex;
  std::optional<Log> log;
  std::optional<Reference> reference;
  std::optional<double> pair_share;
  std::optional<std::string> segments;  // segments_field of the log's scene
  std::optional<std::vector<PairSteps>> steps;      // the log's scene's square wells and shoulders
  std::optional<std::optional<CraterBase>> crater;  // crater_base of the log, once looked for
  std::string crater_before_text;                   // the last ?before= asked for, and its base
  std::optional<CraterBase> crater_before;
  std::uint64_t last_use = 0;
};

class LogStore {
 public:
  // The open log for a canonical path, or the error opening it.
  Result<std::shared_ptr<OpenLog>> get(const std::string& path) {
    std::lock_guard lock(mutex_);
    ++clock_;
    if (auto it = logs_.find(path); it != logs_.end()) {
      it->second->last_use = clock_;
      return it->second;
    }
    auto log = Log::open(path);
    if (!log) return log.error();
    if (logs_.size() >= kOpenLogs) {
      auto oldest = logs_.begin();
      for (auto it = logs_.begin(); it != logs_.end(); ++it)
        if (it->second->last_use < oldest->second->last_use) oldest = it;
      logs_.erase(oldest);
    }
    auto entry = std::make_shared<OpenLog>();
    entry->log.emplace(std::move(log).value());
    entry->last_use = clock_;
    logs_[path] = entry;
    return entry;
  }

 private:
  std::mutex mutex_;
  std::uint64_t clock_ = 0;
  std::map<std::string, std::shared_ptr<OpenLog>> logs_;
};

// The log's crater base (crater_view.hpp), looked for once; the caller holds the entry's mutex.
const std::optional<CraterBase>& crater_of(OpenLog& entry) {
  if (!entry.crater) entry.crater = crater_base(*entry.log);
  return *entry.crater;
}

// The steps of the log's scene (none when its scene cannot be read), read once; the caller holds the mutex.
const std::vector<PairSteps>& steps_of(OpenLog& entry) {
  if (!entry.steps) {
    auto scene = entry.log->scene();
    entry.steps = scene ? scene.value().physics.steps : std::vector<PairSteps>{};
  }
  return *entry.steps;
}

nlohmann::json info_json(const std::string& name, const LogInfo& info) {
  return {{"name", name},
          {"scene", info.scene_name},
          {"disks", info.disks},
          {"events", info.events},
          {"start", info.start_time},
          {"end", double(info.end_time)},
          {"lx", info.lx},
          {"ly", info.ly},
          {"periodic", info.boundary == BoundaryKind::Periodic},
          {"species", info.species_names},
          {"scalar", to_string(info.scalar)},
          {"keyframes", info.keyframes},
          {"complete", info.complete},
          {"incomplete_reason", info.incomplete_reason},
          {"gravity", {info.gx, info.gy}}};
}

// The log a request names (?name=), opened; nothing when an error was sent.
std::shared_ptr<OpenLog> find_log(const std::vector<Root>& roots, LogStore& store, const httplib::Request& req,
                                  httplib::Response& res) {
  if (!req.has_param("name")) {
    send_error(res, 400, "missing parameter 'name' (a log under a served folder, as /api/logs lists them)");
    return nullptr;
  }
  const Resolved r = resolve_under(roots, req.get_param_value("name"), ".ede");
  if (r.status != 200) {
    send_error(res, r.status, r.error);
    return nullptr;
  }
  auto log = store.get(r.path.string());
  if (!log) {
    send_error(res, 422, log.error().message);
    return nullptr;
  }
  return log.value();
}

}  // namespace

void add_log_routes(httplib::Server& server, const std::vector<Root>& roots, FrameBudget& budget) {
  auto store = std::make_shared<LogStore>();
  server.Get("/api/logs", [roots](const httplib::Request&, httplib::Response& res) {
    send_json(res, nlohmann::json{{"logs", list_files(roots, ".ede")}}.dump());
  });
  server.Get("/api/log/info", [roots, store](const httplib::Request& req, httplib::Response& res) {
    auto entry = find_log(roots, *store, req, res);
    if (!entry) return;
    std::lock_guard lock(entry->mutex);
    nlohmann::json info = info_json(req.get_param_value("name"), entry->log->info());
    // Whether the page may colour by clusters: "" if so, else why not.
    info["clusters_unavailable"] = clusters_unavailable(bond_radii(steps_of(*entry), entry->log->info().species_names));
    std::string json = info.dump();
    json.pop_back();
    send_json(res, json + crater_info_field(crater_of(*entry)) + "}");
  });
  server.Get("/api/log/frame", [roots, store, &budget](const httplib::Request& req, httplib::Response& res) {
    auto entry = find_log(roots, *store, req, res);
    if (!entry) return;
    const auto request = frame_request_param(req, res, kDefaultMaxDisks);
    if (!request) return;
    if (!req.has_param("t")) return send_error(res, 400, "missing parameter 't' (a time, or 'end')");
    std::lock_guard lock(entry->mutex);
    const Log& log = *entry->log;
    const std::string t_text = req.get_param_value("t");
    Result<State> state = Error{""};
    if (t_text == "end") {
      state = log.state_at_end();
    } else {
      auto t = parse_exact(t_text, log.info().scalar);
      if (!t) return send_error(res, 400, "parameter 't': " + t.error().message);
      state = log.state_at(t.value());
    }
    if (!state) return send_error(res, 400, state.error().message);
    if (!entry->reference) {
      auto first = log.state_at_event(0);
      if (!first) return send_error(res, 422, first.error().message);
      entry->reference = make_reference(first.value(), steps_of(*entry));
    }
    if (const std::string why = colouring_refused(*request, *entry->reference); !why.empty())
      return send_error(res, 400, "parameter 'colour': " + why);
    const State& s = state.value();
    FrameExtras extras;
    // Pair collisions up to t, estimated from the whole log's share of pair events among logged ones
    // (exact at the end; the page marks it as an estimate).
    if (!entry->pair_share) {
      auto counts = log.count_events();
      const double logged = counts ? double(log.info().events) : 0;
      entry->pair_share = logged > 0 ? double(counts.value().of(EventKind::Pair)) / logged : 0.0;
    }
    extras.collisions = *entry->pair_share * double(s.events);
    if (!entry->segments) {
      auto scene = log.scene();
      entry->segments = scene ? segments_field(scene.value()) : std::string();
    }
    extras.json_fields = "\"t_request\":" + nlohmann::json(t_text).dump() + *entry->segments;
    const std::string crater = req.get_param_value("crater");
    if (!(crater.empty() || crater == "0" || crater == "1"))
      return send_error(res, 400, "parameter 'crater' must be 1 or 0, not '" + crater.substr(0, 40) + "'");
    if (crater == "1" && crater_of(*entry)) {
      const std::string before = req.get_param_value("before");
      if (before.empty()) {
        extras.json_fields += crater_field(*crater_of(*entry), s);
      } else {
        if (!entry->crater_before || before != entry->crater_before_text) {
          auto tb = parse_exact(before, log.info().scalar);
          if (!tb) return send_error(res, 400, "parameter 'before': " + tb.error().message);
          auto base = with_before(*crater_of(*entry), log, tb.value());
          if (!base) return send_error(res, 400, "parameter 'before': " + base.error().message);
          entry->crater_before = std::move(base).value();
          entry->crater_before_text = before;
        }
        extras.json_fields += crater_field(*entry->crater_before, s);
      }
    }
    send_frame(res, std::make_shared<const std::string>(pack_frame(s, *entry->reference, extras, *request)), budget);
  });
}

}  // namespace ede::view
