#pragma once
// Assertions about user-facing errors: the message an InputError carries, and what it says.
#include "core/input_error.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace paver::test {

// The message of the InputError `call` throws; a test failure (and "") when it throws none.
inline std::string error_of(const std::function<void()>& call) {
  try {
    call();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return {};
}

inline ::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

}  // namespace paver::test
