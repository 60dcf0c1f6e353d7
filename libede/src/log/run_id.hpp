// The run id: which run a log's records belong to, so that records of one run spliced behind another
// run's header (every checksum valid) are refused instead of replayed as if they were this run's.
//
// The id is a 32-bit digest (the first 32 bits of XXH3-128) of the header's canonical Cap'n Proto encoding with the build's fields
// (engine version, compiler, flags) and the id itself cleared: the same scene, seed and settings give the
// same id under GCC and Clang, as they give the same events. The header stores it and every chunk and
// keyframe repeats it; readers compare each record's id with the header's. 0 means "not recorded" (logs
// written before ids existed) and disables the check. Rejected: a random id per run (logs would no longer
// be byte-identical run to run), a digest of the previous record (chained digests would make a resumed
// run's records depend on where it was cut) and 64 bits: a 32-bit field fits the spare half-word the Chunk
// and Keyframe structs already had, so format version 1's records (id 0) keep their bytes, and an
// accidental splice passes unnoticed once in 4·10^9.
#pragma once

#include <cstdint>
#include <string>

#include "ede/error.hpp"
#include "ede_log.capnp.h"

namespace ede {

class LogReader;

// Never 0 (0 is "not recorded").
std::uint32_t run_id_of(logschema::Header::Reader header);
// The same from a header whose engine version, compiler and flags are already empty and whose run id is 0
// (the log writer builds such a message for it: no copy of a header that is tens of MB at large N).
std::uint32_t run_id_of_cleared(logschema::Header::Reader cleared);

// Ok if the record's id matches the log's header (or the header records none); else an error naming the
// file, the record and what to do. `what`: "chunk" or "keyframe".
Status check_run_id(const LogReader& log, std::uint32_t record_id, std::uint64_t offset, const char* what);

}  // namespace ede
