#include "ede/version.hpp"
// build_info.hpp: the compiler from its predefined macros, the flags from CMake (EDE_BUILD_FLAGS).
#include "core/build_info.hpp"

#ifndef EDE_BUILD_FLAGS
#define EDE_BUILD_FLAGS "unknown"
#endif

namespace ede {

std::string build_compiler() {
#if defined(__clang__)
  return std::string("Clang ") + __clang_version__;
#elif defined(__GNUC__)
  return std::string("GCC ") + __VERSION__;
#else
  return "unknown compiler";
#endif
}

std::string build_flags() { return EDE_BUILD_FLAGS; }

}  // namespace ede

namespace ede {

const char* version() { return EDE_VERSION; }

}  // namespace ede
