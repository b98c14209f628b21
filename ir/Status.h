// The one error type that crosses library boundaries: a code, a location (file:line:col when
// known) and the message a person reads. Header-only, no dependencies beyond the standard library.
#pragma once

#include <cassert>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace lj {

/// What kind of problem a Status reports (stable: a JSON client may switch on it).
enum class ErrorCode : uint8_t {
  Ok,
  InvalidArgument, ///< a name, option or value the caller passed is not accepted
  NotFound,        ///< a file or object does not exist or cannot be opened
  BadFormat,       ///< a file's content does not follow its format
  Rejected,        ///< well-formed input refused by a check (verifier, ABI, program hash)
  EngineFailed,    ///< an engine could not be built (compile or load failure)
  Internal,        ///< a bug: an invariant the caller relied on did not hold
};

/// The code's name as a JSON client sees it ("invalid_argument").
inline const char *errorCodeName(ErrorCode c) {
  switch (c) {
  case ErrorCode::Ok:
    return "ok";
  case ErrorCode::InvalidArgument:
    return "invalid_argument";
  case ErrorCode::NotFound:
    return "not_found";
  case ErrorCode::BadFormat:
    return "bad_format";
  case ErrorCode::Rejected:
    return "rejected";
  case ErrorCode::EngineFailed:
    return "engine_failed";
  case ErrorCode::Internal:
    return "internal";
  }
  return "internal";
}

/// Where a problem is; line and col are 1-based, 0 when unknown.
struct ErrorLoc {
  std::string file;
  int32_t line = 0;
  int32_t col = 0;
};

/// Success, or a located, coded error. `message()` is the complete line shown to a person (it
/// already names the file the way the CLI always has); `loc()` carries the same place as fields.
class [[nodiscard]] Status {
public:
  Status() = default; ///< success
  static Status error(ErrorCode code, std::string message, ErrorLoc loc = {}) {
    assert(code != ErrorCode::Ok && "an error needs an error code");
    Status s;
    s.code_ = code;
    s.message_ = std::move(message);
    s.loc_ = std::move(loc);
    return s;
  }

  bool ok() const { return code_ == ErrorCode::Ok; }
  ErrorCode code() const { return code_; }
  const ErrorLoc &loc() const { return loc_; }
  const std::string &message() const { return message_; }

  /// The same error with `context + ": "` in front of the message (code and location kept).
  Status withContext(const std::string &context) const {
    Status s = *this;
    if (!ok()) s.message_ = context + ": " + message_;
    return s;
  }

private:
  ErrorCode code_ = ErrorCode::Ok;
  std::string message_;
  ErrorLoc loc_;
};

/// A value or the Status saying why there is none.
template <typename T> class [[nodiscard]] Result {
public:
  Result(T value) : v_(std::move(value)) {}
  Result(Status error) : v_(std::move(error)) {
    assert(!std::get<Status>(v_).ok() && "a Result without a value needs an error");
  }

  bool ok() const { return std::holds_alternative<T>(v_); }
  explicit operator bool() const { return ok(); }

  T &value() & { return std::get<T>(v_); }
  const T &value() const & { return std::get<T>(v_); }
  T &&value() && { return std::get<T>(std::move(v_)); }
  T &operator*() & { return value(); }
  T *operator->() { return &value(); }
  const T *operator->() const { return &value(); }

  /// The error; success when there is a value.
  Status status() const { return ok() ? Status() : std::get<Status>(v_); }

private:
  std::variant<T, Status> v_;
};

} // namespace lj
