// The bad-input corpus, through every tool: bad scenes (tests/bad_input/scenes/*.toml, each saying in its
// first line "# expect: TEXT" what the error must contain) and bad logs (made here from a good one:
// empty, cut at many points, bit-flipped, wrong magic, a newer version, a scene file). Every run must end
// within its time limit with exit status 0 or 1 (never a crash, a sanitizer abort, a usage error or a
// hang); a refusal names the file and says what is wrong; a log that is only cut short is read as far as
// it goes, with a warning. Under the sanitizer build (scripts/check-sanitizers.sh) any memory error,
// leak or undefined behaviour aborts the tool and fails these tests.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "tool_runner.hpp"

using namespace ede::test;

namespace {

constexpr int kTimeLimit = 60;  // seconds per run; the slowest bad scene (a jammed placement) takes ~2 s

std::string expectation(const std::filesystem::path& scene) {
  std::ifstream in(scene);
  std::string first;
  std::getline(in, first);
  const std::string tag = "# expect: ";
  return first.rfind(tag, 0) == 0 ? first.substr(tag.size()) : "";
}

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void write(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

// What a bad log must produce: a refusal containing `refusal` (Refuse); success with an "incomplete"
// warning (Warn: a killed run); or either, a refusal naming the file by the tools that read the damaged
// record and silence from those that do not (Either: a flipped bit).
struct BadLog {
  enum Mode { Refuse, Warn, Either } mode;
  std::string name, path, refusal;
};

// The end of the header record: 16-byte file header, 56-byte record header, then its payload.
std::size_t header_record_end(const std::string& bytes) {
  std::uint64_t payload = 0;
  for (int k = 0; k < 8; ++k) payload |= std::uint64_t(static_cast<unsigned char>(bytes[16 + 8 + k])) << (8 * k);
  return 16 + 56 + std::size_t(payload);
}

std::vector<BadLog> make_bad_logs() {
  const std::string good = sim_log(source_path("examples/scenes/periodic.toml"),
                                   " --set species.gas.count=60 --set stop.time=8 --set log.chunk_events=200"
                                   " --set log.keyframe_interval=500",
                                   temp_path("bad-good.ede"), "bad-good");
  const std::string bytes = bytes_of(good);
  std::vector<BadLog> logs;
  const auto add = [&](BadLog::Mode mode, const std::string& name, const std::string& content,
                       const std::string& refusal = "") {
    const std::string path = temp_path("bad-" + name + ".ede");
    write(path, content);
    logs.push_back({mode, name, path, refusal});
  };
  add(BadLog::Refuse, "empty", "", "too short");
  add(BadLog::Refuse, "magic", "\x7f" "ELF" + bytes.substr(4), "not an ede event log");
  std::string newer = bytes;
  newer[8] = 4;  // 3 is read (thermostat events)
  add(BadLog::Refuse, "version", newer, "version 4");
  add(BadLog::Refuse, "scene-file", bytes_of(source_path("examples/gas.toml")), "not an ede event log");
  add(BadLog::Refuse, "cut-10", bytes.substr(0, 10), "too short");
  add(BadLog::Refuse, "cut-header", bytes.substr(0, 100), "header record is cut short");
  add(BadLog::Refuse, "cut-first-keyframe", bytes.substr(0, header_record_end(bytes) + 30), "no initial state");
  for (const std::size_t at : {bytes.size() / 3, bytes.size() / 2, bytes.size() - 40})
    add(BadLog::Warn, "cut-" + std::to_string(at), bytes.substr(0, at));  // a killed run
  for (const std::size_t at : {bytes.size() / 4, bytes.size() / 2 + 7, bytes.size() - 100}) {
    std::string flipped = bytes;
    flipped[at] = char(flipped[at] ^ 0x10);
    add(BadLog::Either, "flipped-" + std::to_string(at), flipped);
  }
  return logs;
}

}  // namespace

TEST_CASE("every bad scene is refused by ede-sim with its expected message", "[tool][bad-input]") {
  namespace fs = std::filesystem;
  std::size_t checked = 0;
  for (const auto& entry : fs::directory_iterator(source_path("tests/bad_input/scenes"))) {
    const std::string expected = expectation(entry.path());
    INFO(entry.path().filename().string() << " must say: " << expected);
    REQUIRE_FALSE(expected.empty());
    const ToolRun r = run_tool("ede-sim", "'" + entry.path().string() + "' -q", "bad-scene", kTimeLimit);
    INFO("exit " << r.status << ", stderr: " << r.err);
    CHECK(r.status == 1);
    CHECK(r.err.find(expected) != std::string::npos);
    CHECK(r.err.find(entry.path().filename().string()) != std::string::npos);  // the message names the file
    ++checked;
  }
  CHECK(checked >= 20);
}

TEST_CASE("every log tool refuses bad logs clearly and reads cut ones with a warning", "[tool][bad-input][slow]") {
  const std::vector<std::pair<std::string, std::string>> commands = {
      {"ede-replay", "{} --at end -o /dev/null"},  {"ede-replay", "info {}"},
      {"ede-replay", "events {} --from 0 --to 1"}, {"ede-replay", "verify {}"},
      {"ede-stats", "hist {}"},                    {"ede-stats", "species {}"},
      {"ede-stats", "energy {}"},                  {"ede-stats", "collisions {}"},
      {"ede-stats", "pressure {}"},                {"ede-stats", "impacts {}"},
      {"ede-replay", "events {} --full --to 1"},   {"ede-crater", "{}"},
      {"ede-render", "{} --at end -o /dev/null.png"}};
  for (const BadLog& log : make_bad_logs()) {
    for (const auto& [tool, pattern] : commands) {
      std::string args = pattern;
      args.replace(args.find("{}"), 2, log.path);
      const ToolRun r = run_tool(tool, args, "bad-log", kTimeLimit);
      INFO(log.name << ": " << tool << " " << args << " -> exit " << r.status << "\nstderr: " << r.err);
      REQUIRE((r.status == 0 || r.status == 1));  // not a crash (128 + signal), a usage error (2), a hang (124)
      if (log.mode == BadLog::Refuse) {
        CHECK(r.status == 1);
        CHECK(r.err.find(log.refusal) != std::string::npos);
        CHECK(r.err.find(log.path) != std::string::npos);
      } else if (log.mode == BadLog::Warn) {
        CHECK(r.err.find("incomplete") != std::string::npos);  // every tool says so, then reads what is there
      } else if (r.status == 1) {
        CHECK(r.err.find(log.path) != std::string::npos);
      }
    }
  }
}
