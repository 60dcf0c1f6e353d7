// The library's version, for --version and for programs that record which ede they used.
#pragma once

namespace ede {

// "0.1.0": the project version (CMakeLists.txt); logs record it in their header too.
const char* version();

}  // namespace ede
