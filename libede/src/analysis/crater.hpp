// The bed selection on a log's header alone (ede/crater.hpp has the geometry, the types and the analyses
// over a Log): a pure function on plain data, so its tests need no log.
#pragma once

#include <memory>
#include <string>

#include "ede/crater.hpp"
#include "log/log_reader.hpp"

namespace ede {

Result<BedSelection> select_bed(const LogHeaderInfo& header, const std::string& name);

}  // namespace ede
