// libFuzzer entry point for harness_columns.hpp (see there for what is checked).
#include "harness_columns.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (!ede::fuzz::fuzz_columns(data, size)) __builtin_trap();
  return 0;
}
