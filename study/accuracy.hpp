// The accuracy study (ede-bench accuracy): what accuracy costs in time. The same scenes (examples/accuracy)
// under different settings (scalar type; stable or textbook contact root; a time-stepped simulation at
// several dt; the log off, on, and its keyframe interval), each giving its cost (ns per event, or CPU
// seconds) and the errors it leaves (energy drift, largest overlap, time reversal, divergence of runs one
// ulp apart, collision rate and cooling curve, seek time, bytes per event). The definitions are in
// docs/accuracy.md; ede-bench writes the rows as CSV tables, Markdown and a figure.
#pragma once

#include <vector>

#include "ede/error.hpp"
#include "study/accuracy_parts.hpp"

namespace ede::study {

struct StudyResults {
  StudyPlan plan;
  std::vector<EngineRow> engine;
  SteppedStudy stepped;
  std::vector<LogRow> log;
  bool ok() const;  // every row measured, every timed run agreeing with its error run
};

// The plan of a smoke run (ede-bench accuracy --quick, what the test runs): every metric and every row
// but __float128's on the second and third scenes, shorter lists (fewer dt, keyframe intervals, comparison
// times) and shorter runs. Its caller shortens the scenes' stop.events (stop.events=200000) and the repeats.
StudyPlan quick_plan(StudyPlan plan);

// The engine scenes' stop.events must be set (they are how long the error runs are); creates plan.tmp_dir
// and removes it when empty at the end. An error only when the study cannot start; rows that fail carry
// their failure.
Result<StudyResults> run_accuracy_study(const StudyPlan& plan);

}  // namespace ede::study
