// Template outlines and shapes: which templates the analysis covers, which blocks it proves
// empty, and when a template cannot export anything.
#include "backends/generator/template_shape.h"

#include <doctest/doctest.h>

namespace smachac::generator {
namespace {

TEST_CASE("a simple template: blocks, extends, imports, sets") {
  TemplateOutline o = outlineTemplate(
      "{% block meta %}\nname: X\n{% endblock meta %}\n"
      "{% from \"Utils.tpl.py\" import a, b %}\n{% extends \"State.tpl.py\" %}\n"
      "{# a comment with {% tags %} #}\n"
      "{% block imports %}\n  \n{% endblock imports %}\n"
      "{%- block body -%}{{ super() }}{%- endblock body %}\n");
  CHECK(o.simple);
  CHECK(o.parent == "State.tpl.py");
  CHECK_FALSE(o.has_set_or_macro);
  CHECK(o.blocks.at("meta") == false);
  CHECK(o.blocks.at("imports") == true);
  CHECK(o.blocks.at("body") == false);
}

TEST_CASE("top-level sets and macros may export; tags in strings do not confuse the scanner") {
  TemplateOutline o = outlineTemplate(
      "{% set x = '%}' %}{% macro m(a) %}{% if a %}{{ a }}{% endif %}{% endmacro %}"
      "{% block b %}{% endblock %}");
  CHECK(o.simple);
  CHECK(o.has_set_or_macro);
  CHECK(o.blocks.at("b") == true);
}

TEST_CASE("templates outside the simple subset get no outline") {
  for (const char* source : {
           "text outside blocks",
           "{{ output }}",
           "{% include \"X\" %}",
           "{% if x %}{% set y = 1 %}{% endif %}",
           "{% do list.append(1) %}",
           "{% extends name %}",
           "{% block a %}{% block b %}{% endblock %}{% endblock %}",
           "{% block a %}{% raw %}{% endblock %}{% endraw %}{% endblock %}",
           "{% set x %}block set{% endset %}",
           "{% block a %}unterminated",
           "{{ unterminated",
       }) {
    CAPTURE(source);
    CHECK_FALSE(outlineTemplate(source).simple);
  }
}

TEST_CASE("a chain's shape: the root's layout, the most derived definitions") {
  std::vector<EmbeddedFile> files = {
      {"t/Root.tpl.py", "{% block a %}A{% endblock %}{% block b %}{% endblock %}"},
      {"t/Child.tpl.py",
       "{% extends \"Root.tpl.py\" %}{% block b %}B{% endblock %}{% block a %} {% endblock %}"
       "{% block c %}C{% endblock %}"},
      {"t/Exporting.tpl.py", "{% extends \"Child.tpl.py\" %}{% set g = 1 %}"},
      {"t/Complex.tpl.py", "{% extends \"Root.tpl.py\" %}{% include \"Root.tpl.py\" %}"},
  };
  TemplateShapes shapes(TemplatePath{{}, {"t"}, files});
  const std::optional<TemplateShape>& child = shapes.shape("Child.tpl.py");
  REQUIRE(child.has_value());
  CHECK(child->rendersEmpty("a"));        // overridden by a blank definition
  CHECK_FALSE(child->rendersEmpty("b"));  // overridden with content
  CHECK(child->rendersEmpty("c"));        // not in the root's layout: never rendered
  CHECK_FALSE(child->may_export);
  REQUIRE(shapes.shape("Exporting.tpl.py").has_value());
  CHECK(shapes.shape("Exporting.tpl.py")->may_export);
  CHECK_FALSE(shapes.shape("Complex.tpl.py").has_value());
  CHECK_FALSE(shapes.shape("Missing.tpl.py").has_value());
}

}  // namespace
}  // namespace smachac::generator
