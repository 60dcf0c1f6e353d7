// encode_movie and its command line; see ffmpeg.hpp.
#include "ffmpeg.hpp"

#include "ede/number_text.hpp"
#include "render.hpp"
#include "process.hpp"

namespace ede::render {

bool is_encoded_movie(const std::string& output) { return ends_with(output, ".mp4") || ends_with(output, ".gif"); }

std::vector<std::string> ffmpeg_arguments(const std::string& ffmpeg, const std::string& frames_dir, double fps,
                                          const std::string& output) {
  const std::string out = output.starts_with("-") ? "./" + output : output;  // not an option to ffmpeg
  std::vector<std::string> argv = {ffmpeg, "-nostdin", "-hide_banner", "-loglevel", "error", "-y", "-framerate",
                                   brief(fps), "-i", frames_dir + "/frame_%05d.png"};
  if (ends_with(output, ".gif")) {
    argv.insert(argv.end(), {"-vf", "split[a][b];[a]palettegen=stats_mode=full[p];[b][p]paletteuse=dither=none",
                             "-loop", "0", out});
  } else {
    argv.insert(argv.end(), {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2:color=white", "-c:v", "libx264", "-pix_fmt",
                             "yuv420p", "-movflags", "+faststart", out});
  }
  return argv;
}

Status encode_movie(const std::string& ffmpeg, const std::string& frames_dir, double fps, const std::string& output) {
  tools::SpawnRequest request;
  request.argv = ffmpeg_arguments(ffmpeg, frames_dir, fps, output);
  auto run = tools::run_program(request);
  if (!run) return run.error();
  if (run.value().exit_status != 0)
    return Error{"ffmpeg failed (exit status " + std::to_string(run.value().exit_status) + ") encoding '" + output +
                 "'" + (run.value().err.empty() ? std::string() : ":\n" + run.value().err)};
  return Ok{};
}

std::string shell_command(const std::vector<std::string>& argv) {
  std::string line;
  for (const std::string& a : argv) {
    if (!line.empty()) line += ' ';
    const bool plain = !a.empty() && a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                         "0123456789_-+./=:,@%") == std::string::npos;
    if (plain) {
      line += a;
      continue;
    }
    line += '\'';
    for (char c : a) line += c == '\'' ? std::string("'\\''") : std::string(1, c);
    line += '\'';
  }
  return line;
}

}  // namespace ede::render
