// What ede-bench's commands share; see commands.hpp.
#include <string>

#include "commands.hpp"
#include "ede/scene.hpp"
#include "output_file.hpp"
#include "report_error.hpp"

namespace ede::bench {

void add_set_option(CLI::App* app, std::vector<std::string>& overrides) {
  app->add_option("--set", overrides,
                  "override a value of every scene, checked like the file's own, e.g. --set stop.events=100000 "
                  "(repeatable)");
}

bool sets_key(const std::vector<std::string>& overrides, const std::string& key) {
  for (const std::string& o : overrides) {
    const auto eq = o.find('=');
    std::string k = o.substr(0, eq);
    k.erase(0, k.find_first_not_of(" \t"));
    k.erase(k.find_last_not_of(" \t") + 1);
    if (k == key) return true;
  }
  return false;
}

bool check_scenes(const std::vector<std::string>& scenes, const std::vector<std::string>& overrides) {
  std::vector<Override> all;
  for (const std::string& o : overrides) all.push_back({o});
  for (const std::string& path : scenes)
    if (auto scene = load_scene_file(path, all); !scene) return fail(scene.error().message), false;
  return true;
}

int fail(const std::string& message) {
  tools::report_error("ede-bench", message);
  return 1;
}

bool write_file(const std::string& path, const std::string& text) {
  tools::Output out(path);
  if (!out.error().empty()) return fail(out.error()), false;
  out.write(text);
  if (Status s = out.close(); !s) return fail(s.error().message), false;
  return true;
}

}  // namespace ede::bench
