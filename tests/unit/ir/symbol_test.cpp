// Symbol (interned names) and Boxed (optional values on the heap).
#include "ir/symbol.h"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <thread>
#include <vector>

#include "ir/boxed.h"

namespace smachac::ir {
namespace {

TEST_CASE("symbols of the same text share it; symbols compare and order by text") {
  std::string built = std::string("SUC") + "CEEDED";
  Symbol a("SUCCEEDED");
  Symbol b(built);
  CHECK(&a.str() == &b.str());
  CHECK(a == b);
  CHECK(a == "SUCCEEDED");
  CHECK(a == std::string("SUCCEEDED"));
  CHECK_FALSE(a == Symbol("SUCCEEDE"));
  CHECK(Symbol() == Symbol(""));
  CHECK(Symbol().empty());
  std::vector<Symbol> names{"b", "a", "ab"};
  std::sort(names.begin(), names.end());
  CHECK(names == std::vector<Symbol>{"a", "ab", "b"});
}

TEST_CASE("a symbol reads as a string") {
  Symbol s("pick_arm");
  CHECK(s.size() == 8);
  CHECK(s + "_goal" == "pick_arm_goal");
  CHECK("sm_" + s == "sm_pick_arm");
  CHECK(fmt::format("[{:>10}]", s) == "[  pick_arm]");
  const std::string& text = s;
  CHECK(text == "pick_arm");
}

TEST_CASE("threads interning the same names get the same symbols") {
  std::vector<const std::string*> seen(4);
  std::vector<std::thread> threads;
  for (size_t t = 0; t < seen.size(); ++t) {
    threads.emplace_back([t, &seen] {
      for (int i = 0; i < 2000; ++i) Symbol(fmt::format("state_{}", i));
      seen[t] = &Symbol("state_1999").str();
    });
  }
  for (std::thread& thread : threads) thread.join();
  CHECK(std::count(seen.begin(), seen.end(), seen[0]) == 4);
}

TEST_CASE("texts sharing a thread's recent slots still intern to their own symbols") {
  // Far more texts than the recent slots, each interned again after all the others pushed it
  // out, and again at once: the same symbol every time, with its own text.
  std::vector<std::string> texts;
  for (int i = 0; i < 2000; ++i) texts.push_back(fmt::format("recent_{}", i));
  std::vector<Symbol> first(texts.begin(), texts.end());
  for (size_t i = 0; i < texts.size(); ++i) {
    Symbol again(texts[i]);
    Symbol at_once(texts[i]);
    CHECK(again == first[i]);
    CHECK(at_once.data() == first[i].data());
    CHECK(again.str() == texts[i]);
  }
}

TEST_CASE("a boxed value copies deeply and tests like an optional") {
  Boxed<std::string> none;
  CHECK_FALSE(none);
  CHECK_FALSE(none.copy().has_value());
  Boxed<std::string> one(std::string("params"));
  Boxed<std::string> copied = one;
  *copied += "!";
  CHECK(*one == "params");
  CHECK(*copied == "params!");
  CHECK(copied->size() == 7);
  copied = none;
  CHECK_FALSE(copied);
  CHECK(one.copy() == std::optional<std::string>("params"));
}

}  // namespace
}  // namespace smachac::ir
