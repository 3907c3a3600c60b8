// The simple YAML reader against yaml-cpp on random block documents (seeded, so every run
// sees the same ones): keys and scalars of every style, flow collections, nested and
// indentless sequences, empty values, comments and blank lines at any indentation, flow
// collections over several lines, and now and
// then a perturbation (a tab, a carriage return, a deeper line, a missing space). Whatever the
// reader does not give up on must be yaml-cpp's tree exactly.
#include <doctest/doctest.h>

#include <random>
#include <string>
#include <vector>

#include "tests/unit/frontend/yaml_reader_diff.h"

namespace {

class RandomYaml {
 public:
  explicit RandomYaml(uint32_t seed) : rng_(seed) {}

  std::string document() {
    out_.clear();
    if (chance(10)) out_ += "---\n";
    if (chance(2)) {
      map(0, 0);
    } else {
      sequence(0, 0);
    }
    if (chance(5) && !out_.empty()) out_.pop_back();  // no final line break
    return out_;
  }

 private:
  bool chance(int one_in) { return std::uniform_int_distribution<int>(1, one_in)(rng_) == 1; }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }
  template <size_t N>
  const char* pick(const char* const (&items)[N]) {
    return items[pick(static_cast<int>(N))];
  }

  std::string scalar() {
    static const char* const kScalars[] = {"a",
                                           "word",
                                           "two words",
                                           "x#y",
                                           "http://h:8/p",
                                           "a,b[c]{d}",
                                           "~",
                                           "null",
                                           "NULL",
                                           "true",
                                           "False",
                                           "yes",
                                           "0",
                                           "-1",
                                           "+5",
                                           "1.5",
                                           ".5",
                                           "1e3",
                                           "0x1F",
                                           "0o17",
                                           ".inf",
                                           "-.inf",
                                           ".nan",
                                           "'q'",
                                           "''",
                                           "\"d\"",
                                           "'it''s'",
                                           "\"# x\"",
                                           "'a: b'",
                                           "-a",
                                           "\xC3\xA9",
                                           "\"t\\tq\\\"\"",
                                           "\"a\\\\b\"",
                                           "'`lambda ud: 1`'"};
    // What the reader leaves to yaml-cpp, or yaml-cpp rejects: rare, so that most documents
    // exercise the reader.
    static const char* const kOthers[] = {"99999999999999999999",
                                          "\"\\x41\"",
                                          "`e`",
                                          "a: b",
                                          "&x a",
                                          "*x",
                                          "!str 3",
                                          "|",
                                          ">",
                                          "? a",
                                          "-",
                                          "[a",
                                          "{a",
                                          "'a",
                                          "\"a"};
    return chance(40) ? pick(kOthers) : pick(kScalars);
  }

  std::string key() {
    static const char* const kKeys[] = {"a",   "b",     "key_1", "x y", "~",    "null", "1",
                                        "'q'", "\"d\"", "-k",    "a#b", "a b ", "\"\"", "k"};
    std::string k = pick(kKeys);
    return chance(10) ? k : k + std::to_string(++keys_);  // now and then a duplicate
  }

  std::string flow(int depth) {
    if (depth > 2 || chance(3)) return scalar();
    std::string s;
    bool is_map = chance(2);
    s += is_map ? "{" : "[";
    int n = pick(4);
    for (int i = 0; i < n; ++i) {
      if (i > 0) s += chance(8) ? "," : ", ";
      if (chance(6)) s += lineBreakInFlow();
      if (is_map) {
        s += key() + (chance(20) ? ":" : ": ");
        if (!chance(5)) s += flow(depth + 1);
        if (chance(8)) s += " ";
      } else {
        s += flow(depth + 1);
      }
    }
    if (chance(40)) s += ", ";
    s += is_map ? "}" : "]";
    return s;
  }

  /// A line break inside a flow collection, now and then with a blank or comment line, at
  /// any indentation (the reader reads only lines deeper than the block around them).
  std::string lineBreakInFlow() {
    std::string s = "\n";
    if (chance(10)) s += "\n";
    if (chance(20)) s += "  # note\n";
    return s + std::string(pick(12), ' ');
  }

  void lineEnd() {
    if (chance(6)) out_ += "  ";
    if (chance(6)) out_ += " # comment";
    if (chance(300)) out_ += "\r";
    out_ += "\n";
    if (chance(8)) out_ += "\n";
    if (chance(20)) out_ += std::string(pick(8), ' ') + "# note\n";
  }

  std::string indent(int n) {
    if (chance(200)) return std::string(n, ' ') + "\t";
    return std::string(n + (chance(100) ? 1 : 0), ' ');
  }

  /// The rest of a line after `key:` or `-`, and the block that may follow it.
  void value(int col, int depth, bool in_map) {
    int kind = depth > 3 ? pick(2) : pick(6);
    if (kind == 2 && !in_map && !chance(10)) kind = 0;  // an empty item is left to yaml-cpp
    if (kind == 0) {
      out_ += (chance(40) ? "" : " ") + scalar();
      lineEnd();
    } else if (kind == 1) {
      out_ += " " + flow(0);
      lineEnd();
    } else if (kind == 2) {
      lineEnd();  // an empty value
    } else if (kind == 3 || kind == 4) {
      lineEnd();
      map(col + 2 + pick(2) * 2, depth + 1);
    } else {
      lineEnd();
      sequence(in_map && chance(2) ? col : col + 2, depth + 1);
    }
  }

  void map(int col, int depth) {
    int n = 1 + pick(4);
    for (int i = 0; i < n; ++i) {
      out_ += indent(col) + key() + ":";
      value(col, depth, true);
    }
  }

  void sequence(int col, int depth) {
    int n = 1 + pick(3);
    for (int i = 0; i < n; ++i) {
      out_ += indent(col) + "-";
      if (chance(3) && depth < 4) {
        int item_col = col + 2 + pick(2);
        out_ += std::string(item_col - col - 1, ' ') + key() + ":";
        value(item_col, depth + 1, true);
        if (chance(2)) {
          out_ += indent(item_col) + key() + ":";
          value(item_col, depth + 1, true);
        }
      } else {
        value(col, depth, false);
      }
    }
  }

  std::mt19937 rng_;
  std::string out_;
  int keys_ = 0;
};

}  // namespace

TEST_CASE("random block documents read as yaml-cpp reads them") {
  RandomYaml random(20261121);
  int read = 0;
  constexpr int kDocuments = 20000;
  for (int i = 0; i < kDocuments; ++i) {
    std::string text = random.document();
    INFO(text);
    smachac::test::YamlReaderComparison r = smachac::test::compareYamlReaders(text);
    if (!r.simple_read) continue;
    ++read;
    CHECK(r.reference_clean);
    CHECK(r.simple == r.reference);
  }
  INFO("the simple reader read " << read << " of " << kDocuments);
  CHECK(read * 6 >= kDocuments);  // the documents must exercise the reader, not only yaml-cpp
}
