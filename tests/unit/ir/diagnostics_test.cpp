// Diagnostic emission, -W options and the text printer.
#include <doctest/doctest.h>

#include "ir/support/diagnostic_emitter.h"
#include "ir/support/diagnostic_printer.h"

using smachac::DiagKind;
using smachac::Severity;

TEST_CASE("messages are formatted from the registry") {
  smachac::DiagnosticEmitter diags;
  smachac::SourceManager sources;
  uint32_t f = sources.addFile("s.yml", "name: x\n  key: value\n");
  diags.emit<DiagKind::DuplicateKey>({f, 2, 3, 3}, "key");
  diags.note<smachac::DiagNoteKind::FirstDefinedHere>({f, 1, 1, 4});
  REQUIRE(diags.diagnostics().size() == 1);
  CHECK(diags.hasErrors());
  CHECK(smachac::formatDiagnosticText(diags.diagnostics()[0], sources) ==
        "s.yml:2:3: error: duplicate key `key` [duplicate-key]\n"
        "  key: value\n"
        "  ^~~\n"
        "s.yml:1:1: note: first defined here\n"
        "name: x\n"
        "^~~~\n");
}

TEST_CASE("carets follow tabs and multi-byte characters") {
  smachac::DiagnosticEmitter diags;
  smachac::SourceManager sources;
  uint32_t f = sources.addFile("s.yml", "\tcafé: OPNE\n");
  diags.emit<DiagKind::YamlSyntax>({f, 1, 9, 4}, smachac::ForeignMessage("something"));
  CHECK(smachac::formatDiagnosticText(diags.diagnostics()[0], sources) ==
        "s.yml:1:9: error: something [yaml-syntax]\n\tcafé: OPNE\n\t      ^~~~\n");
}

TEST_CASE("warning options") {
  smachac::WarningOptions options;
  CHECK(options.severityOf(DiagKind::UnknownRootKey) == Severity::Warning);
  CHECK_FALSE(options.apply("-Wno-unknown-root-key").has_value());
  CHECK(options.severityOf(DiagKind::UnknownRootKey) == Severity::Ignored);
  CHECK_FALSE(options.apply("-Werror").has_value());
  CHECK(options.severityOf(DiagKind::StatesWithScript) == Severity::Error);
  CHECK_FALSE(options.apply("-Wno-error=states-with-script").has_value());
  CHECK(options.severityOf(DiagKind::StatesWithScript) == Severity::Warning);
  CHECK_FALSE(options.apply("-Wno-duplicate-key").has_value());
  CHECK(options.severityOf(DiagKind::DuplicateKey) == Severity::Error);  // errors stay errors
  CHECK(*options.apply("-Wunknown-rot-key") ==
        "unknown diagnostic kind `unknown-rot-key` in -W flag; did you mean `unknown-root-key`?");
}

TEST_CASE("warning groups: -Wall, -Wextra, -Weverything") {
  smachac::WarningOptions options;
  CHECK_FALSE(options.apply("-Wno-unknown-root-key").has_value());
  CHECK_FALSE(options.apply("-Wall").has_value());  // the later flag wins, as in clang
  CHECK(options.severityOf(DiagKind::UnknownRootKey) == Severity::Warning);
  CHECK_FALSE(options.apply("-Wno-everything").has_value());
  CHECK(options.severityOf(DiagKind::UnusedUserdataKey) == Severity::Ignored);
  CHECK(options.severityOf(DiagKind::DuplicateKey) == Severity::Error);
  CHECK_FALSE(options.apply("-Werror=extra").has_value());
  CHECK(options.severityOf(DiagKind::UnusedUserdataKey) == Severity::Error);
  CHECK(options.severityOf(DiagKind::UnknownTransitionTarget) == Severity::Error);
  CHECK(smachac::warningGroupNames() == std::vector<std::string>{"all", "extra", "everything"});
}

TEST_CASE("an unknown -W name lists the close ones") {
  smachac::WarningOptions options;
  CHECK(*options.apply("-Wal") == "unknown diagnostic kind `al` in -W flag; did you mean `all`?");
  CHECK(*options.apply("-Wno-unknown-root-sta") ==
        "unknown diagnostic kind `unknown-root-sta` in -W flag; did you mean one of "
        "`unknown-root-state`, `unknown-root-key`?");
  CHECK(*options.apply("-Wunknown-root") ==
        "unknown diagnostic kind `unknown-root` in -W flag; did you mean one of "
        "`unknown-root-key`, `unknown-root-state`?");
  CHECK(*options.apply("-Wwhatever-this-is") ==
        "unknown diagnostic kind `whatever-this-is` in -W flag; `smachac --list-warnings` lists "
        "them");
}

TEST_CASE("silenced diagnostics drop their notes") {
  smachac::WarningOptions options;
  CHECK_FALSE(options.apply("-Wno-unknown-root-key").has_value());
  smachac::DiagnosticEmitter diags(options);
  diags.emit<DiagKind::UnknownRootKey>({}, "x", "");
  diags.note<smachac::DiagNoteKind::FirstDefinedHere>({});
  CHECK(diags.diagnostics().empty());
  CHECK(diags.warningCount() == 0);
}

TEST_CASE("notes are formatted from the registry, with their arguments") {
  smachac::DiagnosticEmitter diags;
  diags.emit<DiagKind::SubScriptNotFound>({}, "sub");
  diags.note<smachac::DiagNoteKind::LookedFor>({}, std::string("sub.yml"));
  diags.note<smachac::DiagNoteKind::WhileRenderingTemplate>({}, "T", "S");
  REQUIRE(diags.diagnostics().size() == 1);
  const std::vector<smachac::DiagNote>& notes = diags.diagnostics()[0].notes;
  REQUIRE(notes.size() == 2);
  CHECK(notes[0].message == "looked for `sub.yml`");
  CHECK(notes[1].message == "while rendering template `T` for `S`");
  CHECK(smachac::makeNote<smachac::DiagNoteKind::IncludedFromHere>({}).message ==
        "included from here");
}

TEST_CASE("choices print their registry text; a numbered one fills in its number") {
  smachac::DiagnosticEmitter diags;
  diags.emit<DiagKind::YamlTooComplex>({}, smachac::Numbered{smachac::YamlLimit::Depth, 1000});
  diags.emit<DiagKind::YamlTooComplex>({}, smachac::Numbered{smachac::YamlLimit::ParserDepth, 7});
  diags.note<smachac::DiagNoteKind::LikelyYamlMistake>({}, smachac::YamlSyntaxHint::CloseMapping);
  diags.emit<DiagKind::InvalidEncoding>({}, smachac::EncodingProblem::NulByte);
  REQUIRE(diags.diagnostics().size() == 3);
  CHECK(diags.diagnostics()[0].message == "YAML nested more than 1000 levels deep");
  CHECK(diags.diagnostics()[1].message == "YAML nested too deeply for the parser");
  CHECK(diags.diagnostics()[1].notes[0].message ==
        "a `{` mapping is not closed: add its `}`, also when the mapping spans several lines");
  CHECK(diags.diagnostics()[2].message == "NUL byte in YAML text");
}
