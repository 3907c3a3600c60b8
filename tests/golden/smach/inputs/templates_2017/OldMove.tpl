{% from "Utils.tpl" import render_input_keys, render_transitions, render_def_lambda_callbacks, render_callbacks %}
{% include "State.tpl" %}

{% block class_defs %}
{% if 'class_OldMove' not in defined_headers %}
class OldMove(smach.State):
    def __init__(self, input_keys=[], callbacks=[]):
        smach.State.__init__(self, outcomes=['succeeded', 'aborted'], input_keys=input_keys)

    def execute(self, userdata):
        return 'succeeded' if math.fsum(userdata.positions) > 0 else 'aborted'
{% do defined_headers.append('class_OldMove') %}
{% endif %}
{% endblock class_defs %}

{% block cb_defs %}
{{ render_def_lambda_callbacks(defined_headers, name, input_keys, {'positions': positions_cb}) }}
{% endblock cb_defs %}

{% block body %}
smach.{{ parent_type }}.add('{{ name }}',
{{ '' | indent(23, true) }}OldMove({{ render_input_keys(input_keys, indent=0) }}, {{ render_callbacks(name, {'positions': positions_cb}, indent=0) }}),
{{ render_transitions(transitions) }})
{% endblock body %}
