// ede-bench accuracy's output: the study's rows as CSV (engine.csv, time_stepped.csv, log.csv), as Markdown
// (tables.md, also printed), and a figure drawn from the CSV by tools/plot/plot_accuracy.py.
#pragma once

#include <string>

#include "ede/error.hpp"
#include "study/accuracy.hpp"

namespace ede::bench {

// Writes the tables into out_dir (which must exist) and, with `plot`, accuracy.png; prints tables.md.
Status write_report(const study::StudyResults& results, const std::string& out_dir, bool plot);

}  // namespace ede::bench
