{% block meta %}
name: Utils
description: >
  Macro library of the C++ templates: userdata, outcome, key, transition,
  remapping and outcome-map rendering, state specs, callbacks, the line that
  adds a state to its container, and includes written once per generated file
  (tracked in defined_headers).
language: C++
framework: smachac runtime
type: None
tags: [core]
includes: []
extends: []
variables: []
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{#- Every macro writes C++ for the smachac runtime (`namespace rt = smachac::runtime`):
    strings go through `cppstr` (a C++ string literal for any bytes), values through
    `cppvalue` (an expression converting to rt::Value). The first line of a macro's output is
    never indented by the macro. -#}

{# One userdata value as a C++ expression: None → nullptr, numbers, bools, strings, lists
   (rt::List) and dicts (rt::Map); a backtick expression is written bare (it is C++). #}
{% macro render_value(value) -%}
{{ value | cppvalue }}
{%- endmacro %}

{# A braced list of string literals: {"a", "b"}. #}
{% macro render_list(items) -%}
{{ '{' }}{{ items | map('cppstr') | join(', ') }}{{ '}' }}
{%- endmacro %}

{# `<namespace>.userdata().set("key", value);`, one line per entry, sorted by key; the
   namespace (a container's variable) lower-cased, keys as written; a plain string value is a
   bare string literal (`cppuserdata`). #}
{% macro render_userdata(namespace, userdata) -%}
{% for key, value in userdata.items() | sort -%}
{{ namespace | lower }}.userdata().set({{ key | cppstr }}, {{ value | cppuserdata }});
{% endfor -%}
{% endmacro %}

{% macro render_outcomes(outcomes) -%}
.outcomes = {{ render_list(outcomes) }}
{%- endmacro %}

{% macro render_input_keys(input_keys) -%}
.input_keys = {{ render_list(input_keys) }}
{%- endmacro %}

{% macro render_output_keys(output_keys) -%}
.output_keys = {{ render_list(output_keys) }}
{%- endmacro %}

{# `rt::CStringSpec{.outcomes = ..., .input_keys = ..., .output_keys = ...}`, each field when
   the state gives it (designated initializers, in declaration order). The literal form of
   rt::StateSpec, which it converts to: string literals, nothing to construct or destroy, so
   that a program of thousands of states compiles fast. #}
{% macro render_spec(outcomes, input_keys, output_keys) -%}
{% set fields = [] -%}
{% if outcomes is defined %}{% do fields.append(render_outcomes(outcomes)) %}{% endif -%}
{% if input_keys is defined %}{% do fields.append(render_input_keys(input_keys)) %}{% endif -%}
{% if output_keys is defined %}{% do fields.append(render_output_keys(output_keys)) %}{% endif -%}
rt::CStringSpec{{ '{' }}{{ fields | join(', ') }}{{ '}' }}
{%- endmacro %}

{# One callback: a backtick expression is a C++ callable taking `rt::UserData&` and
   returning something rt::Value converts from; any other value names a function. #}
{% macro render_callback(callback) -%}
{% if callback is string and callback is expression %}{{ callback | exptostr }}
{%- else %}{{ callback | string }}{% endif %}
{%- endmacro %}

{# `rt::CallbacksLiteral{{"key", callback}, ...}` for a state's constructor: the literal form
   of rt::Callbacks, which it converts to (nothing to destroy; a lambda without captures is
   kept as a function pointer). #}
{% macro render_callbacks(state_name, state_uuid, callbacks) -%}
rt::CallbacksLiteral{{ '{' }}
{%- for output_key, callback in callbacks.items() -%}
{{ '{' }}{{ output_key | cppstr }}, {{ render_callback(callback) }}{{ '}' }}{% if not loop.last %}, {% endif %}
{%- endfor %}{{ '}' }}
{%- endmacro %}

{# C++ callbacks need no generated functions: kept for the template API of the SMACH set. #}
{% macro render_def_lambda_callbacks(defined_headers, class_name, state_name, state_uuid, input_keys, outcomes, callbacks) -%}
{%- endmacro %}

{# `{"outcome", {{"CHILD", "child_outcome"}, ...}}, ...` for a ConcurrenceSpec, sorted. #}
{% macro render_outcome_map(outcome_map) -%}
.outcome_map = {{ '{' }}
{%- for outcome, condition in outcome_map.items() | sort -%}
{{ '{' }}{{ outcome | cppstr }}, {{ '{' }}
{%- for child, child_outcome in condition.items() | sort -%}
{{ '{' }}{{ child | cppstr }}, {{ child_outcome | cppstr }}{{ '}' }}{% if not loop.last %}, {% endif %}
{%- endfor %}{{ '}}' }}{% if not loop.last %}, {% endif %}
{%- endfor %}{{ '}' }}
{%- endmacro %}

{# `rt::Transitions{{"outcome", "TARGET"}, ...}`, sorted. #}
{% macro render_transitions(transitions) -%}
rt::Transitions{{ '{' }}
{%- for outcome, target in transitions.items() | sort -%}
{{ '{' }}{{ outcome | cppstr }}, {{ target | cppstr }}{{ '}' }}{% if not loop.last %}, {% endif %}
{%- endfor %}{{ '}' }}
{%- endmacro %}

{# `rt::Remapping{{"state_key", "parent_key"}, ...}`, sorted. #}
{% macro render_remapping(remapping) -%}
rt::Remapping{{ '{' }}
{%- for key, parent_key in remapping.items() | sort -%}
{{ '{' }}{{ key | cppstr }}, {{ parent_key | cppstr }}{{ '}' }}{% if not loop.last %}, {% endif %}
{%- endfor %}{{ '}' }}
{%- endmacro %}

{# The arguments of a state class constructor that State.tpl.cpp writes: the spec, then the
   callbacks when the state gives them. #}
{% macro render_state_arguments(state_name, state_uuid, input_keys, output_keys, callbacks, outcomes) -%}
{{ render_spec(outcomes, input_keys, output_keys) }}
{%- if callbacks is defined %}, {{ render_callbacks(state_name, state_uuid, callbacks) }}{% endif %}
{%- endmacro %}

{# `{{"key", "value"}, ...}`, sorted: a map of strings as `add` takes it (rt::PairsLiteral). #}
{% macro render_pairs(pairs) -%}
{{ '{' }}
{%- for key, value in pairs.items() | sort -%}
{{ '{' }}{{ key | cppstr }}, {{ value | cppstr }}{{ '}' }}{% if not loop.last %}, {% endif %}
{%- endfor %}{{ '}' }}
{%- endmacro %}

{# What `emplace` takes after the label: transitions (not in a Concurrence) and remapping, as
   literals (`{{"succeeded", "NEXT"}}, {}`). #}
{% macro render_add_tail(parent_type, transitions, remapping) -%}
{% if parent_type != 'Concurrence' -%}
{{ render_pairs(transitions if transitions is defined else {}) }}, {% endif -%}
{{ render_pairs(remapping if remapping is defined else {}) }}
{%- endmacro %}

{# `<parent>.emplace<Class>("NAME", transitions, remapping, arguments);`: the state is made
   from `arguments` inside the library's template (StateMachine::emplace), so that each
   statement compiles to the call alone. #}
{% macro render_add_state(parent_sm_name, parent_type, name, class_name, arguments, transitions, remapping) -%}
{{ parent_sm_name }}.emplace<{{ class_name }}>({{ name | cppstr }}, {{ render_add_tail(parent_type, transitions, remapping) }},
    {{ arguments }});
{%- endmacro %}

{# A container after its spec: added to its parent inside its own C++ scope (its variable is
   a reference to the added container), then the header code its children filed under its
   name, its own userdata, its children's userdata and its children. The scope is a lambda
   called in place, capturing the enclosing locals by reference: one function per container
   instead of one huge function for the whole machine, whose optimisation time grows faster
   than its size (a 1,000-state machine builds about 5x faster at -O2). #}
{% macro render_container_contents(name, sm_name, class_name, spec, parent_sm_name, parent_type, header, userdata, header_userdata, body, transitions, remapping) -%}
[&] {
  [[maybe_unused]] auto& {{ sm_name }} = {{ parent_sm_name }}.emplace<{{ class_name }}>({{ name | cppstr }}, {{ render_add_tail(parent_type, transitions, remapping) }},
      {{ spec }});
{%- if name in header and header[name] | trim %}
  {{ header[name] | trim | indent(2) }}
{%- endif %}
{%- if userdata is defined %}
  {{ render_userdata(sm_name, userdata) | trim | indent(2) }}
{%- endif %}
{%- if name in header_userdata and header_userdata[name] | trim %}
  {{ header_userdata[name] | trim | indent(2) }}
{%- endif %}

  {{ body | trim | indent(2) }}
}();
{%- endmacro %}

{# Includes, each written once per generated file: `#include <header>`. #}
{% macro include_header(defined_headers, header) -%}
{% if 'include_' + header not in defined_headers -%}
#include <{{ header }}>{% do defined_headers.append('include_' + header) %}
{%- endif %}
{%- endmacro %}

{# `#include "header"`, once per generated file. #}
{% macro include_local(defined_headers, header) -%}
{% if 'include_local_' + header not in defined_headers -%}
#include "{{ header }}"{% do defined_headers.append('include_local_' + header) %}
{%- endif %}
{%- endmacro %}
