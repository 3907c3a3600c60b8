{% block meta %}
name: RecordROSBagState
description: >
  A SMACH state that starts or stops recording ROS topics into a bag file.
  With action `start` (or `record`) it records the topics of the `topics`
  input key (all topics when empty) into the bag file the `file` input key
  names, until a later state stops that file (`stop`) or every recording
  (`stop_all`). The script's one bag recorder is a ROSBagCLIProcessRecorder
  (a `rosbag record` process per bag) unless the first RecordROSBagState
  names another with `recorder`.
language: Python
framework: SMACH
type: State
tags: [core, ros]
includes:
- ROSBagCLIProcessRecorder
- ROSBagAPIThreadRecorder
extends:
- State
variables:
- action:
    description: start (or record), stop or stop_all.
    type: str
- - recorder:
      description: >
        The recorder class: ROSBagCLIProcessRecorder (the default) or
        ROSBagAPIThreadRecorder (the rosbag API in threads of this program).
      type: str
- - input_keys:
      description: The userdata keys the state reads (file, topics); other keys are for its callbacks.
      type: list of str
- - output_keys:
      description: The userdata keys its callbacks write.
      type: list of str
- - callbacks:
      description: Callbacks by output key, run before the recording starts or stops.
      type: dict of str
input_keys:
- file:
    description: The bag file (a name without .bag is a prefix the CLI recorder dates).
    type: str
- topics:
    description: The topics to record (all topics when empty).
    type: list of str
output_keys: []
outcomes:
- succeeded
- aborted
{% endblock meta %}
{% from "Utils.tpl.py" import render_init_callbacks, render_execute_callbacks %}
{% extends "State.tpl.py" %}
{% if recorder is defined and recorder == 'ROSBagAPIThreadRecorder' %}
{% include "ROSBagAPIThreadRecorder.tpl.py" %}
{% else %}
{% include "ROSBagCLIProcessRecorder.tpl.py" %}
{% endif %}

{% block class_defs %}
{{ super() }}
{% if 'class_RecordROSBagState' not in defined_headers %}
class RecordROSBagState(smach.State):
    """Starts or stops a recording of the script's bag recorder."""

    def __init__(self, name, bag_recorder, action, input_keys=['file', 'topics'], output_keys=[],
                 callbacks=[]):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=['succeeded', 'aborted'])
        self._name = name
        self._recorder = bag_recorder
        self._action = action
        {{ render_init_callbacks() }}

    def execute(self, userdata):
        {{ render_execute_callbacks() }}
        if self._action == 'stop_all':
            return self._recorder.stop_all()
        if self._action not in ('start', 'record', 'stop'):
            rospy.logerr('Unknown action {} (start, record, stop or stop_all)'.format(self._action))
            return 'aborted'
        bag_file = userdata.file if 'file' in self._input_keys else None
        if not isinstance(bag_file, str) or not bag_file:
            rospy.logerr('The input key file must name the bag file, not {!r}'.format(bag_file))
            return 'aborted'
        if self._action == 'stop':
            return self._recorder.stop(bag_file)
        topics = userdata.topics if 'topics' in self._input_keys else []
        if isinstance(topics, str):
            topics = [topics] if topics else []
        if not all(isinstance(topic, str) for topic in topics):
            rospy.logerr('The input key topics must list topic names, not {!r}'.format(topics))
            return 'aborted'
        return self._recorder.start(bag_file, list(topics))
{% do defined_headers.append('class_RecordROSBagState') %}
{% endif %}
{% endblock class_defs %}

{#- The script has one recorder, of the class the first RecordROSBagState names. A class name
    is pasted as code only when it is an identifier. #}
{% block main_def %}
{{ super() }}
{% if 'bag_recorder' not in defined_headers %}
{% set recorder_class = (recorder if recorder is defined else 'ROSBagCLIProcessRecorder') | string %}
{% if recorder_class | pyident == recorder_class and not recorder_class[:1].isdigit() %}
bag_recorder = {{ recorder_class }}()
{% else %}
raise NameError({{ ('not a recorder class: ' ~ recorder_class) | pyrepr }})
{% endif %}
{% do defined_headers.append('bag_recorder') %}
{% endif %}
{% endblock main_def %}

{% block header %}
{{ super() }}
{# The container gets default `file` and `topics` userdata before the states' own userdata,
   so that scripts may leave them out where the action does not use them. #}
{% set defaults = {} %}
{% if action == 'stop_all' %}{% do defaults.update({'file': ''}) %}{% endif %}
{% if action in ['stop', 'stop_all'] %}{% do defaults.update({'topics': ''}) %}{% endif %}
{{ render_userdata(parent_sm_name, defaults) }}
{% endblock header %}

{% block body %}
{% set arguments = [name | pyrepr, 'bag_recorder', action | pyrepr] %}
{% if input_keys is defined %}{% do arguments.append(render_input_keys(input_keys, indent=0)) %}{% endif %}
{% if output_keys is defined %}{% do arguments.append(render_output_keys(output_keys, indent=0)) %}{% endif %}
{% if callbacks is defined %}{% do arguments.append(render_callbacks(name, uuid, callbacks, indent=0)) %}{% endif %}
smach.{{ parent_type }}.add({{ name | pyrepr }},
                       {{ class_name }}({{ arguments | join(', ') }})
{%- if transitions is defined and parent_type != 'Concurrence' %},
{{ render_transitions(transitions) }}
{%- endif %}
{%- if remapping is defined %},
{{ render_remapping(remapping) }}
{%- endif %})
{% endblock body %}
