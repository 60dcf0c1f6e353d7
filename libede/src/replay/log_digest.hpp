// A digest of what a log says, independent of how it is stored: SHA-256 over the scene text, the scalar
// type, the per-disk constants, every event (index, time, kind, disks, post-event velocities as raw
// scalars) and the final state. Two logs with the same digest describe the same run bit for bit, whatever
// compiler wrote them, whatever zstd level compressed them. Tests pin it; ede-replay info prints it.
#pragma once

#include <string>

#include "log/log_reader.hpp"
#include "ede/error.hpp"

namespace ede {

Result<std::string> log_content_digest(std::shared_ptr<const LogReader> log);

}  // namespace ede
