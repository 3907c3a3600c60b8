// The runtime's exceptions. Every message names what failed (a state path, a userdata key) in
// backticks, lowercase, without a trailing period, like the compiler's diagnostics.
//
//   Error                 base of everything the runtime throws
//   ├─ TypeError          a Value read as a type it does not hold (no key context yet)
//   ├─ UserDataError      undeclared, missing or mistyped userdata key, naming the state
//   ├─ ConsistencyError   a container that cannot run (unknown targets, unmapped outcomes, ...)
//   └─ ExecutionError     a state failed while running (user exception, bad outcome)
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace smachac::runtime {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A Value converted to a type it does not hold: "expected a double, got a string".
class TypeError : public Error {
 public:
  TypeError(std::string expected, std::string actual)
      : Error("expected " + expected + ", got " + actual),
        expected_(std::move(expected)),
        actual_(std::move(actual)) {}
  /// What was asked for, with its article: "a double", "a list of strings".
  const std::string& expected() const { return expected_; }
  /// What the value holds, with its article: "a string", "a list with a string at index 1".
  const std::string& actual() const { return actual_; }

 private:
  std::string expected_;
  std::string actual_;
};

class UserDataError : public Error {
 public:
  using Error::Error;
};

/// All the problems a consistency check found, one per line in what().
class ConsistencyError : public Error {
 public:
  explicit ConsistencyError(std::vector<std::string> problems);
  const std::vector<std::string>& problems() const { return problems_; }

 private:
  std::vector<std::string> problems_;
};

/// A failure while executing; the message names the state. Containers pass it through
/// unchanged, so the root sees the innermost failure.
class ExecutionError : public Error {
 public:
  using Error::Error;
};

}  // namespace smachac::runtime
