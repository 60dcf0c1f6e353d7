// The ede-stats helpers of stats_cli.hpp: opening logs, reading times and species, writing the CSV and
// drawing the figure through a temporary file when no -o was given (the script reads a file, never a
// pipe). Rejected: a --plot that needs -o, one more rule for users to learn.
#include "stats_cli.hpp"

#include <unistd.h>

#include <algorithm>

#include "output_file.hpp"
#include "plot_runner.hpp"

namespace ede::stats_tool {

namespace {

// A scratch file for a plotting script's input, removed when it goes out of scope.
class TempFile {
 public:
  explicit TempFile(const std::string& suffix) {
    std::string name = "/tmp/ede-stats-XXXXXX" + suffix;
    const int fd = mkstemps(name.data(), int(suffix.size()));
    if (fd >= 0) {
      ::close(fd);
      path_ = name;
    }
  }
  ~TempFile() {
    if (!path_.empty()) std::remove(path_.c_str());
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// `text` as the whole of a file; the error names the file.
Status write_file(const std::string& path, const std::string& text) {
  tools::Output out(path);
  if (!out.file()) return Error{out.error()};
  out.write(text);
  return out.close();
}

// The path a CSV is written to: -o, or a temporary file (kept alive by `temp`) when only a figure needs it.
Result<std::string> csv_path(const std::string& output, bool needed, std::unique_ptr<TempFile>& temp) {
  if (!output.empty() || !needed) return output;
  temp = std::make_unique<TempFile>(".csv");
  if (temp->path().empty()) return Error{"cannot create a temporary file for the figure's data"};
  return temp->path();
}

}  // namespace

Result<OpenedLog> open_log_overview(const std::string& path) {
  auto log = tools::open_log_warning("ede-stats", path);
  if (!log) return log.error();
  auto overview = log_overview(log.value());
  if (!overview) return overview.error();
  return OpenedLog{std::move(log).value(), overview.value()};
}

Result<double> read_analysis_time(const OpenedLog& opened, const std::string& text, const std::string& option,
                                  const std::string& fallback) {
  auto t = tools::read_time(opened.log, text.empty() ? fallback : text, option);
  if (!t) return t.error();
  if (t.value().end) return opened.overview.end_time;
  return std::min(double(t.value().t), opened.overview.end_time);  // a long double time within the log stays so
}

Result<std::int32_t> read_species(const Log& log, const std::string& name) {
  auto species = species_index(log.info(), name);
  if (!species) return Error{log.info().path + ": " + species.error().message};
  return species;
}

int write_csv_and_plot(const CsvAndFigure& f) {
  std::unique_ptr<TempFile> temp, extra;
  auto path = csv_path(f.output, !f.plot.empty(), temp);
  if (!path) return fail(path.error().message);
  if (!path.value().empty())
    if (Status s = write_file(path.value(), f.csv); !s) return fail(s.error().message);
  if (f.after_csv)
    if (Status s = f.after_csv(); !s) return fail(s.error().message);
  if (f.plot.empty()) return 0;
  std::vector<std::string> args = {path.value()};
  args.insert(args.end(), f.args.begin(), f.args.end());
  if (!f.extra_csv.empty()) {
    extra = std::make_unique<TempFile>(".csv");
    if (extra->path().empty() || !write_file(extra->path(), f.extra_csv))
      return fail("cannot write a temporary file for the figure's data");
    args[1 + f.extra_csv_arg] = extra->path();
  }
  if (Status p = tools::run_plot_script_to(f.script, args, f.plot); !p) return fail(p.error().message);
  if (!f.figure_label.empty()) std::printf("%s%s\n", f.figure_label.c_str(), f.plot.c_str());
  return 0;
}

}  // namespace ede::stats_tool
