#include "core/engine_revision.hpp"

#include "ede/version.hpp"

namespace ede {

std::string engine_version_text() { return std::string(version()) + "+t" + std::to_string(kTrajectoryRevision); }

int trajectory_revision_of(const std::string& engine_version) {
  const std::size_t at = engine_version.rfind("+t");
  if (at == std::string::npos || at + 2 >= engine_version.size()) return 0;
  int r = 0;
  for (std::size_t k = at + 2; k < engine_version.size(); ++k) {
    const char c = engine_version[k];
    if (c < '0' || c > '9' || r > 100000) return 0;
    r = r * 10 + (c - '0');
  }
  return r;
}

std::string revision_note(const std::string& engine_version) {
  const int theirs = trajectory_revision_of(engine_version);
  if (theirs == kTrajectoryRevision) return "";
  const std::string them = theirs == 0 ? "before trajectory revisions were recorded" : "revision " + std::to_string(theirs);
  return "the log was written by ede " + (engine_version.empty() ? std::string("(unknown)") : engine_version) + " (" +
         them + "), this is ede " + engine_version_text() + " (revision " + std::to_string(kTrajectoryRevision) +
         "): a different revision may take another trajectory for the same scene (CHANGELOG.md says which), so a "
         "re-run need not match the log event for event; the log itself still decodes exactly";
}

}  // namespace ede
