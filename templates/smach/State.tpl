{% block meta %}
name: State
description: >
  The 2017 state template, which templates written for SMACHA 2017 include:
  it renders the state's userdata in the `header` block (in the parent
  container, by parent_sm_name). Templates written since extend State.tpl.py.
language: Python
framework: SMACH
type: None
tags: [core]
includes: []
extends: []
variables:
- - userdata:
      description: Userdata values set in the parent container, by key.
      type: dict
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% from "Utils.tpl.py" import render_userdata %}
{% block header %}
{% if userdata is defined %}
{{ render_userdata(parent_sm_name, userdata) }}
{% endif %}
{% endblock header %}
