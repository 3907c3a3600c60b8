// yaml-cpp events → YamlValueBuilder, behind the simple reader.
#include "frontend/yaml_events.h"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/exceptions.h>
#include <yaml-cpp/parser.h>

#include <algorithm>
#include <sstream>

#include "frontend/simple_yaml_reader.h"
#include "frontend/yaml_syntax_hints.h"

namespace smachac::frontend {
namespace {

YamlMark yamlMark(const YAML::Mark& mark) {
  if (mark.is_null()) return {};
  return {mark.line, mark.column};
}

/// Forwards yaml-cpp's parse events to the builder.
class YamlCppEvents : public YAML::EventHandler {
 public:
  explicit YamlCppEvents(YamlValueBuilder& builder) : builder_(builder) {}

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    builder_.onNull(yamlMark(mark), anchor);
  }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    builder_.onAlias(yamlMark(mark), anchor);
  }
  void OnScalar(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                const std::string& value) override {
    builder_.onScalar(yamlMark(mark), tag, anchor, value);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    builder_.onSequenceStart(yamlMark(mark), anchor);
  }
  void OnSequenceEnd() override { builder_.onCollectionEnd(); }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    builder_.onMapStart(yamlMark(mark), anchor);
  }
  void OnMapEnd() override { builder_.onCollectionEnd(); }

 private:
  YamlValueBuilder& builder_;
};

/// Ignores a document's events but where it starts.
class DocumentStart : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark& mark) override { mark_ = mark; }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
  const YAML::Mark& mark() const { return mark_; }

 private:
  YAML::Mark mark_ = YAML::Mark::null_mark();
};

SourceLoc markLoc(uint32_t file, const YAML::Mark& mark) {
  if (mark.is_null()) return {file, 0, 0, 1};
  return {file, static_cast<uint32_t>(std::max(mark.line, 0) + 1),
          static_cast<uint32_t>(std::max(mark.column, 0) + 1), 1};
}

}  // namespace

std::optional<ir::Value> buildYamlValueWithYamlCpp(uint32_t file, std::string_view text,
                                                   DiagnosticEmitter& diags) {
  std::istringstream stream{std::string(text)};
  YamlValueBuilder builder(file, diags, YamlProblems::Report, text);
  YamlCppEvents events(builder);
  try {
    YAML::Parser parser(stream);
    parser.HandleNextDocument(events);
    DocumentStart second;
    if (parser.HandleNextDocument(second)) {
      diags.emit<DiagKind::MultipleDocuments>(markLoc(file, second.mark()));
      return std::nullopt;
    }
  } catch (const YAML::DeepRecursion& e) {
    diags.emit<DiagKind::YamlTooComplex>(markLoc(file, e.mark),
                                         Numbered<YamlLimit>{YamlLimit::ParserDepth});
    return std::nullopt;
  } catch (const YAML::Exception& e) {
    diags.emit<DiagKind::YamlSyntax>(markLoc(file, e.mark), ForeignMessage(e.msg));
    if (std::optional<YamlSyntaxHint> hint = yamlSyntaxHint(e.msg)) {
      diags.note<DiagNoteKind::LikelyYamlMistake>(markLoc(file, e.mark), *hint);
    }
    return std::nullopt;
  }
  std::optional<ir::Value> root = builder.take();
  if (!root && !builder.aborted()) return ir::Value::null({file, 1, 1, 1});
  return root;
}

std::optional<ir::Value> buildYamlValue(uint32_t file, std::string_view text,
                                        DiagnosticEmitter& diags) {
  if (std::optional<ir::Value> simple = readSimpleYaml(file, text)) return simple;
  return buildYamlValueWithYamlCpp(file, text, diags);
}

}  // namespace smachac::frontend
