{% extends "State.tpl.py" %}
{% block body %}
smach.{{ parent_type }}.add({{ name | pyrepr }}, Broken(
{% if transitions is defined %}
{{ render_transitions(transitions) }}
{% endblock body %}
