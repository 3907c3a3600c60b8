{% from "Utils.tpl.py" import render_outcomes, render_transitions %}
{% block header %}
{{ name | lower }}_ready = True
{% endblock header %}
{% block body %}
sm_{{ name | lower }} = smach.StateMachine({{ render_outcomes(outcomes) }})
with sm_{{ name | lower }}:
    {{ body | indent(4) }}
smach.{{ parent_type }}.add({{ name | pyrepr }}, sm_{{ name | lower }},
{{ render_transitions(transitions) }})
{% endblock body %}
