// The shared tail of ede-stats gr, sk, psi6, msd and vacf (table_cli.hpp). JSON is written by hand: a flat
// object of numbers and arrays of numbers with 17 significant digits, NaN as null. Rejected: linking
// nlohmann-json into ede-stats for that.
#include "table_cli.hpp"

#include <cmath>
#include <cstdio>

namespace ede::stats_tool {

namespace {

std::string json_number(double v) { return std::isfinite(v) ? exact_double(v) : "null"; }

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) continue;
    out += c;
  }
  return out + "\"";
}

}  // namespace

void FrameCli::add(CLI::App* cmd, const char* what) {
  cmd->add_option("--at", at, std::string("one time to compute ") + what + " at (default: the end)");
  cmd->add_option("--from", from, "first frame's time (with --frames)");
  cmd->add_option("--to", to, "last frame's time, or 'end' (with --frames; default end)");
  cmd->add_option("--frames", frames, "frames averaged, equally spaced from --from to --to (default 1)")
      ->check(CLI::Range(std::size_t(1), std::size_t(1000000)));
}

Result<FrameTimes> FrameCli::read(const Log& log) const {
  FrameTimes f;
  f.frames = frames;
  const auto time = [&](const std::string& text, const char* option) -> Result<std::optional<double>> {
    if (text.empty()) return std::optional<double>{};
    auto t = tools::read_time(log, text, option);
    if (!t) return t.error();
    return std::optional<double>(double(t.value().t));
  };
  if (!at.empty()) {
    if (!from.empty() || !to.empty() || frames != 1) return Error{"--at is one time: give --from/--to/--frames instead"};
    auto t = time(at, "--at");
    if (!t) return t.error();
    f.from = f.to = t.value();
    return f;
  }
  auto a = time(from, "--from"), b = time(to, "--to");
  if (!a) return a.error();
  if (!b) return b.error();
  f.from = a.value(), f.to = b.value();
  if (f.frames > 1 && !f.from) return Error{"--frames above 1 needs --from (the first frame's time)"};
  return f;
}

Result<std::pair<std::optional<double>, std::optional<double>>> read_window(const Log& log, const std::string& from,
                                                                             const std::string& to) {
  std::pair<std::optional<double>, std::optional<double>> w;
  if (!from.empty()) {
    auto t = tools::read_time(log, from, "--from", false);
    if (!t) return t.error();
    w.first = double(t.value().t);
  }
  if (!to.empty()) {
    auto t = tools::read_time(log, to, "--to");
    if (!t) return t.error();
    if (!t.value().end) w.second = double(t.value().t);
  }
  return w;
}

std::string Table::csv() const {
  std::string text;
  for (std::size_t c = 0; c < names.size(); ++c) text += (c ? "," : "") + names[c];
  text += "\n";
  const std::size_t rows = columns.empty() ? 0 : columns[0].size();
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < columns.size(); ++c) text += (c ? "," : "") + exact_cell(columns[c][r]);
    text += "\n";
  }
  return text;
}

void TableOutput::add(CLI::App* cmd, const char* csv_help, const char* plot_help) {
  cmd->add_option("-o,--output", output, csv_help);
  cmd->add_option("--plot", plot, plot_help);
  cmd->add_flag("--json", json, "print the summary and every column as one JSON object on stdout");
}

bool plot_name_ok(const std::string& path) {
  const auto ends = [&](const char* e) {
    const std::string s(e);
    return path.size() > s.size() && path.compare(path.size() - s.size(), s.size(), s) == 0;
  };
  return ends(".png") || ends(".svg");
}

int finish_table(const std::string& command, const TableOutput& out, const Summary& s, const Table& t, const Figure& f) {
  if (out.json) {
    std::string j = "{\"command\": " + json_string(command);
    for (const auto& [k, v] : s.numbers) j += ", " + json_string(k) + ": " + json_number(v);
    j += ", \"columns\": {";
    for (std::size_t c = 0; c < t.names.size(); ++c) {
      j += (c ? ", " : "") + json_string(t.names[c]) + ": [";
      for (std::size_t r = 0; r < t.columns[c].size(); ++r) j += (r ? "," : "") + json_number(t.columns[c][r]);
      j += "]";
    }
    std::printf("%s}}\n", j.c_str());
  } else {
    for (const auto& [label, value] : s.text) std::printf("%-17s%s\n", label.c_str(), value.c_str());
  }
  std::fflush(stdout);
  if (out.output.empty() && out.plot.empty()) return 0;
  return write_csv_and_plot({.output = out.output,
                             .plot = out.plot,
                             .csv = t.csv(),
                             .script = f.script,
                             .args = f.script == "plot_table.py"
                                         ? std::vector<std::string>{out.plot, f.x, f.ys, f.error, f.dashed, f.title,
                                                                    f.xlabel, f.ylabel, f.scale}
                                         : std::vector<std::string>{out.plot, f.title},
                             .figure_label = out.json ? "" : "figure           "});
}

}  // namespace ede::stats_tool
