// Attribute paths of filters (see attr_path.h).
#include "backends/tmpl/filters/attr_path.h"

#include "backends/tmpl/renderer/render.h"
#include "backends/tmpl/values/string_ops.h"
#include "ir/support/unicode.h"

namespace smachac::tmpl {

AttrPath::AttrPath(const Value& attribute) {
  if (attribute.isNone() || attribute.isUndefined()) return;
  if (!attribute.isString()) {
    parts_.push_back(attribute);
    return;
  }
  for (std::string& part : splitString(attribute.s(), &*intern("."), -1)) {
    bool digits = !part.empty() && part.size() <= 18 &&
                  part.find_first_not_of("0123456789") == std::string::npos;
    parts_.push_back(digits ? Value::integer(std::stoll(part)) : Value::string(std::move(part)));
  }
}

Value AttrPath::get(const Value& item) const {
  Value v = item;
  for (const Value& part : parts_) v = getItem(v, part);
  return v;
}

std::vector<AttrPath> multiAttrPath(const Value& attribute) {
  std::vector<AttrPath> paths;
  if (!attribute.isString()) {
    paths.emplace_back(attribute);
    return paths;
  }
  for (std::string& part : splitString(attribute.s(), &*intern(","), -1)) {
    paths.emplace_back(Value::string(std::move(part)));
  }
  return paths;
}

Value ignoreCase(const Value& v) {
  return v.isString() ? Value::string(unicode::toLower(v.s())) : v;
}

}  // namespace smachac::tmpl
