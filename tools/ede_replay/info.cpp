// ede-replay info: what a log holds, from its header, its index and the chunks' kind columns alone.
//
// No replay (except for --digest, which reads every event). An incomplete log is said to be so first,
// with the reader's reason, and then summarised as far as it goes: exit 0. A chunk that cannot be read is
// reported after the summary: exit 1.
#include "replay_tool.hpp"

namespace ede::replay_tool {

namespace {

struct InfoOptions {
  std::string log;
  bool scene = false;
  bool digest = false;
};

void line(const char* label, const std::string& text) { std::printf("%-17s%s\n", label, text.c_str()); }

std::string number(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

std::string species_line(const LogInfo& i) {
  std::string text;
  for (std::size_t k = 0; k < i.species_names.size(); ++k)
    text += (k ? ", " : "") + i.species_names[k] + " " + std::to_string(i.species_counts[k]);
  return text;
}

void print_header(const LogInfo& i) {
  line("scene", i.scene_name);
  line("seed", std::to_string(i.seed));
  line("engine", "ede " + i.engine_version + ", " + i.compiler);
  line("flags", i.compile_flags);
  line("scalar", to_string(i.scalar));
  line("disks", std::to_string(i.disks));
  line("box", number(i.lx) + " x " + number(i.ly) + ", " + (i.lees_edwards ? "lees-edwards" : to_string(i.boundary)));
  line("species", species_line(i));
  line("TC model", i.tc_model ? "yes (keyframes keep the TC times)" : "no");
}

void print_events(const Log& log, std::string& problem) {
  auto counts = log.count_events();
  const std::string total = std::to_string(log.info().events);
  if (!counts) {
    problem = counts.error().message;
    line("events", total + " (counting them by kind failed: " + problem + ")");
    return;
  }
  const EventCounts& c = counts.value();
  line("events", total + ": pair " + std::to_string(c.of(EventKind::Pair)) + ", wall " +
                     std::to_string(c.of(EventKind::Wall)) + ", wrap " + std::to_string(c.of(EventKind::Wrap)) +
                     ", action " + std::to_string(c.of(EventKind::Action)) +
                     (c.of(EventKind::Segment) ? ", segment " + std::to_string(c.of(EventKind::Segment)) : "") +
                     (c.of(EventKind::Step) ? ", step " + std::to_string(c.of(EventKind::Step)) : "") +
                     (c.of(EventKind::Thermostat) ? ", thermostat " + std::to_string(c.of(EventKind::Thermostat)) : "") +
                     (c.of(EventKind::Shear) ? ", shear " + std::to_string(c.of(EventKind::Shear)) : ""));
}

void print_records(const Log& log) {
  const LogInfo& i = log.info();
  const std::string end = i.complete ? exact(log, i.end_time)
                                     : exact(log, i.end_time) + " (the last logged event: the log is incomplete)";
  std::string span = number(i.start_time) + " to " + end;
  if (i.chunks) span += "; events from t = " + number(i.first_event_time) + " to " + number(i.last_event_time);
  line("time", span);
  line("chunks", std::to_string(i.chunks) + " (up to " + std::to_string(i.chunk_events) + " events each)");
  line("keyframes", std::to_string(i.keyframes) + ", " + std::to_string(i.resumable_keyframes) +
                        " resumable (one every " + std::to_string(i.keyframe_interval) +
                        " events, and at engine rebuilds every " + std::to_string(i.rebuild_interval) +
                        " engine events)");
  const double per_event = i.events ? double(i.file_size) / double(i.events) : 0.0;
  line("size", std::to_string(i.file_size) + " bytes (" + number(double(i.file_size) / 1048576) + " MiB), " +
                   number(per_event) + " bytes/event");
}

int run_info(const InfoOptions& opt) {
  auto opened = open_log(opt.log);
  if (!opened) return fail(opened.error().message);
  const Log& log = opened.value();
  const LogInfo& i = log.info();
  line("file", i.path + " (format version " + std::to_string(i.format_version) + ")");
  if (i.complete)
    line("log", "complete; the run ended: " + i.final_status);
  else
    line("log", std::string(i.damaged ? "DAMAGED, read up to the damage: " : "incomplete: ") + i.incomplete_reason);
  print_header(i);
  std::string count_problem, digest_problem;
  print_events(log, count_problem);
  print_records(log);
  if (opt.digest) {
    if (auto digest = log.content_digest())
      line("content digest", digest.value());
    else
      digest_problem = digest.error().message;
  }
  if (opt.scene) std::printf("\n# effective scene (%s)\n%s", i.scene_name.c_str(), i.scene_text.c_str());
  std::fflush(stdout);
  if (!count_problem.empty()) return fail(count_problem);
  if (!digest_problem.empty()) return fail(digest_problem);
  return 0;
}

}  // namespace

Command add_info_command(CLI::App& app) {
  auto opt = std::make_shared<InfoOptions>();
  CLI::App* cmd = app.add_subcommand("info", "summarise a log: header, event counts, records, size, completeness");
  cmd->add_option("log", opt->log, "event log (any file name)")->required();
  cmd->add_flag("--scene", opt->scene, "also print the effective scene (TOML, after --set overrides)");
  cmd->add_flag("--digest", opt->digest,
                "also print the content digest (of the scene, every event and the final state: equal for logs "
                "of the same run, however stored); replays the whole log");
  return [opt] { return run_info(*opt); };
}

}  // namespace ede::replay_tool
