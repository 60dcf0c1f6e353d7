// libFuzzer entry point for harness_engine.hpp (see there for what is checked).
#include "harness_engine.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (!ede::fuzz::fuzz_engine(data, size)) __builtin_trap();
  return 0;
}
