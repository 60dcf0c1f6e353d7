// read_time; see time_option.hpp.
#include "time_option.hpp"

namespace ede::tools {

Result<TimeOption> read_time(const Log& log, const std::string& text, const std::string& option, bool end_allowed) {
  const LogInfo& info = log.info();
  if (text == "end" && end_allowed) return TimeOption{info.end_time, true};
  auto v = parse_exact(text, info.scalar);
  if (!v)
    return Error{info.path + ": " + option + " '" + text + "' is not a time (a number such as 0.5 or 1e-3" +
                 (end_allowed ? ", or 'end')" : ")")};
  if (v.value() < 0) return Error{info.path + ": " + option + " '" + text + "' is negative"};
  if (v.value() > info.end_time)
    return Error{info.path + ": " + option + " " + text + " is after the end of the log (t = " +
                 exact_text(info.end_time, info.scalar) + (info.complete ? "" : "; the log is incomplete") + ")" +
                 (end_allowed ? "; " + option + " end gives the last state" : "")};
  return TimeOption{v.value(), false};
}

}  // namespace ede::tools
