{% block meta %}
name: State
description: Base of the benchmark state templates (shaped like SMACHA's State.tpl.py).
{% endblock meta %}
{% from "Utils.tpl.py" import render_input_keys, render_output_keys, render_outcomes, render_transitions, render_remapping, render_userdata, import_module %}

{% block base_header %}
{% endblock base_header %}

{% block imports %}
{{ import_module(defined_headers, 'smach') }}
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
{% if userdata is defined %}{{ render_userdata(parent_sm_name, userdata) }}{% endif %}
{% endblock header %}

{% block body %}
smach.{{ parent_type }}.add('{{ name }}',
        {{ '' | indent(23, true) }}{{ class_name }}({% if input_keys is defined %}{{ render_input_keys(input_keys, indent=0) }}{% endif %}{% if output_keys is defined %}{% if input_keys is defined %}, {% endif %}{{ render_output_keys(output_keys, indent=0) }}{% endif %}{% if outcomes is defined %}{% if input_keys is defined or output_keys is defined %}, {% endif %}{{ render_outcomes(outcomes, indent=0) }}{% endif %}){% if transitions is defined %},
{{ render_transitions(transitions) }}{% endif %}{% if remapping is defined %},
{{ render_remapping(remapping) }}{% endif %})
{% endblock body %}

{% block footer %}
{% endblock footer %}

{% block execute %}
{% endblock execute %}

{% block base_footer %}
{% endblock base_footer %}

{% block main %}
{% endblock main %}
