{% extends "State.tpl.py" %}
{% block class_defs %}
{% for key, value in settings.items() %}
# {{ key }} = {{ value }}
{% endfor %}
{% endblock class_defs %}
