// ede-bench log's tables (bench_log.cpp runs the benchmark and prints them): Markdown on stdout, and with
// --out-dir DIR the same rows as CSV files in DIR.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "study/log_bench.hpp"

namespace ede::bench {

// The CSV tables of --out-dir DIR (DIR/scenes.csv, ...); none without it.
struct CsvDir {
  std::string dir;
  bool failed = false;  // a table could not be written (the message is printed)
  std::FILE* open(const char* name);  // nullptr without a dir, or when the file cannot be written
};

struct ScenePair {
  std::string label;
  study::Series* off;
  study::Series* on;
};

std::string percent(double ratio);             // "+3.1 %"
std::string share(double part, double whole);  // "12.5 %"
std::string mib(double bytes);

// 1. Bytes per event by scene, and where they go (columns): bench_log.cpp.
void print_scenes(const std::vector<ScenePair>& pairs, CsvDir& out);
void print_columns(const std::vector<ScenePair>& pairs, CsvDir& out);
// 2, 3 and 4: the zstd level, the logging overhead, seeking.
void print_levels(const study::Series& off, const std::vector<study::Series*>& levels, CsvDir& out);
void print_overhead(const std::vector<study::Series*>& rows, bool have_cycles);
void print_seek(const std::vector<study::SeekRow>& rows, const study::Series& sim, CsvDir& out);
void print_failures(const std::vector<study::Series>& all);

}  // namespace ede::bench
