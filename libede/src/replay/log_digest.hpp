// A digest of what a log says, independent of how it is stored: XXH3-128 (core/xxh3.hpp) over the scene
// text, the scalar type, the per-disk constants, every event (index, time, kind, disks, post-event
// velocities as raw scalars) and the final state. Two logs with the same digest describe the same run bit
// for bit, whatever compiler wrote them, whatever zstd level compressed them. Tests pin it; ede-replay info
// prints it. The text names its algorithm, "xxh3-128:<32 hex digits>", so a digest noted down is never
// compared with one of another kind (ede printed bare SHA-256 digests, 64 hex digits, before). Digests are computed, never stored in a log: changing the algorithm leaves every log readable.
#pragma once

#include <string>

#include "log/log_reader.hpp"
#include "ede/error.hpp"

namespace ede {

inline constexpr const char* kDigestAlgorithm = "xxh3-128";

Result<std::string> log_content_digest(std::shared_ptr<const LogReader> log);

}  // namespace ede
