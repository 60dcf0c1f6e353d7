// parse_command_line; see command_line.hpp.
#include "command_line.hpp"

#include <vector>

#include "ede/ede.hpp"

namespace ede::tools {

void add_version_flags(CLI::App& app, const std::string& tool) {
  const std::string text = tool + ", ede " + version();
  app.set_version_flag("--version", text, "print the version and exit");
  for (CLI::App* sub : app.get_subcommands({})) add_version_flags(*sub, tool + " " + sub->get_name());
}

std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  return std::nullopt;
}

std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv, const std::string& default_subcommand) {
  std::vector<char*> args(argv, argv + argc);
  std::string inserted = default_subcommand;
  if (argc > 1) {
    const std::string first = argv[1];
    bool known = first == "-h" || first == "--help" || first == "--version";
    for (const CLI::App* sub : app.get_subcommands({})) known = known || first == sub->get_name();
    if (!known) args.insert(args.begin() + 1, inserted.data());
  }
  return parse_command_line(app, int(args.size()), args.data());
}

}  // namespace ede::tools
