// ocean/core.hpp — status and result types shared by every module.
//
// Contract: library functions never throw across the library boundary. Failures caused by the
// environment or by input (a bad parameter, an unreadable file) are reported as a Status with a
// one-line, human-readable message that names what is wrong and what would be valid. Programmer
// mistakes (broken invariants) are asserts, not Status values.
#pragma once

#include <cmath>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace ocean {

/// Broad class of a failure, so callers can react without parsing messages.
enum class ErrorCode {
  ok = 0,
  invalid_argument,  ///< a parameter is outside its valid range (NaN, negative, unknown name...)
  io_error,          ///< a file could not be read or written
  unsupported,       ///< a feature that was not compiled in or that this machine lacks
  internal,          ///< should not happen; a bug
  cancelled,         ///< stopped at the caller's request (a cancellation flag it set)
};

/// Outcome of an operation: ok, or an error code with a one-line message.
class [[nodiscard]] Status {
 public:
  Status() = default;
  Status(ErrorCode code, std::string message) : code_(code), message_(std::move(message)) {}

  static Status ok_status() { return {}; }

  [[nodiscard]] bool ok() const { return code_ == ErrorCode::ok; }
  [[nodiscard]] ErrorCode code() const { return code_; }
  /// One line, no trailing newline; empty when ok().
  [[nodiscard]] const std::string& message() const { return message_; }

 private:
  ErrorCode code_ = ErrorCode::ok;
  std::string message_;
};

/// Shorthand constructors.
inline Status invalid_argument(std::string message) {
  return {ErrorCode::invalid_argument, std::move(message)};
}
inline Status io_error(std::string message) { return {ErrorCode::io_error, std::move(message)}; }
inline Status unsupported(std::string message) {
  return {ErrorCode::unsupported, std::move(message)};
}

/// A value or the Status explaining why there is none.
template <typename T>
class [[nodiscard]] Result {
 public:
  Result(T value) : data_(std::move(value)) {}         // NOLINT(google-explicit-constructor)
  Result(Status status) : data_(std::move(status)) {}  // NOLINT(google-explicit-constructor)

  [[nodiscard]] bool ok() const { return std::holds_alternative<T>(data_); }
  [[nodiscard]] const T& value() const& { return std::get<T>(data_); }
  [[nodiscard]] T& value() & { return std::get<T>(data_); }
  [[nodiscard]] T&& value() && { return std::get<T>(std::move(data_)); }
  /// The failure; an ok Status when a value is held.
  [[nodiscard]] Status status() const { return ok() ? Status{} : std::get<Status>(data_); }

 private:
  std::variant<T, Status> data_;
};

/// Parameter validation helpers: each returns an ok Status or one naming the parameter, the
/// offending value and the valid range, e.g. "wind_speed_mps = -3 is out of range: must be > 0".
Status require_finite(std::string_view name, double value);
Status require_positive(std::string_view name, double value);
Status require_non_negative(std::string_view name, double value);
/// Inclusive range [lo, hi].
Status require_in_range(std::string_view name, double value, double lo, double hi);

/// Formats a double the way messages and JSON print it: shortest form that round-trips.
std::string format_number(double value);

/// A value typed by a user, made safe to echo in a one-line message: at most `max_bytes` bytes of
/// it (cut on a UTF-8 character boundary, then "..." and the full length in bytes), with control
/// characters, invalid UTF-8 and backslashes written as C-style escapes (\n, \t, \xHH, \\).
/// A 300 MB argument comes back as about `max_bytes` bytes; the result never holds a newline.
std::string excerpt(std::string_view text, std::size_t max_bytes = 80);

}  // namespace ocean
