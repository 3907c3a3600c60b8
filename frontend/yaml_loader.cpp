// YAML file → ir::Value with locations, on yaml-cpp.
#include "frontend/yaml_loader.h"

#include <fmt/core.h>
#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "frontend/scalar.h"
#include "ir/support/utf8.h"

namespace smachac::frontend {
namespace {

namespace fs = std::filesystem;

class Converter {
 public:
  Converter(uint32_t file, DiagnosticEmitter& diags) : file_(file), diags_(diags) {}

  std::optional<ir::Value> convert(const YAML::Node& node) {
    ir::Value v = value(node, 0);
    if (aborted_) return std::nullopt;
    return v;
  }

 private:
  SourceLoc loc(const YAML::Mark& mark, size_t length = 1) const {
    if (mark.is_null()) return {file_, 1, 1, 1};
    return {file_, static_cast<uint32_t>(mark.line + 1), static_cast<uint32_t>(mark.column + 1),
            static_cast<uint32_t>(std::max<size_t>(length, 1))};
  }

  bool budget(const YAML::Node& node, size_t depth) {
    if (aborted_) return false;
    if (depth > kMaxYamlDepth) {
      diags_.emit(DiagKind::YamlTooComplex, loc(node.Mark()),
                  fmt::format("YAML nested more than {} levels deep", kMaxYamlDepth));
      aborted_ = true;
    } else if (++nodes_ > kMaxYamlNodes) {
      diags_.emit(DiagKind::YamlTooComplex, loc(node.Mark()),
                  fmt::format("YAML document expands to more than {} nodes (aliases included)",
                              kMaxYamlNodes));
      aborted_ = true;
    }
    return !aborted_;
  }

  ir::Value scalar(const YAML::Node& node) {
    const std::string& text = node.Scalar();
    bool quoted = node.Tag() == "!";
    SourceLoc l = loc(node.Mark(), text.size() + (quoted ? 2 : 0));
    ScalarResult r =
        resolveScalar(text, quoted ? ScalarStyle::Quoted : ScalarStyle::Plain, node.Tag(), l);
    if (r.int_overflow) diags_.emit(DiagKind::IntegerOutOfRange, l, text);
    return std::move(r.value);
  }

  ir::Value sequence(const YAML::Node& node, size_t depth) {
    ir::List items;
    items.reserve(node.size());
    for (const YAML::Node& item : node) {
      items.push_back(value(item, depth + 1));
      if (aborted_) break;
    }
    return ir::Value::list(std::move(items), loc(node.Mark()));
  }

  ir::Value mapping(const YAML::Node& node, size_t depth) {
    ir::Map entries;
    entries.reserve(node.size());
    for (const auto& pair : node) {
      const YAML::Node& key = pair.first;
      if (!key.IsScalar() && !key.IsNull()) {
        diags_.emit(DiagKind::NonScalarKey, loc(key.Mark()),
                    key.IsMap() ? "a mapping" : "a sequence");
        continue;
      }
      std::string text = key.IsScalar() ? key.Scalar() : "";
      SourceLoc key_loc = loc(key.Mark(), text.size());
      if (const ir::MapEntry* first = findEntry(entries, text)) {
        diags_.emit(DiagKind::DuplicateKey, key_loc, text);
        diags_.note(first->key_loc, "first defined here");
        continue;
      }
      ir::Value v = value(pair.second, depth + 1);
      if (aborted_) break;
      if (pair.second.IsNull() && pair.second.Scalar().empty()) v.loc = key_loc;
      entries.push_back({std::move(text), key_loc, std::move(v)});
    }
    return ir::Value::map(std::move(entries), loc(node.Mark()));
  }

  static const ir::MapEntry* findEntry(const ir::Map& entries, const std::string& key) {
    for (const ir::MapEntry& e : entries) {
      if (e.key == key) return &e;
    }
    return nullptr;
  }

  ir::Value value(const YAML::Node& node, size_t depth) {
    if (!budget(node, depth)) return ir::Value::null();
    switch (node.Type()) {
      case YAML::NodeType::Scalar:
        return scalar(node);
      case YAML::NodeType::Sequence:
        return sequence(node, depth);
      case YAML::NodeType::Map:
        return mapping(node, depth);
      case YAML::NodeType::Null:
      case YAML::NodeType::Undefined:
        break;
    }
    if (node.Tag() == "!str" || node.Tag() == "tag:yaml.org,2002:str") {
      return resolveScalar("", ScalarStyle::Plain, node.Tag(), loc(node.Mark())).value;
    }
    return ir::Value::null(loc(node.Mark()));
  }

  uint32_t file_;
  DiagnosticEmitter& diags_;
  size_t nodes_ = 0;
  bool aborted_ = false;
};

std::optional<std::string> readRegularFile(const std::string& path, SourceLoc from,
                                           DiagnosticEmitter& diags) {
  std::error_code ec;
  fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) {
    diags.emit(DiagKind::FileNotFound, from, path, "no such file");
    return std::nullopt;
  }
  if (!fs::is_regular_file(status)) {
    diags.emit(DiagKind::FileNotFound, from, path,
               fs::is_directory(status) ? "it is a directory" : "it is not a regular file");
    return std::nullopt;
  }
  uintmax_t size = fs::file_size(path, ec);
  if (!ec && size > kMaxScriptBytes) {
    diags.emit(DiagKind::FileTooLarge, from, path, size, kMaxScriptBytes);
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    diags.emit(DiagKind::FileNotFound, from, path, "permission denied or unreadable");
    return std::nullopt;
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return std::move(buffer).str();
}

}  // namespace

std::optional<ir::Value> parseYaml(uint32_t file, const SourceManager& sources,
                                   DiagnosticEmitter& diags) {
  std::string_view text = sources.content(file);
  if (std::optional<size_t> bad = findInvalidUtf8(text)) {
    bool nul = text[*bad] == '\0';
    diags.emit(DiagKind::InvalidEncoding, sources.locOf(file, *bad),
               nul ? "NUL byte in YAML text" : "invalid UTF-8 byte sequence");
    return std::nullopt;
  }
  YAML::Node root;
  try {
    root = YAML::Load(std::string(text));
  } catch (const YAML::DeepRecursion& e) {
    diags.emit(DiagKind::YamlTooComplex,
               SourceLoc{file, static_cast<uint32_t>(std::max(e.mark.line, 0) + 1),
                         static_cast<uint32_t>(std::max(e.mark.column, 0) + 1), 1},
               "YAML nested too deeply for the parser");
    return std::nullopt;
  } catch (const YAML::Exception& e) {
    SourceLoc l{file, static_cast<uint32_t>(std::max(e.mark.line, 0) + 1),
                static_cast<uint32_t>(std::max(e.mark.column, 0) + 1), 1};
    if (e.mark.is_null()) l = {file, 0, 0, 1};
    diags.emit(DiagKind::YamlSyntax, l, e.msg);
    return std::nullopt;
  }
  return Converter(file, diags).convert(root);
}

LoadedYaml loadYamlFile(const std::string& path, SourceLoc from, SourceManager& sources,
                        DiagnosticEmitter& diags) {
  std::optional<std::string> text = readRegularFile(path, from, diags);
  if (!text) return {};
  uint32_t file = sources.addFile(path, std::move(*text));
  return {file, parseYaml(file, sources, diags)};
}

}  // namespace smachac::frontend
