// The CSV files ede-crater measure writes: the surface profiles and the energy curve; quoting for fields.
//
// Plain comma-separated tables with one header line, numbers with 17 significant digits (they read back to
// the same double), so scripts and the plotting script need no special reader. Rejected: one file with
// several tables separated by blank lines, which every CSV reader then has to be taught to split.
#include <cerrno>
#include <cstring>

#include "crater_tool.hpp"
#include "output_file.hpp"

namespace ede::crater_tool {

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string q = "\"";
  for (const char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

Status write_text_file(const std::string& path, const std::string& text) {
  return tools::write_file_atomically(path, text);  // temporary, then renamed; never over an input
}

Status write_profile_csv(const std::string& path, const CraterMeasurement& m) {
  const CraterReport& r = m.report;
  const double w = r.before.bin_width;
  std::string s = "x_left,x_right,x,h_before,h_after,drop,in_crater,disks_before,disks_after\n";
  for (std::size_t k = 0; k < r.before.height.size(); ++k) {
    const bool in = r.metrics.has_crater && k >= r.metrics.first_bin && k <= r.metrics.last_bin;
    s += exact_double(double(k) * w) + "," + exact_double(double(k + 1) * w) + "," + exact_double(r.before.centre(k)) + "," +
         exact_double(r.before.height[k]) + "," + exact_double(r.after.height[k]) + "," +
         exact_double(r.before.height[k] - r.after.height[k]) + "," + (in ? "1" : "0") + "," +
         std::to_string(r.before.disks[k]) + "," + std::to_string(r.after.disks[k]) + "\n";
  }
  return write_text_file(path, s);
}

Status write_energy_csv(const std::string& path, const CraterMeasurement& m) {
  std::string s = "t,energy_fraction\n";
  for (std::size_t k = 0; k < m.energy.t.size(); ++k) s += exact_double(m.energy.t[k]) + "," + exact_double(m.energy.f[k]) + "\n";
  return write_text_file(path, s);
}

}  // namespace ede::crater_tool
