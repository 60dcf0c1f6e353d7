// encode_mp4; see ffmpeg.hpp.
#include "ffmpeg.hpp"

#include "number_text.hpp"
#include "spawn.hpp"

namespace ede::render {

Status encode_mp4(const std::string& ffmpeg, const std::string& frames_dir, double fps, const std::string& output) {
  const std::string out = output.starts_with("-") ? "./" + output : output;  // not an option to ffmpeg
  tools::SpawnRequest request;
  request.argv = {ffmpeg, "-nostdin", "-hide_banner", "-loglevel", "error", "-y", "-framerate", tools::brief(fps),
                  "-i", frames_dir + "/frame_%05d.png", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2:color=white", "-c:v",
                  "libx264", "-pix_fmt", "yuv420p", "-movflags", "+faststart", out};
  auto run = tools::run_program(request);
  if (!run) return run.error();
  if (run.value().exit_status != 0)
    return Error{"ffmpeg failed (exit status " + std::to_string(run.value().exit_status) + ") encoding '" + output +
                 "'" + (run.value().err.empty() ? std::string() : ":\n" + run.value().err)};
  return Ok{};
}

}  // namespace ede::render
