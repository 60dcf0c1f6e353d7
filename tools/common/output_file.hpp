// An output file, or stdout when the path is empty, written so that a reader never sees half of it: the
// text goes to a temporary file beside the target (TARGET.tmp-XXXXXX, same directory, so the rename cannot
// cross file systems), and close() flushes, fsyncs, closes and renames it over the target only when every
// step succeeded. A failure (a full disk, a killed tool) leaves the old target untouched and no half
// file under its name; the temporary is removed unless the process was killed. Every error names the
// target. A target that exists and is not a regular file (/dev/null, /dev/full, a FIFO) is written
// directly: renaming over a device would replace it. stdout is flushed and checked on close().
// A FILE*, because the library's writers take one (write_state_csv). Rejected: std::ofstream, whose
// failure does not say why (no errno text for the message), and writing the target in place (a full disk
// or a kill leaves a short file that looks complete).
#pragma once

#include <cstdio>
#include <string>

#include "ede/error.hpp"

namespace ede::tools {

class Output {
 public:
  explicit Output(const std::string& path);
  ~Output();  // without a successful close(): removes the temporary file, leaves the target as it was
  Output(const Output&) = delete;
  Output& operator=(const Output&) = delete;

  std::FILE* file() const { return file_; }
  const std::string& error() const { return error_; }  // why the file could not be opened
  void write(const std::string& text) { std::fwrite(text.data(), 1, text.size(), file_); }
  // Checks every write, flushes, fsyncs and renames into place; the error names the target.
  Status close();

 private:
  std::string path_, temp_;  // temp_ empty: writing the target (or stdout) directly
  std::FILE* file_ = nullptr;
  std::string error_;
};

// `text` as the whole of `path` through an Output.
Status write_file_atomically(const std::string& path, const std::string& text);

// The temporary file name an output to `path` uses (for tools that let another program write it, such as
// a plotting script or cairo): TARGET.tmp-PID plus the target's extension, so the writer picks the format.
std::string temporary_name(const std::string& path);
// Renames a finished temporary over `path`; the error names `path`.
Status commit_temporary(const std::string& temp, const std::string& path);

}  // namespace ede::tools
