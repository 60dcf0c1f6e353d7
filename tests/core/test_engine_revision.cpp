// The engine revision recorded in log headers (core/engine_revision.hpp): parsed back from the engine
// version text, and the plain sentence verify and diff add when two revisions are compared.
#include <catch2/catch.hpp>

#include "core/engine_revision.hpp"
#include "ede/version.hpp"

using namespace ede;

TEST_CASE("the engine version text names the trajectory revision, and reads back", "[core][revision]") {
  CHECK(engine_version_text() == std::string(version()) + "+t" + std::to_string(kTrajectoryRevision));
  CHECK(trajectory_revision_of(engine_version_text()) == kTrajectoryRevision);
  CHECK(trajectory_revision_of("0.1.0") == 0);      // written before revisions were recorded
  CHECK(trajectory_revision_of("0.3.2+t17") == 17);
  CHECK(trajectory_revision_of("0.1.0+t") == 0);    // malformed: not a revision
  CHECK(trajectory_revision_of("0.1.0+tx1") == 0);
  CHECK(trajectory_revision_of("") == 0);
}

TEST_CASE("comparing with a log of another revision says so plainly", "[core][revision]") {
  CHECK(revision_note(engine_version_text()).empty());
  const std::string old = revision_note("0.1.0");
  CHECK_THAT(old, Catch::Contains("before trajectory revisions were recorded"));
  CHECK_THAT(old, Catch::Contains("another trajectory"));
  CHECK_THAT(old, Catch::Contains("still decodes exactly"));
  CHECK_THAT(revision_note("9.9.9+t999"), Catch::Contains("revision 999"));
}
