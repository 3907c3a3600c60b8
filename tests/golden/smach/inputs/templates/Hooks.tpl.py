{% extends "State.tpl.py" %}
{% block main_def %}
hooks_{{ label }} = []
{% endblock main_def %}
{% block footer %}
# footer of {{ name }}
{% endblock footer %}
{% block execute %}
logging.info('about to run, hook {{ label }}')
{% endblock execute %}
{% block body %}
smach.{{ parent_type }}.add({{ name | pyrepr }}, smach.CBState(lambda ud: 'succeeded', outcomes=['succeeded']),
{{ render_transitions(transitions) }})
{% endblock body %}
