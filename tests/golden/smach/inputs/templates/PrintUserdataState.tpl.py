{% extends "State.tpl.py" %}
{% block class_defs %}
{% if 'class_PrintUserdataState' not in defined_headers %}
class PrintUserdataState(smach.State):
    """The user's own version, found before the built-in one."""
    def __init__(self, input_keys=[], outcomes=['succeeded']):
        smach.State.__init__(self, input_keys=input_keys, outcomes=outcomes)

    def execute(self, userdata):
        for key in self.get_registered_input_keys():
            print(key, userdata[key])
        return 'succeeded'
{% do defined_headers.append('class_PrintUserdataState') %}
{% endif %}
{% endblock class_defs %}
