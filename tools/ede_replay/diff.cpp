// ede-replay diff: the first event at which two logs differ, by bisection over keyframes and chunks rather
// than a full scan (ede::Log::diff does the work). Exit 0 if the logs hold the same events, final time and
// status; 1 if they differ or cannot be compared, or if either is damaged (the part after the damage
// cannot be compared, so "identical" would be a claim about what was not read).
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
  if (!report.value().identical) return 1;
  // Identical as far as both logs read is not identical when one of them is damaged: bisection skipped
  // records it found equal by position, not by reading, so every record of both is decoded once (one
  // pass at decompression speed) before the verdict stands.
  for (const Log* log : {&a.value(), &b.value()}) {
    std::string damage = log->info().damaged ? log->info().incomplete_reason : std::string();
    if (damage.empty())
      if (auto counted = log->count_events(); !counted) damage = counted.error().message;
    if (!damage.empty())
      return fail(log->info().path + " is DAMAGED (" + damage +
                  "): the records compared are only those bisection read, so the logs cannot be called identical. "
                  "Fix: compare with an undamaged copy; ede-replay verify tells what is readable.");
  }
  return 0;
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
