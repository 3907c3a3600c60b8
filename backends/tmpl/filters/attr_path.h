// Jinja2's attribute getters for filters (`sort(attribute='a.b')`, `map(attribute=...)`):
// dotted paths, integer parts as indices, and comma-separated lists of paths.
#pragma once

#include <vector>

#include "backends/tmpl/values/value.h"

namespace smachac::tmpl {

class AttrPath {
 public:
  AttrPath() = default;
  /// `attribute` is a string path, an integer index, or none (identity).
  explicit AttrPath(const Value& attribute);
  Value get(const Value& item) const;
  bool empty() const { return parts_.empty(); }

 private:
  std::vector<Value> parts_;
};

/// A comma-separated list of paths (Jinja's make_multi_attrgetter).
std::vector<AttrPath> multiAttrPath(const Value& attribute);

/// Jinja's ignore_case postprocessor: strings lowercased, other values unchanged.
Value ignoreCase(const Value& v);

}  // namespace smachac::tmpl
