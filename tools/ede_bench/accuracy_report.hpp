// ede-bench accuracy's output: the study's rows as CSV (engine.csv, time_stepped.csv, log.csv), as Markdown
// (tables.md, also printed), and a figure drawn from the CSV by tools/plot/plot_accuracy.py.
#pragma once

#include <string>
#include <vector>

#include "accuracy_parts.hpp"
#include "ede/error.hpp"

namespace ede::bench {

struct StudyResults {
  StudyPlan plan;
  std::vector<EngineRow> engine;
  SteppedStudy stepped;
  std::vector<LogRow> log;
};

// Writes the tables into out_dir (which must exist) and, with `plot`, accuracy.png; prints tables.md.
Status write_report(const StudyResults& results, const std::string& out_dir, bool plot);

}  // namespace ede::bench
