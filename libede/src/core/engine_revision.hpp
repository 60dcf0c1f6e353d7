// The engine's revision: which trajectory this ede computes for a scene (docs/reliability.md, "What is
// promised"). The same build, scene and seed give the same bytes, and GCC and Clang agree; a later ede may
// take another trajectory for the same scene (faster arithmetic, other cells), and then the revision goes
// up by one, in the commit that changes the pinned digest (tests/log/test_log_determinism.cpp) and with a
// line in CHANGELOG.md. Every log header records it in its engine version text ("0.1.0+t1"), so that
// `ede-replay verify` and `diff` can say plainly when they compare runs of different revisions. Logs
// written before revisions were recorded ("0.1.0") are revision 0. A log of any revision decodes exactly
// with every later ede: decoding never depends on the revision (schema/FORMAT.md).
// Rejected: a header field of its own (the run id hashes every header field but the build texts, so an old
// reader would refuse a new log's records).
#pragma once

#include <string>

namespace ede {

// Bumped whenever the same build inputs give another trajectory (see above).
inline constexpr int kTrajectoryRevision = 1;

// The engine version text a log header records: "<version>+t<revision>".
std::string engine_version_text();
// The revision a header's engine version text names (0: recorded before revisions, or not ede's).
int trajectory_revision_of(const std::string& engine_version);
// Empty when a log written by `engine_version` and this ede take the same trajectory; else one plain
// sentence saying they are different revisions and what that means for a comparison.
std::string revision_note(const std::string& engine_version);

}  // namespace ede
