// Old logs decode forever (issue 33; schema/FORMAT.md, "Versioning and the promise"): the golden logs of
// every format version, committed with the states and content digest they decoded to when they were
// written (tests/log/golden/ for version 2, made by make-golden.sh; tests/log/fixtures/ for version 1,
// written by the last ede that wrote it), are decoded by today's reader and by the reference reader
// (reference_reader.hpp, written from FORMAT.md alone) and compared exactly:
//   - the content digest (every event and the final state),
//   - the state at the end, after the middle event (a chunk boundary) and at the middle time, value for
//     value (the expected CSVs hold each number with the digits that read back to it exactly in the log's
//     scalar type; -0 and +0 are told apart),
//   - the reference reader's records after every chunk against today's replay, bit for bit.
// If this fails, today's ede decodes an old log differently: the change is a bug, or it needed a new
// format version with the old one's decoding kept. Never regenerate a golden log to make this pass.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "ede/ede.hpp"
#include "reference_compare.hpp"

using namespace ede;
using namespace ede::test;

namespace {

struct Expected {
  std::string digest;
  std::uint64_t event = 0;
  std::string time;
};

Expected read_expect(const std::filesystem::path& path) {
  std::ifstream in(path);
  Expected e;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "digest") words >> e.digest;
    if (key == "event") words >> e.event;
    if (key == "time") words >> e.time;
  }
  return e;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  std::string field;
  while (std::getline(s, field, ',')) out.push_back(field);
  return out;
}

// The column of a state the CSV names.
const Column* column_of(const State& s, const std::string& name) {
  static const std::map<std::string, Column State::*> columns = {
      {"x", &State::x},       {"y", &State::y},           {"vx", &State::vx},        {"vy", &State::vy},
      {"radius", &State::radius}, {"mass", &State::mass}, {"omega", &State::omega}, {"inertia", &State::inertia}};
  const auto it = columns.find(name);
  return it == columns.end() ? nullptr : &(s.*(it->second));
}

bool same_value(long double a, long double b) { return a == b && std::signbit(a) == std::signbit(b); }

// Every number of the expected CSV against the state, exactly in the log's scalar type.
void compare_state(const State& state, const std::filesystem::path& csv) {
  INFO(csv.string());
  std::ifstream in(csv);
  std::string line;
  REQUIRE(std::getline(in, line));
  const std::vector<std::string> header = split(line);
  std::size_t rows = 0, values = 0;
  while (std::getline(in, line)) {
    const std::vector<std::string> fields = split(line);
    REQUIRE(fields.size() == header.size());
    const std::size_t id = std::stoul(fields[0]);
    REQUIRE(id < state.size());
    CHECK(state.species_names[std::size_t(state.species[id])] == fields[1]);
    for (std::size_t c = 2; c < fields.size(); ++c) {
      const Column* column = column_of(state, header[c]);
      REQUIRE(column != nullptr);
      REQUIRE(column->size() == state.size());
      const auto expected = parse_exact(fields[c], state.scalar);
      REQUIRE(expected.ok());
      INFO("disk " << id << ", " << header[c] << ": expected " << fields[c]);
      CHECK(same_value(column->exact(id), expected.value()));
      ++values;
    }
    ++rows;
  }
  CHECK(rows == state.size());
  CHECK(values >= 6 * rows);
}

std::uint64_t compare_any_with_reference(const std::string& path) {
  switch (open_log(path)->header().scalar) {
    case ScalarKind::Float: return compare_with_reference<float>(path);
    case ScalarKind::LongDouble: return compare_with_reference<long double>(path);
    default: return compare_with_reference<double>(path);
  }
}

void check_golden(const std::filesystem::path& log_path, std::uint32_t format_version) {
  INFO(log_path.string());
  const std::filesystem::path base = log_path.parent_path() / log_path.stem();
  const Expected e = read_expect(base.string() + ".expect");
  REQUIRE(!e.digest.empty());
  auto log = Log::open(log_path.string());
  REQUIRE(log.ok());
  CHECK(log.value().info().format_version == format_version);
  const auto digest = log.value().content_digest();
  REQUIRE(digest.ok());
  CHECK(digest.value() == e.digest);

  const auto end = log.value().state_at_end();
  REQUIRE(end.ok());
  compare_state(end.value(), base.string() + ".end.csv");
  const auto at_event = log.value().state_at_event(e.event);
  REQUIRE(at_event.ok());
  compare_state(at_event.value(), base.string() + ".event.csv");
  const auto time = parse_exact(e.time, log.value().info().scalar);
  REQUIRE(time.ok());
  const auto at_time = log.value().state_at(time.value());
  REQUIRE(at_time.ok());
  compare_state(at_time.value(), base.string() + ".time.csv");

  CHECK(compare_any_with_reference(log_path.string()) == open_log(log_path.string())->total_events());
}

std::vector<std::filesystem::path> logs_in(const std::string& folder) {
  std::vector<std::filesystem::path> out;
  for (const auto& f : std::filesystem::directory_iterator(std::string(EDE_SOURCE_DIR) + "/" + folder))
    if (f.path().extension() == ".ede") out.push_back(f.path());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_CASE("the golden logs of format versions 2 and 3 decode to the states and digests they were written with", "[log][golden]") {
  const auto logs = logs_in("tests/log/golden");
  REQUIRE(logs.size() >= 15);  // periodic, walls + TC, gravity, segments, rough, mixture, polydisperse, float,
                               // long double, time reversal, scheduled actions; version 3: a square well and
                               // the thermostat (periodic; walls in float), a Lees-Edwards box
  // The version is the file name's prefix: v2-..., v3-... (version 3: step, thermostat and shear events,
  // FORMAT.md).
  std::size_t v3 = 0;
  for (const auto& path : logs) {
    const bool third = path.filename().string().rfind("v3-", 0) == 0;
    v3 += third;
    check_golden(path, third ? 3 : 2);
  }
  CHECK(v3 >= 4);
}

TEST_CASE("the version 1 fixtures decode to the states and digests recorded for them", "[log][golden]") {
  const auto logs = logs_in("tests/log/fixtures");
  REQUIRE(logs.size() >= 3);
  for (const auto& path : logs) check_golden(path, 1);
}

TEST_CASE("every golden log has its scene, its expected states and several chunks and keyframes", "[log][golden]") {
  for (const auto& path : logs_in("tests/log/golden")) {
    INFO(path.string());
    const std::filesystem::path base = path.parent_path() / path.stem();
    for (const char* suffix : {".toml", ".expect", ".end.csv", ".event.csv", ".time.csv"})
      CHECK(std::filesystem::exists(base.string() + suffix));
    auto reader = open_log(path.string());
    CHECK(reader->complete());
    CHECK(reader->chunks().size() >= 4);
    CHECK(reader->keyframes().size() >= 2);
  }
}
