// ede-replay info: what a log holds, from its header, its index and the chunks' kind columns alone.
//
// No replay (except for --digest, which reads every event): the event counts come from count_logged_kinds
// (one byte per event), the time span and the records from the index (or, for a log whose run was killed,
// from the reader's scan of its records).
// An incomplete log is said to be so first, with the reader's reason, and then summarised as far as it
// goes: exit 0. A chunk that cannot be read is reported after the summary: exit 1.
#include <memory>
#include <string>
#include <vector>

#include "replay/log_digest.hpp"
#include "log/log_stats.hpp"
#include "replay_tool.hpp"
#include "log/scalar_bytes.hpp"

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

std::string species_line(const LogHeaderInfo& h) {
  std::vector<std::uint64_t> count(h.species_names.size(), 0);
  for (const std::uint32_t s : h.species) ++count[s];  // the reader checked every index
  std::string text;
  for (std::size_t k = 0; k < count.size(); ++k)
    text += (k ? ", " : "") + h.species_names[k] + " " + std::to_string(count[k]);
  return text;
}

// The time the run reached, exactly (complete logs: the index's); for a log cut short, the time of its
// last logged event, as the record headers give it (a double).
std::string final_time_text(const LogReader& log) {
  if (!log.complete()) {
    const double last = log.chunks().empty() ? log.keyframes().back().time_last : log.chunks().back().time_last;
    return exact(last) + " (the last logged event: the log is incomplete)";
  }
  return tools::with_scalar(log.header().scalar,
                            [&]<class T>() { return exact(scalar_from_bytes<T>(log.final_time_bytes().data())); });
}

void print_header(const LogReader& log) {
  const LogHeaderInfo& h = log.header();
  line("scene", h.scene_name);
  line("seed", std::to_string(h.seed));
  line("engine", "ede " + h.engine_version + ", " + h.compiler);
  line("flags", h.compile_flags);
  line("scalar", to_string(h.scalar));
  line("disks", std::to_string(h.disks));
  line("box", number(h.lx) + " x " + number(h.ly) + ", " + to_string(h.boundary));
  line("species", species_line(h));
  line("TC model", h.tc_model ? "yes (keyframes keep the TC times)" : "no");
}

void print_events(const LogReader& log, std::string& problem) {
  auto counts = count_logged_kinds(log);
  const std::string total = std::to_string(log.total_events());
  if (!counts) {
    problem = counts.error().message;
    line("events", total + " (counting them by kind failed: " + problem + ")");
    return;
  }
  const LogKindCounts& c = counts.value();
  line("events", total + ": pair " + std::to_string(c.of(EventKind::Pair)) + ", wall " +
                     std::to_string(c.of(EventKind::Wall)) + ", wrap " + std::to_string(c.of(EventKind::Wrap)) +
                     ", action " + std::to_string(c.of(EventKind::Action)));
}

void print_records(const LogReader& log, const std::string& final_time) {
  const LogHeaderInfo& h = log.header();
  const auto& chunks = log.chunks();
  const auto& kfs = log.keyframes();
  std::string span = number(kfs.front().time_first) + " to " + final_time;
  if (!chunks.empty())
    span += "; events from t = " + number(chunks.front().time_first) + " to " + number(chunks.back().time_last);
  line("time", span);
  line("chunks", std::to_string(chunks.size()) + " (up to " + std::to_string(h.chunk_events) + " events each)");
  std::size_t resumable = 0;
  for (const LogRecordRef& k : kfs) resumable += k.resumable ? 1 : 0;
  line("keyframes", std::to_string(kfs.size()) + ", " + std::to_string(resumable) + " resumable (one every " +
                        std::to_string(h.keyframe_interval) + " events, and at engine rebuilds every " +
                        std::to_string(h.rebuild_interval) + " engine events)");
  const double per_event = log.total_events() ? double(log.file_size()) / double(log.total_events()) : 0.0;
  line("size", std::to_string(log.file_size()) + " bytes (" + number(double(log.file_size()) / 1048576) + " MiB), " +
                   number(per_event) + " bytes/event");
}

int run_info(const InfoOptions& opt) {
  auto opened = open_log(opt.log);
  if (!opened) return fail(opened.error().message);
  const std::shared_ptr<LogReader>& log = opened.value();
  line("file", log->path() + " (format version " + std::to_string(log->header().format_version) + ")");
  if (log->complete())
    line("log", "complete; the run ended: " + log->final_status());
  else
    line("log", std::string(log->damaged() ? "DAMAGED, read up to the damage: " : "incomplete: ") +
                    log->incomplete_reason());
  print_header(*log);
  std::string count_problem;
  print_events(*log, count_problem);
  print_records(*log, final_time_text(*log));
  std::string digest_problem;
  if (opt.digest) {
    auto digest = log_content_digest(log);
    if (digest)
      line("content digest", "sha256 " + digest.value());
    else
      digest_problem = digest.error().message;
  }
  if (opt.scene)
    std::printf("\n# effective scene (%s)\n%s", log->header().scene_name.c_str(), log->header().scene_text.c_str());
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
                "also print the content digest (SHA-256 of the scene, every event and the "
                "final state: equal for logs of the same run, however stored); replays "
                "the whole log");
  return [opt] { return run_info(*opt); };
}

}  // namespace ede::replay_tool
