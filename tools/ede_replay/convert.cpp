// ede-replay convert: the same log in another format version (ede::Log::convert), e.g. an old version 1
// log as a version 2 one a third of the size, or back. The states read from the copy are bit-identical
// to the original's; `ede-replay diff` of the two says "identical". Exit 0 on success, 1 if the log
// cannot be read or the copy written, 2 for a bad command line.
#include "replay_tool.hpp"

namespace ede::replay_tool {

namespace {

struct ConvertOptions {
  std::string log, output;
  unsigned version = 2;
};

int run_convert(const ConvertOptions& opt) {
  if (opt.version < 1 || opt.version > 3) return usage_error("--format-version must be 1, 2 or 3");
  if (opt.output == opt.log) return usage_error("-o must name a new file, not the log being converted");
  auto log = open_log(opt.log);
  if (!log) return fail(log.error().message);
  if (Status s = log.value().convert(opt.output, opt.version); !s) return fail(s.error().message);
  auto copy = Log::open(opt.output);
  if (!copy) return fail(copy.error().message);
  const LogInfo& a = log.value().info();
  const LogInfo& b = copy.value().info();
  std::printf("%s: format version %u, %llu bytes -> %s: format version %u, %llu bytes (%.2f bytes/event)\n",
              a.path.c_str(), a.format_version, static_cast<unsigned long long>(a.file_size), b.path.c_str(),
              b.format_version, static_cast<unsigned long long>(b.file_size),
              b.events ? double(b.file_size) / double(b.events) : 0.0);
  return 0;
}

}  // namespace

Command add_convert_command(CLI::App& app) {
  auto opt = std::make_shared<ConvertOptions>();
  CLI::App* cmd = app.add_subcommand(
      "convert", "write a complete log again in another format version (2: predicted columns, the default; 1)");
  cmd->add_option("log", opt->log, "event log to convert")->required();
  cmd->add_option("-o,--output", opt->output, "the converted log (a new file)")->required();
  cmd->add_option("--format-version", opt->version, "format version to write: 2 (default), 1, or 3 (a log with thermostat events stays in 3)");
  return [opt] { return run_convert(*opt); };
}

}  // namespace ede::replay_tool
