// DeleteFileState and WriteCSVFileState (file_states.h).
#include "smachac/runtime/file_states.h"

#include <glob.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <optional>

#include "smachac/runtime/errors.h"
#include "text.h"

namespace smachac::runtime {

namespace {

constexpr const char* kSucceeded = "succeeded";
constexpr const char* kAborted = "aborted";

StateSpec withFileKeys(StateSpec spec, std::initializer_list<const char*> keys) {
  if (spec.outcomes.empty()) spec.outcomes = {kSucceeded, kAborted};
  for (const char* key : keys) {
    if (std::find(spec.input_keys.begin(), spec.input_keys.end(), key) == spec.input_keys.end()) {
      spec.input_keys.emplace_back(key);
    }
  }
  return spec;
}

/// The paths `pattern` matches, or the pattern itself when nothing does (as glob.glob's
/// empty result falls back to the name in the Python class).
std::vector<std::string> matches(const std::string& pattern) {
  glob_t found{};
  std::vector<std::string> paths;
  if (glob(pattern.c_str(), 0, nullptr, &found) == 0) {
    for (std::size_t i = 0; i < found.gl_pathc; ++i) paths.emplace_back(found.gl_pathv[i]);
  }
  globfree(&found);
  if (paths.empty()) paths.push_back(pattern);
  return paths;
}

/// A value as Python's csv module writes it: str(value), None empty.
std::string field(const Value& value) { return value.isNull() ? std::string() : value.str(); }

bool needsQuotes(const std::string& text, const std::string& delimiter) {
  return text.find_first_of(delimiter + "\"\r\n") != std::string::npos;
}

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

std::string csvRow(const std::vector<std::string>& fields, const std::string& delimiter) {
  if (fields.size() == 1 && fields.front().empty()) return "\"\"\r\n";  // else a blank line
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i > 0) line += delimiter;
    line += needsQuotes(fields[i], delimiter) ? quoted(fields[i]) : fields[i];
  }
  return line + "\r\n";
}

// --- DeleteFileState -------------------------------------------------------------------------

DeleteFileState::DeleteFileState(StateSpec spec, Callbacks callbacks)
    : State(withFileKeys(std::move(spec), {"file"})), callbacks_(std::move(callbacks)) {
  for (const auto& entry : callbacks_) addOutputKey(entry.key);
  placeCallbacks(callbacks_, outputKeys());
}

std::string DeleteFileState::execute(UserData& userdata) {
  runCallbacks(callbacks_, userdata);
  for (const std::string& path : matches(userdata.get<std::string>("file"))) {
    if (std::remove(path.c_str()) != 0) return kAborted;
  }
  return kSucceeded;
}

// --- WriteCSVFileState -----------------------------------------------------------------------

WriteCSVFileState::WriteCSVFileState(std::string delimiter, StateSpec spec, Callbacks callbacks)
    : State(withFileKeys(std::move(spec), {"file", "data_keys"})),
      delimiter_(std::move(delimiter)),
      callbacks_(std::move(callbacks)) {
  for (const auto& entry : callbacks_) addOutputKey(entry.key);
  placeCallbacks(callbacks_, outputKeys());
}

std::vector<std::string> WriteCSVFileState::row(UserData& userdata) const {
  std::vector<std::string> fields;
  for (const std::string& key : userdata.get<std::vector<std::string>>("data_keys")) {
    Value value = userdata.at(key);
    if (value.type() != ValueType::List) {
      fields.push_back(field(value));
      continue;
    }
    for (const Value& item : value.list()) fields.push_back(field(item));
  }
  return fields;
}

std::string WriteCSVFileState::execute(UserData& userdata) {
  if (delimiter_.size() != 1) {
    throw Error("WriteCSVFileState " + backticked(displayName()) +
                ": the delimiter must be one character, not " + backticked(delimiter_));
  }
  runCallbacks(callbacks_, userdata);
  std::vector<std::string> fields = row(userdata);
  std::optional<Value> header = declaresInput("header") ? userdata.find("header") : std::nullopt;
  std::ofstream file(userdata.get<std::string>("file"), std::ios::binary | std::ios::trunc);
  if (!file) return kAborted;
  if (header) {
    std::vector<std::string> titles;
    for (const Value& title : header->list()) titles.push_back(field(title));
    file << csvRow(titles, delimiter_);
  }
  file << csvRow(fields, delimiter_);
  file.close();
  return file ? kSucceeded : kAborted;
}

}  // namespace smachac::runtime
