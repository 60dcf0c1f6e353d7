// Row files as JSON (see run_row.hpp).
#include "run_row.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <algorithm>
#include <fstream>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

namespace ede::sweep {

std::string row_to_json(const RunRow& row) {
  nlohmann::json j;
  j["index"] = row.index;
  j["name"] = row.name;
  j["overrides"] = row.overrides;
  j["collect"] = row.collect;
  nlohmann::json values = nlohmann::json::array();
  for (double v : row.values) values.push_back(std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr));
  j["values"] = values;
  if (!row.notes.empty()) j["notes"] = row.notes;
  if (!row.measured_with.empty()) j["measured_with"] = row.measured_with;
  j["status"] = row.status;
  j["error"] = row.error;
  j["wall_seconds"] = row.wall_seconds;
  j["log"] = row.log;
  j["digest"] = row.digest;
  j["summary"] = row.summary;
  if (row.reused) j["reused"] = true;  // for rank 0's report; never in a row file (the child writes those)
  return j.dump();
}

Result<RunRow> row_from_json(const std::string& text, const std::string& where) {
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    RunRow row;
    row.index = j.at("index").get<std::size_t>();
    row.name = j.at("name").get<std::string>();
    row.overrides = j.at("overrides").get<std::vector<std::string>>();
    row.collect = j.at("collect").get<std::vector<std::string>>();
    for (const auto& v : j.at("values"))
      row.values.push_back(v.is_null() ? std::numeric_limits<double>::quiet_NaN() : v.get<double>());
    row.notes = j.value("notes", std::vector<std::string>());
    row.measured_with = j.value("measured_with", std::string());
    row.status = j.at("status").get<std::string>();
    row.error = j.at("error").get<std::string>();
    row.wall_seconds = j.at("wall_seconds").get<double>();
    row.log = j.at("log").get<std::string>();
    row.digest = j.at("digest").get<std::string>();
    row.reused = j.value("reused", false);
    row.summary = j.value("summary", std::string());
    return row;
  } catch (const std::exception& e) {
    return Error{where + ": not a sweep row (" + e.what() + "). Fix: delete it; the run is then done again"};
  }
}

Status write_row_file(const std::string& path, const RunRow& row) {
  const std::string tmp = path + ".tmp";
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  out << row_to_json(row) << "\n";
  out.close();
  if (!out) {
    const std::string why = std::strerror(errno);
    std::remove(tmp.c_str());
    return Error{path + ": cannot write the run's row (" + why + ")", ErrorKind::Io};
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) return Error{path + ": cannot rename " + tmp + " to it"};
  return Ok{};
}

Result<RunRow> read_row_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{path + ": no row"};
  std::stringstream s;
  s << in.rdbuf();
  return row_from_json(s.str(), path);
}

std::string summary_to_json(const RunSummary& s) {
  nlohmann::json j;
  j["by_kind"] = std::vector<std::uint64_t>(std::begin(s.counts.by_kind), std::end(s.counts.by_kind));
  j["collisions_per_particle"] = s.collisions_per_particle;
  j["sim_time"] = s.sim_time;
  j["energy_initial"] = s.energy_initial;
  j["energy_final"] = s.energy_final;
  return j.dump();
}

Result<RunSummary> summary_from_json(const std::string& text) {
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    RunSummary s;
    const auto by_kind = j.at("by_kind").get<std::vector<std::uint64_t>>();
    if (by_kind.size() != std::size(s.counts.by_kind)) return Error{"a row's summary counts another set of event kinds"};
    std::copy(by_kind.begin(), by_kind.end(), s.counts.by_kind);
    s.collisions_per_particle = j.at("collisions_per_particle").get<double>();
    s.sim_time = j.at("sim_time").get<double>();
    s.energy_initial = j.at("energy_initial").get<double>();
    s.energy_final = j.at("energy_final").get<double>();
    return s;
  } catch (const std::exception& e) {
    return Error{std::string("a row's summary: ") + e.what()};
  }
}

bool final_status(const std::string& status) {
  return status != "failed" && status != "timeout" && status != "killed" && status != "crashed" &&
         status != "interrupted" && status != "lost";
}

}  // namespace ede::sweep
