// The fuzz harnesses (fuzz/harness_*.hpp) on every committed input: the seed corpora and the inputs that
// once crashed a fuzzer (tests/fuzz_regressions/<target>-*). Every build runs them, not only fuzz builds,
// so a regression of a fixed crash fails the ordinary test suite.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "harness_columns.hpp"
#include "harness_engine.hpp"
#include "harness_log.hpp"
#include "harness_queue.hpp"
#include "harness_scene.hpp"

namespace {

using Harness = bool (*)(const std::uint8_t*, std::size_t);

std::vector<std::filesystem::path> inputs(const std::string& target) {
  namespace fs = std::filesystem;
  std::vector<fs::path> out;
  const fs::path corpus = fs::path(EDE_SOURCE_DIR) / "fuzz" / "corpus" / target;
  if (fs::exists(corpus))
    for (const auto& e : fs::directory_iterator(corpus)) out.push_back(e.path());
  for (const auto& e : fs::directory_iterator(fs::path(EDE_SOURCE_DIR) / "tests" / "fuzz_regressions"))
    if (e.path().filename().string().rfind(target + "-", 0) == 0) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

void run_all(const std::string& target, Harness harness) {
  const auto files = inputs(target);
  REQUIRE_FALSE(files.empty());
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), {});
    INFO(f.string());
    CHECK(harness(bytes.data(), bytes.size()));
  }
}

}  // namespace

TEST_CASE("fuzz harness inputs: scene parser", "[fuzz]") { run_all("scene", ede::fuzz::fuzz_scene); }
TEST_CASE("fuzz harness inputs: log reader", "[fuzz]") { run_all("log", ede::fuzz::fuzz_log); }
TEST_CASE("fuzz harness inputs: chunk columns", "[fuzz]") { run_all("columns", ede::fuzz::fuzz_columns); }
TEST_CASE("fuzz harness inputs: event queue", "[fuzz]") { run_all("queue", ede::fuzz::fuzz_queue); }
TEST_CASE("fuzz harness inputs: engine invariants", "[fuzz]") { run_all("engine", ede::fuzz::fuzz_engine); }
