// Output and the temporary-then-rename helpers; see output_file.hpp.
#include "output_file.hpp"

#include "file_checks.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace ede::tools {

namespace {

bool is_other_than_regular(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode);
}

std::string why(int err) { return std::strerror(err); }

}  // namespace

Output::Output(const std::string& path) : path_(path) {
  if (path.empty()) {
    file_ = stdout;
    return;
  }
  if (Status s = check_not_an_input(path); !s) {
    error_ = s.error().message;
    return;
  }
  if (is_other_than_regular(path)) {
    file_ = std::fopen(path.c_str(), "w");
    if (!file_) error_ = "cannot write '" + path + "': " + why(errno);
    return;
  }
  std::string name = path + ".tmp-XXXXXX";
  const int fd = ::mkstemp(name.data());
  if (fd < 0) {
    error_ = "cannot write '" + path + "': cannot create a temporary file beside it (" + why(errno) +
             "). Fix: check that the directory exists and is writable.";
    return;
  }
  ::fchmod(fd, 0644);
  temp_ = name;
  file_ = ::fdopen(fd, "w");
  if (!file_) {
    error_ = "cannot write '" + path + "': " + why(errno);
    ::close(fd);
    ::unlink(temp_.c_str());
    temp_.clear();
  }
}

Output::~Output() {
  if (file_ && file_ != stdout) std::fclose(file_);
  if (!temp_.empty()) ::unlink(temp_.c_str());
}

Status Output::close() {
  const std::string shown = path_.empty() ? std::string("<stdout>") : "'" + path_ + "'";
  if (!file_) return Error{error_.empty() ? "cannot write " + shown : error_, ErrorKind::Io};
  int err = 0;
  if (std::fflush(file_) != 0) err = errno;
  if (!err && std::ferror(file_)) err = EIO;
  if (file_ == stdout) {
    if (err) return Error{"error while writing " + shown + ": " + why(err), ErrorKind::Io};
    return Ok{};
  }
  if (!err && !temp_.empty() && ::fsync(::fileno(file_)) != 0) err = errno;
  if (std::fclose(file_) != 0 && !err) err = errno;
  file_ = nullptr;
  if (err) return Error{"error while writing " + shown + ": " + why(err) + "; it was left as it was", ErrorKind::Io};
  if (temp_.empty()) return Ok{};
  Status s = commit_temporary(temp_, path_);
  temp_.clear();
  return s;
}

Status write_file_atomically(const std::string& path, const std::string& text) {
  Output out(path);
  if (!out.file()) return Error{out.error(), ErrorKind::Io};
  out.write(text);
  return out.close();
}

std::string temporary_name(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash + 1);
  const std::string stem = has_ext ? path.substr(0, dot) : path;
  return stem + ".tmp-" + std::to_string(::getpid()) + (has_ext ? path.substr(dot) : std::string());
}

Status commit_temporary(const std::string& temp, const std::string& path) {
  if (Status s = check_not_an_input(path); !s) {
    ::unlink(temp.c_str());
    return s;
  }
  if (is_other_than_regular(path)) {
    ::unlink(temp.c_str());
    return Error{"cannot write '" + path + "': it exists and is not a regular file", ErrorKind::Io};
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(temp.c_str());
    return Error{"cannot put the finished file in place as '" + path + "': " + why(err), ErrorKind::Io};
  }
  return Ok{};
}

}  // namespace ede::tools
