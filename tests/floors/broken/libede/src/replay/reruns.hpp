// A file breaking rule 2 of check_floors.cmake, for the test that the check fails (tests/CMakeLists.txt).
#include "engine/engine.hpp"
