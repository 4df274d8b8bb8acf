#pragma once
// Errors as values at the Vulkan boundary: a Result holds either a value or an Error with
// readable text (what failed and, where we know it, what to do).
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

namespace paver::gpu {

struct Error {
  std::string message;
};

template <class T>
class Result {
public:
  Result(T value) : state_(std::move(value)) {}
  Result(Error error) : state_(std::move(error)) {}

  bool ok() const { return std::holds_alternative<T>(state_); }
  explicit operator bool() const { return ok(); }
  T& value() { return std::get<T>(state_); }
  const T& value() const { return std::get<T>(state_); }
  const Error& error() const { return std::get<Error>(state_); }
  // The value, or a std::runtime_error with the error's text (for callers that cannot go on).
  T& value_or_throw() {
    if (!ok()) throw std::runtime_error(error().message);
    return value();
  }

private:
  std::variant<T, Error> state_;
};

}  // namespace paver::gpu
