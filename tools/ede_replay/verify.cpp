// ede-replay verify: re-run the scene a log records and compare every event with the log, bit for bit
// (ede::Log::verify does the work). Exit 0 if identical, 1 at the first difference or for a log that
// cannot be read.
#include "progress.hpp"
#include "replay_tool.hpp"

namespace ede::replay_tool {

namespace {

struct VerifyCliOptions {
  std::string log;
  bool quiet = false;
};

int run_verify(const VerifyCliOptions& opt) {
  auto log = open_log(opt.log);
  if (!log) return fail(log.error().message);
  tools::ProgressReporter progress(!opt.quiet, "ede-replay verify");
  VerifyOptions options;
  options.progress = [&](double fraction, std::uint64_t events) { progress.update(fraction, events, 0); };
  auto report = log.value().verify(options);
  progress.finish();
  if (!report) return fail(report.error().message);
  std::printf("%s", report.value().text.c_str());
  return report.value().identical ? 0 : 1;
}

}  // namespace

Command add_verify_command(CLI::App& app) {
  auto opt = std::make_shared<VerifyCliOptions>();
  CLI::App* cmd = app.add_subcommand("verify",
                                     "re-run the log's scene and compare every event with the log, bit for "
                                     "bit; exit 0 if identical, 1 at the first difference");
  cmd->add_option("log", opt->log, "event log (any file name)")->required();
  cmd->add_flag("-q,--quiet", opt->quiet, "no progress output");
  return [opt] { return run_verify(*opt); };
}

}  // namespace ede::replay_tool
