// A file breaking rule 3 of check_floors.cmake, for the test that the check fails (tests/CMakeLists.txt).
#include "core/rng.hpp"
