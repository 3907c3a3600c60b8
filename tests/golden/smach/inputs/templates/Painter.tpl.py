{% extends "State.tpl.py" %}
{# `colour` is exported (a template global); `scratch` is listed in local_vars and is not. #}
{% set colour = 'yellow' %}
{% set scratch = 'temporary' %}
{% set local_vars = ['scratch'] %}
{% block body %}
smach.{{ parent_type }}.add({{ name | pyrepr }}, smach.CBState(lambda ud: 'succeeded', outcomes=['succeeded']),
{{ render_transitions(transitions) }})
{% endblock body %}
