{% block meta %}
name: ParamState
description: A test state whose constructor takes a name, an outcome and a label.
language: Python
framework: SMACH
type: State
tags: [test]
includes: []
extends: [State]
variables:
- name_param: {description: The name the state logs., type: str}
- outcome_param: {description: The outcome it returns., type: str}
- - label: {description: A label to log., type: str}
input_keys: []
output_keys: []
outcomes: [outcome_a, outcome_b]
{% endblock meta %}
{% extends "State.tpl.py" %}

{% block class_defs %}
{{ super() }}
{% if 'class_ParamState' not in defined_headers %}
class ParamState(smach.State):
    def __init__(self, name, outcome, label=''):
        smach.State.__init__(self, outcomes=['outcome_a', 'outcome_b'])
        self._name, self._outcome, self._label = name, outcome, label

    def execute(self, userdata):
        smach.loginfo('{} ({}) returns {}'.format(self._name, self._label, self._outcome))
        return self._outcome
{% do defined_headers.append('class_ParamState') %}
{% endif %}
{% endblock class_defs %}

{% block body %}
smach.{{ parent_type }}.add({{ name | pyrepr }},
                       ParamState({{ name_param | pyrepr }}, {{ outcome_param | pyrepr }}{% if label is defined %}, label={{ label | pyrepr }}{% endif %})
{%- if transitions is defined %},
{{ render_transitions(transitions) }}
{%- endif %})
{% endblock body %}
