// Writing runs.csv and points.csv (see results_table.hpp).
#include "results_table.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>

#include "ede/number_text.hpp"

namespace ede::sweep {

namespace {

std::string cell(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return out + "\"";
}

Status write_file(const std::string& path, const std::string& text) {
  // A temporary file renamed into place: a failed write (a full disk) leaves the last complete table.
  const std::string tmp = path + ".tmp";
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) {
    const std::string why = std::strerror(errno);
    std::remove(tmp.c_str());
    return Error{path + ": cannot write the table (" + why + ")", ErrorKind::Io};
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) return Error{path + ": cannot rename " + tmp + " to it"};
  return Ok{};
}

std::string runs_csv(const Sweep& s, const std::vector<RunRow>& rows, bool timing) {
  std::string t = "run,name";
  for (const std::string& c : parameter_columns(s.spec)) t += "," + cell(c);
  t += ",seed";
  for (const std::string& q : s.spec.collect) t += "," + cell(q);
  t += ",status,error,log,digest";
  t += timing ? ",wall_seconds\n" : "\n";
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const PlannedRun& r = s.runs[k];
    const RunRow& row = rows[k];
    t += std::to_string(k) + "," + r.name;
    for (const std::string& c : r.columns) t += "," + cell(c);
    t += "," + (r.seed ? std::to_string(*r.seed) : std::string());
    for (double v : row.values) t += "," + exact_cell(v);
    t += "," + cell(row.status) + "," + cell(row.error) + "," + cell(row.log) + "," + row.digest;
    t += timing ? "," + brief(row.wall_seconds, 4) + "\n" : "\n";
  }
  return t;
}

std::string points_csv(const Sweep& s, const std::vector<RunRow>& rows) {
  std::string t = "point";
  for (const std::string& c : parameter_columns(s.spec)) t += "," + cell(c);
  t += ",runs,ok";
  for (const std::string& q : s.spec.collect) t += "," + cell(q + "_mean") + "," + cell(q + "_error");
  t += "\n";
  std::size_t k = 0;
  while (k < rows.size()) {
    const std::size_t point = s.runs[k].point;
    std::size_t end = k;
    while (end < rows.size() && s.runs[end].point == point) ++end;
    std::size_t ok = 0;
    std::vector<std::vector<double>> per_quantity(s.spec.collect.size());
    for (std::size_t j = k; j < end; ++j) {
      if (rows[j].status != "ok") continue;
      ++ok;
      for (std::size_t q = 0; q < per_quantity.size(); ++q)
        if (std::isfinite(rows[j].values[q])) per_quantity[q].push_back(rows[j].values[q]);
    }
    t += std::to_string(point);
    for (const std::string& c : s.runs[k].columns) t += "," + cell(c);
    t += "," + std::to_string(end - k) + "," + std::to_string(ok);
    for (const auto& values : per_quantity) {
      const MeanAndError m = mean_and_error(values);
      t += "," + (m.n ? exact_cell(m.mean) : std::string()) + "," + (m.n > 1 ? exact_cell(m.error) : std::string());
    }
    t += "\n";
    k = end;
  }
  return t;
}

}  // namespace

Status write_tables(const Sweep& s, const std::vector<RunRow>& rows, bool timing) {
  if (Status w = write_file(s.results + "/runs.csv", runs_csv(s, rows, timing)); !w) return w;
  return write_file(s.results + "/points.csv", points_csv(s, rows));
}

std::string rows_summary(const std::vector<RunRow>& rows) {
  std::map<std::string, std::size_t> by_status;
  std::size_t reused = 0;
  for (const RunRow& r : rows) {
    ++by_status[r.status];
    reused += r.reused ? 1 : 0;
  }
  std::string t = std::to_string(rows.size()) + " runs:";
  bool first = true;
  for (const auto& [status, n] : by_status) {
    t += (first ? " " : ", ") + std::to_string(n) + " " + status;
    first = false;
  }
  return t + " (" + std::to_string(rows.size() - reused) + " run now, " + std::to_string(reused) + " reused)";
}

}  // namespace ede::sweep
