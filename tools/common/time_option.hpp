// A time typed on a tool's command line (--at, --from, --to, --before): a number read exactly in the log's
// scalar type, or the word `end`, the time the run reached (docs/cli.md).
//
// Every tool words the same mistakes the same way: not a number, negative, after the end of the log (with
// that end exactly, so it can be typed back). `--at 0.1` in a float log is the float nearest 0.1, what a
// float engine stopping at stop.time = 0.1 reaches. Rejected: reading every time as a double (a long
// double log's times would be rounded) and each tool checking times in its own words.
#pragma once

#include <string>

#include "ede/log.hpp"

namespace ede::tools {

struct TimeOption {
  Time t = 0;        // exactly a value of the log's scalar type (the end's, for `end`)
  bool end = false;  // `end` was typed
};

// `text` as given after `option` ("--at"); `end` is refused when end_allowed is false. Errors name the log.
Result<TimeOption> read_time(const Log& log, const std::string& text, const std::string& option,
                             bool end_allowed = true);

}  // namespace ede::tools
