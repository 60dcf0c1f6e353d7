// Result<T>: a value or an error message, for I/O and API boundaries.
//
// The event loop never throws; parsing, validation and file I/O return Result so that every tool can print
// one clear message and exit non-zero. (std::expected is C++23; this is the small subset we need.)
// Rejected: exceptions across the library boundary, which make "which errors can this call give?" hard to
// answer and cost a try/catch at every tool entry point anyway.
#pragma once

#include <string>
#include <utility>
#include <variant>

namespace ede {

struct Error {
  std::string message;  // complete sentence(s): where (file, line, key), what is wrong, how to fix it
};

template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : data_(std::move(value)) {}
  Result(Error error) : data_(std::move(error)) {}

  bool ok() const { return std::holds_alternative<T>(data_); }
  explicit operator bool() const { return ok(); }

  T& value() & { return std::get<T>(data_); }
  const T& value() const& { return std::get<T>(data_); }
  T&& value() && { return std::get<T>(std::move(data_)); }
  const Error& error() const { return std::get<Error>(data_); }

 private:
  std::variant<T, Error> data_;
};

// For calls that return nothing on success.
struct Ok {};
using Status = Result<Ok>;

}  // namespace ede
