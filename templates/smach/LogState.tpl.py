{% block meta %}
name: LogState
description: >
  A SMACH state that logs `text` (smach.loginfo), then returns `done`:
  FlexBE's LogState under the same name, variables and outcome (`severity`
  is accepted for scripts written for FlexBE and does not change the log
  level).
language: Python
framework: SMACH
type: State
tags: [core]
includes: []
extends:
- State
variables:
- text:
    description: The message.
    type: str
- - severity:
      description: FlexBE's Logger.REPORT_* level; not used here.
      type: str
input_keys: []
output_keys: []
outcomes:
- done
{% endblock meta %}
{% extends "State.tpl.py" %}

{% block class_defs %}
{{ super() }}
{% if 'class_LogState' not in defined_headers %}
class LogState(smach.State):
    """Logs a text, then returns `done`."""

    def __init__(self, text):
        smach.State.__init__(self, outcomes=['done'])
        self._text = text

    def execute(self, userdata):
        smach.loginfo(self._text)
        return 'done'
{% do defined_headers.append('class_LogState') %}
{% endif %}
{% endblock class_defs %}

{% block body %}
smach.{{ parent_type }}.add({{ name | pyrepr }},
                       LogState({{ text | string | pyrepr }})
{%- if transitions is defined and parent_type != 'Concurrence' %},
{{ render_transitions(transitions) }}
{%- endif %}
{%- if remapping is defined %},
{{ render_remapping(remapping) }}
{%- endif %})
{% endblock body %}
