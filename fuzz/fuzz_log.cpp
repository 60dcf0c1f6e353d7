// libFuzzer entry point for harness_log.hpp (see there for what is checked).
#include "harness_log.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (!ede::fuzz::fuzz_log(data, size)) __builtin_trap();
  return 0;
}
