// libFuzzer entry point for harness_scene.hpp (see there for what is checked).
#include "harness_scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (!ede::fuzz::fuzz_scene(data, size)) __builtin_trap();
  return 0;
}
