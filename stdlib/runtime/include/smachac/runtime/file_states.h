// The file states of SMACHA's core templates, as their Python classes behave:
//
//   DeleteFileState    deletes the files the `file` input key names (a path or a glob
//                      pattern); `aborted` when one cannot be deleted or none exists
//   WriteCSVFileState  writes the values of the `data_keys` userdata keys as one row of the
//                      CSV `file` (a list value spreads over several columns), after an
//                      optional `header` row; `aborted` when the file cannot be written
//
// Both run their callbacks first (e.g. to compute the file name), like CallbacksState. The
// CSV is written as Python's csv.writer writes it: fields quoted only when they hold the
// delimiter, a quote or a line break (quotes doubled), each value as Python's str() (None
// empty), rows ended by "\r\n".
#pragma once

#include <string>
#include <vector>

#include "smachac/runtime/core_states.h"

namespace smachac::runtime {

class DeleteFileState : public State {
 public:
  /// Input key `file` is added to the spec; outcomes are succeeded and aborted.
  explicit DeleteFileState(StateSpec spec = {}, Callbacks callbacks = {});
  std::string execute(UserData& userdata) override;

 private:
  Callbacks callbacks_;
};

class WriteCSVFileState : public State {
 public:
  /// Input keys `file` and `data_keys` are added to the spec; outcomes are succeeded and
  /// aborted.
  explicit WriteCSVFileState(std::string delimiter = ",", StateSpec spec = {},
                             Callbacks callbacks = {});
  std::string execute(UserData& userdata) override;

 private:
  std::vector<std::string> row(UserData& userdata) const;

  std::string delimiter_;
  Callbacks callbacks_;
};

/// One CSV row as Python's csv.writer (QUOTE_MINIMAL) writes it, "\r\n" included.
std::string csvRow(const std::vector<std::string>& fields, const std::string& delimiter);

}  // namespace smachac::runtime
