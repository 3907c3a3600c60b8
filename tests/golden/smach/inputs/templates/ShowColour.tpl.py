{% extends "State.tpl.py" %}
{% block body %}
# colour={{ colour }} scratch={{ scratch | default('undefined') }} sm_name={{ sm_name }}
smach.{{ parent_type }}.add({{ name | pyrepr }}, smach.CBState(lambda ud: 'succeeded', outcomes=['succeeded']),
{{ render_transitions(transitions) }})
{% endblock body %}
