{% block meta %}
name: State
description: >
  What every C++ state template extends: one block per code buffer, the
  state's userdata (set in the parent container) and the statement that adds
  it to the parent container. State templates override class_defs (a
  using-declaration or their class, written once) and imports, and body when
  their constructor differs from (rt::StateSpec[, rt::Callbacks]).
language: C++
framework: smachac runtime
type: None
tags: [core]
includes: []
extends: []
variables:
- - outcomes:
      description: The outcomes of the state.
      type: list of str
- - input_keys:
      description: The userdata keys the state reads.
      type: list of str
- - output_keys:
      description: The userdata keys the state writes.
      type: list of str
- - callbacks:
      description: >
        Callbacks by output key: the name of a C++ function, or a
        backtick-wrapped C++ lambda taking rt::UserData&, such as
        `[](rt::UserData& ud) { return ud.get<int64_t>("n") + 1; }`.
      type: dict of str
- - transitions:
      description: The sibling state or container outcome for each outcome.
      type: dict of str
- - remapping:
      description: The parent's userdata key for each of the state's keys.
      type: dict of str
- - userdata:
      description: Userdata values set in the parent container, by key.
      type: dict
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{# Templates that extend this one can call these macros without importing them; they import
   any other Utils macro they use. #}
{% from "Utils.tpl.cpp" import render_userdata, render_outcomes, render_input_keys, render_output_keys, render_spec, render_def_lambda_callbacks, render_callbacks, render_transitions, render_remapping, render_state_arguments, render_add_state, include_header %}

{% block base_header %}
{% endblock base_header %}

{% block imports %}
{% endblock imports %}

{% block defs %}
{% endblock defs %}

{% block class_defs %}
{% endblock class_defs %}

{% block cb_defs %}
{% endblock cb_defs %}

{% block main_def %}
{% endblock main_def %}

{% block header %}
{% endblock header %}

{% block header_userdata %}
{%- if userdata is defined %}
{{ render_userdata(parent_sm_name, userdata) }}
{%- endif %}
{% endblock header_userdata %}

{% block body %}
{%- if include_comments %}
// {{ name | cppcomment }} ({{ class_name }})
{%- endif %}
{{ render_add_state(parent_sm_name, parent_type, name, class_name, render_state_arguments(name, uuid, input_keys, output_keys, callbacks, outcomes), transitions, remapping) }}
{% endblock body %}

{% block footer %}
{% endblock footer %}

{% block introspection_server %}
{% endblock introspection_server %}

{% block execute %}
{% endblock execute %}

{% block spin %}
{% endblock spin %}

{% block base_footer %}
{% endblock base_footer %}

{% block main %}
{% endblock main %}
