// DeleteFileState and WriteCSVFileState: the files they leave, byte for byte as SMACHA's Python
// classes (csv.writer) leave them, and their outcomes.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "helpers.h"

namespace rt = smachac::runtime;
namespace fs = std::filesystem;

namespace {

/// A fresh folder under the system's temporary folder, removed with the fixture.
struct TempFolder {
  fs::path path = fs::temp_directory_path() / ("smachac_file_states_" + std::to_string(::getpid()));
  TempFolder() { fs::create_directories(path); }
  ~TempFolder() { fs::remove_all(path); }
};

std::string contents(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("csvRow quotes as Python's csv.writer does") {
  CHECK(rt::csvRow({"1", "2.5", "True", ""}, ",") == "1,2.5,True,\r\n");
  CHECK(rt::csvRow({"a,b", "say \"hi\"", "two\nlines", "a;b"}, ",") ==
        "\"a,b\",\"say \"\"hi\"\"\",\"two\nlines\",a;b\r\n");
  CHECK(rt::csvRow({"a;b"}, ";") == "\"a;b\"\r\n");
  CHECK(rt::csvRow({""}, ",") == "\"\"\r\n");
}

TEST_CASE("WriteCSVFileState writes the header and one row; lists spread over columns") {
  TempFolder folder;
  fs::path file = folder.path / "out.csv";
  rt::StateMachine sm({.outcomes = {"done", "failed"},
                       .userdata = {{"file", file.string()},
                                    {"data_keys", rt::List{"xs", "label", "none"}},
                                    {"header", rt::List{"x1", "x2", "label", "none"}},
                                    {"xs", rt::List{1, 2.5}},
                                    {"label", "a;b"},
                                    {"none", rt::Value()}}});
  sm.add("WRITE",
         std::make_unique<rt::WriteCSVFileState>(
             ";", rt::StateSpec{.input_keys = {"header", "xs", "label", "none"}}),
         {{"succeeded", "done"}, {"aborted", "failed"}});
  CHECK(rt::run(sm).outcome == "done");
  CHECK(contents(file) == "x1;x2;label;none\r\n1;2.5;\"a;b\";\r\n");
}

TEST_CASE("WriteCSVFileState aborts when the file cannot be written") {
  rt::StateMachine sm(
      {.outcomes = {"done", "failed"},
       .userdata = {{"file", "/nonexistent/dir/out.csv"}, {"data_keys", rt::List{"x"}}, {"x", 1}}});
  sm.add("WRITE", std::make_unique<rt::WriteCSVFileState>(",", rt::StateSpec{.input_keys = {"x"}}),
         {{"succeeded", "done"}, {"aborted", "failed"}});
  CHECK(rt::run(sm).outcome == "failed");
}

TEST_CASE("DeleteFileState deletes what a glob pattern matches, and aborts on nothing") {
  TempFolder folder;
  for (const char* name : {"a.csv", "b.csv", "keep.txt"}) std::ofstream(folder.path / name) << "x";
  rt::StateMachine sm(
      {.outcomes = {"done", "failed"}, .userdata = {{"file", (folder.path / "*.csv").string()}}});
  sm.add("DELETE", std::make_unique<rt::DeleteFileState>(),
         {{"succeeded", "done"}, {"aborted", "failed"}});
  CHECK(rt::run(sm).outcome == "done");
  CHECK_FALSE(fs::exists(folder.path / "a.csv"));
  CHECK_FALSE(fs::exists(folder.path / "b.csv"));
  CHECK(fs::exists(folder.path / "keep.txt"));
  CHECK(rt::run(sm).outcome == "failed");  // nothing matches now: the pattern itself is missing
}
