// Errors: Result<T> (a value or an Error) at every API boundary, and ede::Exception, the one exception
// type the library throws.
//
// Every call that can fail for a reason outside the program's control (a file, a scene, a log, a
// request for something the run cannot do) returns a Result. Its Error carries one complete message:
// where (file, line, key, byte), what is wrong, and how to fix it, ready to print. Nothing in the
// library calls exit() or prints. Taking value() of a failed Result throws ede::Exception with that
// message, so code that prefers exceptions writes `auto log = ede::Log::open(path).value();` and
// catches ede::Exception at the top. The event loop itself never throws.
// Rejected: exceptions as the primary channel (which errors can a call give?), and error codes without
// messages (a user needs the file and the fix, not a number).
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

namespace ede {

// What kind of failure, for callers that react differently (the Python module maps them to exception
// classes). The message is what to show.
enum class ErrorKind {
  Invalid,      // bad input: a scene, an argument, a state, a request outside what the data holds
  Io,           // a file could not be opened, read or written
  Corrupt,      // a log that is damaged, truncated where it must not be, or not a log at all
  Unsupported,  // valid, but not something this build of ede can do (a newer log version, float128 here)
};

struct Error {
  std::string message;  // complete sentence(s): where (file, line, key), what is wrong, how to fix it
  ErrorKind kind = ErrorKind::Invalid;
};

// The exception value() throws for a failed Result.
class Exception : public std::runtime_error {
 public:
  explicit Exception(Error error) : std::runtime_error(error.message), error_(std::move(error)) {}
  const Error& error() const { return error_; }
  ErrorKind kind() const { return error_.kind; }

 private:
  Error error_;
};

template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : data_(std::move(value)) {}
  Result(Error error) : data_(std::move(error)) {}

  bool ok() const { return std::holds_alternative<T>(data_); }
  explicit operator bool() const { return ok(); }

  // The value; throws ede::Exception if this is an error.
  T& value() & { return check(), std::get<T>(data_); }
  const T& value() const& { return check(), std::get<T>(data_); }
  T&& value() && { return check(), std::get<T>(std::move(data_)); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  // The error; only meaningful when !ok().
  const Error& error() const { return std::get<Error>(data_); }

 private:
  void check() const {
    if (!ok()) throw Exception(std::get<Error>(data_));
  }
  std::variant<T, Error> data_;
};

// For calls that return nothing on success.
struct Ok {};
using Status = Result<Ok>;

}  // namespace ede
