// The generator's algorithm (SMACHA's) on small in-memory templates: blocks
// flow into buffers, containers replace their children's body, template globals persist to
// later states at their level and below, defined_headers is pre-seeded by the base, and
// template problems become located diagnostics.
#include "backends/generator/generator.h"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <utility>

#include "frontend/lower.h"

namespace smachac::generator {
namespace {

const std::vector<EmbeddedFile> kTemplates = {
    {"t/Base.tpl.py",
     "{%- set defined_headers = ['base_marker'] -%}\n"
     "I[{{ imports }}]B[{{ body }}]F[{{ footer }}]U[{{ header_userdata[name] }}]"
     "P[{{ previous }}]"},
    {"t/Leaf.tpl.py",
     "{% block imports %}{% if 'base_marker' in defined_headers %}seeded{% endif %} "
     "{{ name }}{% endblock imports %}"
     "{% block body %}{{ parent_type }}:{{ name }}:{{ previous | default('-') }}"
     "{% endblock body %}"
     "{% block footer %}f{{ name }}{% endblock footer %}"
     "{% block header_userdata %}ud_{{ name }}@{{ parent_sm_name }}{% endblock header_userdata %}"
     "{% set previous = name %}"},
    {"t/Box.tpl.py", "{% block body %}box {{ name }}({{ body | trim }}){% endblock body %}"},
    {"t/Bad.tpl.py", "{% block body %}{{ missing.attribute }}{% endblock body %}"},
    {"t/LateBad.tpl.py", "{% if body %}{{ missing.attribute }}{% endif %}"},
};

struct Run {
  std::optional<std::string> output;
  std::vector<std::string> messages;
};

/// `consume`: the generator takes the module (and frees it before the base render).
Run generateFrom(const std::string& script, bool consume = false) {
  SourceManager sources;
  DiagnosticEmitter diags;
  Run run;
  std::optional<ir::Module> module =
      frontend::lowerScriptText("test.yml", script, {}, sources, diags);
  REQUIRE(module.has_value());
  tmpl::Environment env({}, {"t/"}, kTemplates);
  ValueConverter converter;
  GeneratorContext context{env, converter, sources, diags, {{}, {"t/"}, kTemplates}, {}};
  run.output = consume ? generate(std::move(*module), context) : generate(*module, context);
  for (const Diagnostic& d : diags.diagnostics()) {
    run.messages.push_back(d.message);
    for (const DiagNote& note : d.notes) {
      run.messages.push_back(
          fmt::format("{}:{}: {}", note.loc.line, note.loc.column, note.message));
    }
  }
  return run;
}

TEST_CASE("blocks flow through buffers into the base; globals persist at their level") {
  Run run = generateFrom(
      "name: top\ntemplate: Base\noutcomes: [done]\nstates:\n"
      "  - A: {template: Leaf, transitions: {succeeded: BOX}}\n"
      "  - BOX:\n"
      "      template: Box\n"
      "      outcomes: [x]\n"
      "      transitions: {x: done}\n"
      "      states:\n"
      "        - B: {template: Leaf, transitions: {succeeded: x}}\n");
  REQUIRE(run.output.has_value());
  CHECK(*run.output ==
        "I[seeded A\n\nseeded B]"
        "B[StateMachine:A:-\n\nbox BOX(Box:B:A)]"
        "F[fB\n\n\nfA]"
        "U[ud_A@top]"
        "P[A]\n");
}

TEST_CASE("a generator that takes the module gives the same code") {
  const std::string script =
      "name: top\ntemplate: Base\noutcomes: [done]\nstates:\n"
      "  - A: {template: Leaf, transitions: {succeeded: B}}\n"
      "  - B: {template: Leaf, transitions: {succeeded: done}}\n";
  Run kept = generateFrom(script);
  Run taken = generateFrom(script, /*consume=*/true);
  REQUIRE(kept.output.has_value());
  CHECK(taken.output == kept.output);
}

TEST_CASE("an error of the base render, after the module is freed, notes the script's root") {
  Run run = generateFrom("name: top\ntemplate: LateBad\nstates:\n  - A: {template: Leaf}\n",
                         /*consume=*/true);
  CHECK_FALSE(run.output.has_value());
  REQUIRE(run.messages.size() == 2);
  CHECK(run.messages[0] == "`missing` is undefined");
  CHECK(run.messages[1] == "2:11: while rendering template `LateBad` for `top`");
}

TEST_CASE("an unknown template is reported at the script's template value") {
  Run run = generateFrom("name: top\ntemplate: Base\nstates:\n  - A: {template: Leef}\n");
  CHECK_FALSE(run.output.has_value());
  REQUIRE(run.messages.size() == 1);
  CHECK(run.messages[0] == "template `Leef` not found in built-in `t/`; did you mean `Leaf`?");
}

TEST_CASE("a template error is reported in the template, with a note at the state") {
  SourceManager sources;
  DiagnosticEmitter diags;
  std::optional<ir::Module> module = frontend::lowerScriptText(
      "test.yml",
      "name: top\ntemplate: Base\nstates:\n  - A: {template: Bad}\n  - B: {template: Bad}\n", {},
      sources, diags);
  REQUIRE(module.has_value());
  tmpl::Environment env({}, {"t/"}, kTemplates);
  ValueConverter converter;
  GeneratorContext context{env, converter, sources, diags, {{}, {"t/"}, kTemplates}, {}};
  CHECK_FALSE(generate(*module, context).has_value());
  REQUIRE(diags.diagnostics().size() == 1);  // the same error in two states: reported once
  const Diagnostic& d = diags.diagnostics()[0];
  CHECK(d.kind == DiagKind::TemplateError);
  CHECK(sources.path(d.loc.file) == "<builtin>/t/Bad.tpl.py");
  CHECK(d.loc.line == 1);
  REQUIRE(d.notes.size() == 1);
  CHECK(d.notes[0].message == "while rendering template `Bad` for `A`");
}

}  // namespace
}  // namespace smachac::generator
