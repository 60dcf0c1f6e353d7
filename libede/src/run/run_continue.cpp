// continuation_scene (ede/simulation.hpp): a finished run's scene made to start from its state.
// The scene text is edited as TOML (scene/scene_start.hpp) and loaded again like any scene, so --set
// overrides on it are checked exactly as on a file. Rejected: a Scene edited as a struct, whose source_text
// (what the new log records) would no longer say what was run.
#include <filesystem>

#include "ede/log.hpp"
#include "ede/simulation.hpp"
#include "scene/scene_start.hpp"

namespace ede {

Result<Scene> continuation_scene(const std::string& log_path, std::optional<double> at,
                                 const std::vector<Override>& overrides) {
  auto log = Log::open(log_path);
  if (!log) return log.error();
  const LogInfo& info = log.value().info();
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(log_path, ec);
  const std::string from = ec ? log_path : absolute.lexically_normal().string();
  auto text = continuation_scene_text(info.scene_text, info.scene_name, from, at);
  if (!text) return text.error();
  return parse_scene_text(text.value(), "<continuation of " + log_path + ">", overrides);
}

}  // namespace ede
