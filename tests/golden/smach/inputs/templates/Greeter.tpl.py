{% block meta %}
name: Greeter
description: A test state that logs a greeting to the `who` input key.
language: Python
framework: SMACH
type: State
tags: [test]
includes: [GreeterHelper]
extends: [State]
variables:
- greeting: {description: The greeting., type: str}
input_keys:
- who: {description: Whom to greet., type: str}
output_keys: []
outcomes: [succeeded]
{% endblock meta %}
{% from "Utils.tpl.py" import import_module %}
{% extends "State.tpl.py" %}
{% include "GreeterHelper.tpl.py" %}

{% block imports %}
{{ super() }}
{{ import_module(defined_headers, 'textwrap') }}
{% endblock imports %}

{% block class_defs %}
{{ super() }}
{% if 'class_Greeter' not in defined_headers %}
class Greeter(smach.State):
    def __init__(self, greeting, input_keys=[]):
        smach.State.__init__(self, input_keys=input_keys, outcomes=['succeeded'])
        self._greeting = greeting

    def execute(self, userdata):
        smach.loginfo(textwrap.shorten(greet(self._greeting, userdata.who), 40))
        return 'succeeded'
{% do defined_headers.append('class_Greeter') %}
{% endif %}
{% endblock class_defs %}

{% block body %}
smach.{{ parent_type }}.add({{ name | pyrepr }},
                       Greeter({{ greeting | pyrepr }}, {{ render_input_keys(input_keys, indent=0) }}),
{{ render_transitions(transitions) }})
{% endblock body %}
