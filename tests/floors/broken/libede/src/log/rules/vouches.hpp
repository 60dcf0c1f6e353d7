// A file breaking rule 2 of check_floors.cmake (log/ includes nothing of the engine), for the test that
// the check fails (tests/CMakeLists.txt).
#include "engine/collide.hpp"
