// An output file, or stdout when the path is empty, for tools whose -o is optional; close() reports write
// errors, so a full disk is an error message and exit status 1, not a short file and status 0. A FILE*,
// because the library's writers take one (write_state_csv). Rejected: std::ofstream, whose failure does
// not say why (no errno text for the message).
#pragma once

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include "ede/error.hpp"

namespace ede::tools {

class Output {
 public:
  explicit Output(const std::string& path) : path_(path) {
    file_ = path.empty() ? stdout : std::fopen(path.c_str(), "w");
    if (!file_) error_ = "cannot write '" + path + "': " + std::strerror(errno);
  }
  ~Output() {
    if (file_ && file_ != stdout) std::fclose(file_);
  }
  Output(const Output&) = delete;
  Output& operator=(const Output&) = delete;

  std::FILE* file() const { return file_; }
  const std::string& error() const { return error_; }  // why the file could not be opened
  void write(const std::string& text) { std::fputs(text.c_str(), file_); }
  Status close() {
    const bool failed = std::ferror(file_) != 0;
    const int closed = file_ == stdout ? std::fflush(file_) : std::fclose(file_);
    if (file_ != stdout) file_ = nullptr;
    if (failed || closed != 0)
      return Error{"error while writing '" + (path_.empty() ? std::string("<stdout>") : path_) + "'"};
    return Ok{};
  }

 private:
  std::string path_;
  std::FILE* file_ = nullptr;
  std::string error_;
};

}  // namespace ede::tools
