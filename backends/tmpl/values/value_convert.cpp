// JSON (nlohmann) and YAML (yaml-cpp, YAML 1.2 core schema) to Value conversion.
#include "backends/tmpl/values/value_convert.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>

#include "backends/tmpl/error.h"
#include "backends/tmpl/values/value_ops.h"

namespace smachac::tmpl {
namespace {

constexpr int kMaxDepth = 200;

std::pair<int, int> lineColumnAt(std::string_view text, size_t offset) {
  int line = 1;
  int column = 1;
  for (size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {
      ++column;
    }
  }
  return {line, column};
}

Value fromJson(const nlohmann::ordered_json& j) {
  switch (j.type()) {
    case nlohmann::ordered_json::value_t::null:
      return Value::none();
    case nlohmann::ordered_json::value_t::boolean:
      return Value::boolean(j.get<bool>());
    case nlohmann::ordered_json::value_t::number_integer:
      return Value::integer(j.get<int64_t>());
    case nlohmann::ordered_json::value_t::number_unsigned: {
      auto u = j.get<uint64_t>();
      if (u > static_cast<uint64_t>(INT64_MAX)) fail("integer out of range");
      return Value::integer(static_cast<int64_t>(u));
    }
    case nlohmann::ordered_json::value_t::number_float:
      return Value::real(j.get<double>());
    case nlohmann::ordered_json::value_t::string:
      return Value::string(j.get<std::string>());
    case nlohmann::ordered_json::value_t::array: {
      std::vector<Value> items;
      for (const auto& item : j) items.push_back(fromJson(item));
      return Value::newList(std::move(items));
    }
    case nlohmann::ordered_json::value_t::object: {
      Value dict = Value::newDict();
      for (const auto& [k, v] : j.items()) dict.dict().setString(k, fromJson(v));
      return dict;
    }
    default:
      fail("unsupported JSON value");
  }
}

bool allOf(std::string_view s, bool (*pred)(char)) {
  return !s.empty() && std::all_of(s.begin(), s.end(), pred);
}
bool isDec(char c) { return c >= '0' && c <= '9'; }
bool isOct(char c) { return c >= '0' && c <= '7'; }
bool isHex(char c) { return isDec(c) || ((c | 0x20) >= 'a' && (c | 0x20) <= 'f'); }

std::string_view withoutSign(std::string_view s) {
  return !s.empty() && (s[0] == '-' || s[0] == '+') ? s.substr(1) : s;
}

// [-+]?(\.[0-9]+|[0-9]+(\.[0-9]*)?)([eE][-+]?[0-9]+)?
bool isCoreFloat(std::string_view s) {
  s = withoutSign(s);
  size_t e = s.find_first_of("eE");
  std::string_view mantissa = s.substr(0, e);
  if (e != std::string_view::npos && !allOf(withoutSign(s.substr(e + 1)), isDec)) return false;
  size_t dot = mantissa.find('.');
  if (dot == std::string_view::npos) return allOf(mantissa, isDec);
  std::string_view whole = mantissa.substr(0, dot);
  std::string_view fraction = mantissa.substr(dot + 1);
  if (whole.empty()) return allOf(fraction, isDec);
  return allOf(whole, isDec) && (fraction.empty() || allOf(fraction, isDec));
}

Value integerScalar(const std::string& s, int base, size_t skip) {
  bool negative = !s.empty() && s[0] == '-';
  size_t start = (s[0] == '-' || s[0] == '+') ? 1 : 0;
  int64_t v = 0;
  auto result = std::from_chars(s.data() + start + skip, s.data() + s.size(), v, base);
  if (result.ec != std::errc()) fail("integer `" + s + "` out of range");
  return Value::integer(negative ? -v : v);
}

// YAML 1.2 core schema resolution of a plain scalar.
Value plainScalar(const std::string& s) {
  if (s.empty() || s == "~" || s == "null" || s == "Null" || s == "NULL") return Value::none();
  if (s == "true" || s == "True" || s == "TRUE") return Value::boolean(true);
  if (s == "false" || s == "False" || s == "FALSE") return Value::boolean(false);
  std::string_view body = withoutSign(s);
  if (allOf(body, isDec)) return integerScalar(s, 10, 0);
  if (s.size() > 2 && s.compare(0, 2, "0o") == 0 && allOf(std::string_view(s).substr(2), isOct)) {
    return integerScalar(s, 8, 2);
  }
  if (s.size() > 2 && s.compare(0, 2, "0x") == 0 && allOf(std::string_view(s).substr(2), isHex)) {
    return integerScalar(s, 16, 2);
  }
  if (isCoreFloat(s)) return Value::real(std::strtod(s.c_str(), nullptr));
  if (body == ".inf" || body == ".Inf" || body == ".INF")
    return Value::real(s[0] == '-' ? -HUGE_VAL : HUGE_VAL);
  if (s == ".nan" || s == ".NaN" || s == ".NAN") return Value::real(std::nan(""));
  return Value::string(s);
}

Value scalar(const YAML::Node& node) {
  const std::string& text = node.Scalar();
  const std::string& tag = node.Tag();
  if (tag == "?") return plainScalar(text);
  if (tag == "!" || tag == "tag:yaml.org,2002:str") return Value::string(text);
  Value resolved = plainScalar(text);
  if (tag == "tag:yaml.org,2002:int" && !resolved.isInt()) fail("`" + text + "` is not an int");
  if (tag == "tag:yaml.org,2002:float" && resolved.isInt()) return Value::real(resolved.number());
  if (tag == "tag:yaml.org,2002:float" && !resolved.isFloat())
    fail("`" + text + "` is not a float");
  if (tag == "tag:yaml.org,2002:bool" && !resolved.isBool()) fail("`" + text + "` is not a bool");
  if (tag == "tag:yaml.org,2002:null" && !resolved.isNone()) fail("`" + text + "` is not null");
  return resolved;
}

Value fromYaml(const YAML::Node& node, int depth) {
  if (depth > kMaxDepth)
    fail("the document is nested too deeply (limit " + std::to_string(kMaxDepth) + ")");
  switch (node.Type()) {
    case YAML::NodeType::Undefined:
    case YAML::NodeType::Null:
      return Value::none();
    case YAML::NodeType::Scalar:
      return scalar(node);
    case YAML::NodeType::Sequence: {
      std::vector<Value> items;
      for (const auto& item : node) items.push_back(fromYaml(item, depth + 1));
      return Value::newList(std::move(items));
    }
    case YAML::NodeType::Map: {
      Value dict = Value::newDict();
      for (const auto& entry : node) {
        Value key = fromYaml(entry.first, depth + 1);
        if (dict.dict().find(key))
          fail("duplicate key " + std::string(key.isString() ? key.s() : "in a mapping"));
        dict.dict().set(key, fromYaml(entry.second, depth + 1));
      }
      return dict;
    }
  }
  return Value::none();
}

}  // namespace

Value parseJson(std::string_view text, std::string_view origin) {
  try {
    auto limit_depth = [](int depth, nlohmann::ordered_json::parse_event_t,
                          nlohmann::ordered_json&) {
      if (depth > kMaxDepth) throw Fault("the document is nested too deeply");
      return true;
    };
    return fromJson(nlohmann::ordered_json::parse(text.begin(), text.end(), limit_depth));
  } catch (const nlohmann::ordered_json::parse_error& e) {
    auto [line, column] = lineColumnAt(text, e.byte > 0 ? e.byte - 1 : 0);
    std::string message = e.what();
    size_t colon = message.rfind(": ");
    throw TemplateError(
        std::string(origin), line, column,
        "invalid JSON: " + (colon == std::string::npos ? message : message.substr(colon + 2)));
  } catch (const Fault& f) {
    throw TemplateError(std::string(origin), 0, 0, f.message());
  }
}

Value parseYaml(std::string_view text, std::string_view origin) {
  try {
    return fromYaml(YAML::Load(std::string(text)), 0);
  } catch (const YAML::Exception& e) {
    throw TemplateError(std::string(origin), e.mark.line + 1, e.mark.column + 1,
                        "invalid YAML: " + e.msg);
  } catch (const Fault& f) {
    throw TemplateError(std::string(origin), 0, 0, f.message());
  }
}

Value valueFromYaml(const YAML::Node& node) { return fromYaml(node, 0); }

}  // namespace smachac::tmpl
