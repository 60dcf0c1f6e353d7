// Internal tier (README.md here): the log's reader, writer and column sizes, and Replay, for the log
// benchmarks and the checks that a log replays to the engine's state.
#pragma once

#include "log/log_column_sizes.hpp"
#include "log/log_reader.hpp"
#include "log/log_writer.hpp"
#include "replay/replay.hpp"
