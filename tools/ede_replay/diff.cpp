// ede-replay diff: the first event at which two logs differ, by bisection over keyframes and chunks rather
// than a full scan (ede::Log::diff does the work). Exit 0 if the logs hold the same events, final time and
// status; 1 if they differ or cannot be compared.
#include "replay_tool.hpp"

namespace ede::replay_tool {

namespace {

struct DiffOptions {
  std::string a, b;
  bool full = false;
};

int run_diff(const DiffOptions& opt) {
  auto a = open_log(opt.a);
  if (!a) return fail(a.error().message);
  auto b = open_log(opt.b);
  if (!b) return fail(b.error().message);
  auto report = a.value().diff(b.value(), opt.full);
  if (!report) return fail(report.error().message);
  std::printf("%s", report.value().text.c_str());
  return report.value().identical ? 0 : 1;
}

}  // namespace

Command add_diff_command(CLI::App& app) {
  auto opt = std::make_shared<DiffOptions>();
  CLI::App* cmd = app.add_subcommand("diff",
                                     "the first event at which two logs differ (by bisection over keyframes "
                                     "and chunks, not a full scan); exit 0 if identical, 1 if they differ");
  cmd->add_option("a", opt->a, "first event log")->required();
  cmd->add_option("b", opt->b, "second event log")->required();
  cmd->add_flag("--full", opt->full,
                "no bisection: compare every chunk from the start (reads both logs whole, "
                "so damage in records bisection skips is found too)");
  return [opt] { return run_diff(*opt); };
}

}  // namespace ede::replay_tool
