// Rewriting a complete log in another format version (1 or 2) with bit-identical states; log_convert.cpp.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "ede/error.hpp"
#include "log/log_reader.hpp"

namespace ede {

Status convert_log(const std::shared_ptr<const LogReader>& log, const std::string& out_path, std::uint32_t version);

}  // namespace ede
