// Value: construction from C++ values, checked conversions and their messages, Python text.
#include <doctest/doctest.h>

#include "smachac/runtime/errors.h"
#include "smachac/runtime/value.h"

namespace rt = smachac::runtime;
using rt::List;
using rt::Map;
using rt::Value;
using rt::ValueType;

TEST_CASE("values keep the type they were made from") {
  CHECK(Value().type() == ValueType::Null);
  CHECK(Value(true).type() == ValueType::Bool);
  CHECK(Value(3).type() == ValueType::Int);
  CHECK(Value(int64_t{1} << 40).as<int64_t>() == int64_t{1} << 40);
  CHECK(Value(2.5).type() == ValueType::Double);
  CHECK(Value("abc").type() == ValueType::String);
  CHECK(Value(std::string("abc")).as<std::string>() == "abc");
  CHECK(Value(List{1, 2.5, "x"}).list().size() == 3);
  CHECK(Value(Map{{"a", 1}}).map().at("a") == Value(1));
  Value nested = std::vector<std::vector<double>>{{0.0, 0.0, 0.15}, {1.0}};
  CHECK(nested.as<std::vector<std::vector<double>>>()[0][2] == 0.15);
}

TEST_CASE("checked conversions") {
  CHECK(Value(3).as<double>() == 3.0);
  CHECK(Value(7).as<int>() == 7);
  CHECK(Value(List{"a", "b"}).as<std::vector<std::string>>() == std::vector<std::string>{"a", "b"});
  CHECK(Value(List{1, 2}).as<std::vector<int64_t>>() == std::vector<int64_t>{1, 2});
  CHECK_THROWS_WITH_AS(Value("x").as<double>(), "expected a double, got a string", rt::TypeError);
  CHECK_THROWS_WITH_AS(Value(1.5).as<int64_t>(), "expected an int, got a double", rt::TypeError);
  CHECK_THROWS_WITH_AS(Value().as<bool>(), "expected a bool, got null", rt::TypeError);
  CHECK_THROWS_WITH_AS(Value(List{1.0, "b"}).as<std::vector<double>>(),
                       "expected a list of doubles, got a list with a string at index 1",
                       rt::TypeError);
  CHECK_THROWS_WITH_AS(Value(int64_t{1} << 40).as<int>(),
                       "expected a 32-bit int, got an int out of range (1099511627776)",
                       rt::TypeError);
  CHECK_THROWS_WITH_AS(Value(1).map(), "expected a map, got an int", rt::TypeError);
}

TEST_CASE("truthiness follows Python") {
  CHECK_FALSE(Value().truthy());
  CHECK_FALSE(Value(0).truthy());
  CHECK_FALSE(Value(0.0).truthy());
  CHECK_FALSE(Value("").truthy());
  CHECK_FALSE(Value(List{}).truthy());
  CHECK(Value(List{0}).truthy());
  CHECK(Value("no").truthy());
  CHECK(Value(-1).truthy());
}

TEST_CASE("str and repr spell values as Python does") {
  CHECK(Value(1.0).repr() == "1.0");
  CHECK(Value(0.1).repr() == "0.1");
  CHECK(Value(100000.0).repr() == "100000.0");
  CHECK(Value(1e16).repr() == "1e+16");
  CHECK(Value(1.5e-5).repr() == "1.5e-05");
  CHECK(Value(0.0001).repr() == "0.0001");
  CHECK(Value(-2.5).repr() == "-2.5");
  CHECK(Value(true).repr() == "True");
  CHECK(Value().repr() == "None");
  CHECK(Value("it's").repr() == "\"it's\"");
  CHECK(Value("cats").str() == "cats");
  CHECK(Value(List{"cats", 1, 0.15, List{}}).str() == "['cats', 1, 0.15, []]");
  CHECK(Value(Map{{"b", false}, {"a", 1}}).str() == "{'a': 1, 'b': False}");
}

TEST_CASE("equality compares contents") {
  CHECK(Value(List{1, "a"}) == Value(List{1, "a"}));
  CHECK_FALSE(Value(1) == Value(1.0));
  CHECK_FALSE(Value(List{1}) == Value(List{2}));
}
