// Checks a tool makes before it writes anything: no output is one of its inputs (or another output), and
// nothing it reads is a device, a directory or some other file it cannot sensibly read.
//
// Sameness is by device and inode (stat), not by the path string: `-o ./scene.toml`, a symlink or a hard
// link to the scene, or `../dir/scene.toml` all name the scene, and all are refused before the run
// starts, so no input is ever replaced. An output that does not exist yet cannot be an input. Rejected:
// comparing paths (fooled by every spelling above) and relying on the temporary-then-rename of outputs
// (the input would still be replaced at the end, after the run). The tools that read logs note them as
// inputs when they open them; every output is checked against those notes before it is put in place.
#pragma once

#include <string>
#include <vector>

#include "ede/error.hpp"

namespace ede::tools {

struct NamedPath {
  std::string what;  // how the command line named it: "the scene", "-o", "--final-state", "LOG 2"
  std::string path;  // "" = not given (skipped)
};

// Fails when an output is the same file as an input or as another output; the message names both and the
// fix. Call before any work is done.
Status check_outputs_distinct(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs);

// The inputs of this process, noted as they are opened (open_log_warning notes every log a tool reads), so
// that every output path (Output, commit_temporary) can refuse to replace one, whichever tool and option
// named it.
// A log noted as input is also held open with a shared lock (flock) for the life of the process, so an
// ede-sim told to write over it meanwhile is refused (the log writer's exclusive lock cannot be taken);
// a log being written (exclusively locked) is still read, without the shared lock.
void note_input(const std::string& what, const std::string& path);
Status check_not_an_input(const std::string& output);

}  // namespace ede::tools
