// The template engine's one public exception type, TemplateError (syntax errors, unknown
// filters or tests, missing templates, runtime errors), and Fault, the location-less error
// that value operations and filters raise and the renderer turns into a TemplateError.
#pragma once

#include <exception>
#include <string>
#include <string_view>
#include <vector>

namespace smachac::tmpl {

class TemplateError : public std::exception {
 public:
  /// `line` and `column` are 1-based; 0 when the error has no position (e.g. a missing
  /// top-level template).
  TemplateError(std::string file, int line, int column, std::string message);

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  int column() const { return column_; }
  const std::string& message() const { return message_; }
  /// "file:line:col: message" (or "file: message" without a position).
  const char* what() const noexcept override { return what_.c_str(); }

 private:
  std::string file_;
  int line_;
  int column_;
  std::string message_;
  std::string what_;
};

/// An error without a location, raised by value operations, filters, tests and methods.
/// Custom filters and tests may throw it too (through fail()).
class Fault : public std::exception {
 public:
  explicit Fault(std::string message) : message_(std::move(message)) {}
  const std::string& message() const { return message_; }
  const char* what() const noexcept override { return message_.c_str(); }

 private:
  std::string message_;
};

[[noreturn]] void fail(std::string message);

/// "; did you mean `x`?" for the closest candidate (edit distance), or "".
std::string didYouMean(std::string_view name, const std::vector<std::string_view>& candidates);

}  // namespace smachac::tmpl
