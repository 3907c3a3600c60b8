// Python semantics of values: truthiness, equality (1 == 1.0 == True), ordering (with
// TypeError-like faults for mixed types), hashing, arithmetic, `in`, iteration and length.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "backends/tmpl/values/value.h"

namespace smachac::tmpl {

enum class BinOp : uint8_t { Add, Sub, Mul, Div, FloorDiv, Mod, Pow };

/// Python's type name of the value (`int`, `str`, `list`, `NoneType`, `Undefined`, ...).
std::string_view typeName(const Value& v);
std::string_view kindName(Kind kind);

bool truthy(const Value& v);
bool equals(const Value& a, const Value& b);
/// Python's `a < b`; raises Fault for values that cannot be ordered.
bool lessThan(const Value& a, const Value& b);
/// Hash consistent with equals(); raises Fault for unhashable values.
size_t hashOf(const Value& v);

Value binary(BinOp op, const Value& a, const Value& b);
std::string_view binOpSymbol(BinOp op);
Value negate(const Value& v);
Value unaryPlus(const Value& v);

/// Python's `item in container`.
bool contains(const Value& container, const Value& item);

/// The items Python's iter() yields (chars of a str, keys of a dict, ...). Undefined yields
/// nothing; non-iterables raise Fault.
std::vector<Value> iterate(const Value& v);
bool isIterable(const Value& v);
/// Python's len(); raises Fault for values without a length.
int64_t length(const Value& v);

/// Python's int(x) for a float: truncation, Fault for inf/nan/out of range.
int64_t floatToInt(double d);

/// Raises Fault when a container or string would exceed the engine's size limits.
void checkSize(size_t n, std::string_view what);

/// RAII guard bounding the recursion of value operations (printing, comparing nested data).
class DepthGuard {
 public:
  DepthGuard();
  ~DepthGuard();
  DepthGuard(const DepthGuard&) = delete;
  DepthGuard& operator=(const DepthGuard&) = delete;
};

}  // namespace smachac::tmpl
