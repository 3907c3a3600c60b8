{% block meta %}
name: WorkState
description: A leaf state that does some work (benchmark).
{% endblock meta %}
{% extends "State.tpl.py" %}
{% from "Utils.tpl.py" import import_module %}
{% include "Common.tpl.py" %}

{% block imports %}
{{ super() }}
{{ import_module(defined_headers, 'time') }}
{% endblock imports %}

{% block class_defs %}
{% if 'class_' + class_name not in defined_headers %}
class {{ class_name }}(smach.State):
    def __init__(self, duration={{ duration }}):
        smach.State.__init__(self, outcomes={{ outcomes }}, input_keys={{ input_keys }})
        self._duration = duration

    def execute(self, userdata):
        time.sleep(self._duration)
        return '{{ outcomes[0] }}'
{% do defined_headers.append('class_' + class_name) %}
{% endif %}
{% endblock class_defs %}
