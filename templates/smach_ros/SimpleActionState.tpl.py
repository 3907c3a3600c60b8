{% block meta %}
name: SimpleActionState
description: >
  Sends a goal to a ROS action server through smach_ros.SimpleActionState. The
  goal is a fixed expression (goal), built from userdata slots (goal_slots) or
  by a callback (goal_cb); the result goes to userdata slots (result_slots) or
  to a callback (result_cb).
language: Python
framework: SMACH
type: State
tags: [core, ros]
includes: []
extends:
- State
variables:
- action_server_namespace:
    description: The action server's name, e.g. /robot/joint_motion.
    type: str
- action:
    description: The action type (a Python expression, e.g. TestAction).
    type: str
- - goal:
      description: The goal, a Python expression.
      type: str
  - goal_slots:
      description: Goal fields filled from the userdata keys of the same names.
      type: list of str
  - goal_cb:
      description: A function (a name or a backtick-wrapped lambda) that builds the goal from the userdata.
      type: str
- - result_slots:
      description: Result fields stored in the userdata keys of the same names.
      type: list of str
  - result_cb:
      description: A function (a name or a backtick-wrapped lambda) called with the userdata, the status and the result.
      type: str
- - input_keys:
      description: The userdata keys the goal callback reads.
      type: list of str
- - output_keys:
      description: The userdata keys the result callback writes.
      type: list of str
- - import_modules:
      description: Modules that this state's code uses, each written `import <module>`.
      type: list of str
- - from_imports:
      description: >
        Names that this state's code uses (service, action or message types,
        goal classes, callbacks), by module, each written `from <module> import
        <name>` (e.g. {std_srvs.srv: [Trigger]}).
      type: dict of list of str
input_keys: []
output_keys: []
outcomes:
- succeeded
- aborted
- preempted
{% endblock meta %}
{% from "Utils.tpl.py" import from_import, render_goal_slots, render_result_slots %}
{% from "ScriptImports.tpl.py" import render_script_imports %}
{% extends "State.tpl.py" %}

{% block imports %}
{{ super() }}
{{ from_import(defined_headers, 'actionlib', '*') }}
{{ render_script_imports(defined_headers, import_modules if import_modules is defined else [], from_imports if from_imports is defined else {}) }}
{% endblock imports %}

{% block body %}
smach.{{ parent_type }}.add({{ name | pyrepr }},
                       smach_ros.SimpleActionState({{ action_server_namespace | pyrepr }}, {{ action }}
{%- if goal is defined %},
{{ ' ' * 51 }}goal = {{ goal }}
{%- elif goal_slots is defined %},
{{ render_goal_slots(goal_slots) }}
{%- elif goal_cb is defined %},
{{ ' ' * 51 }}goal_cb = {{ goal_cb | exptostr if goal_cb is expression else goal_cb }}
{%- if input_keys is defined %},
{{ render_input_keys(input_keys) }}
{%- endif %}
{%- endif %}
{%- if result_slots is defined %},
{{ render_result_slots(result_slots) }}
{%- elif result_cb is defined %},
{{ ' ' * 51 }}result_cb = {{ result_cb | exptostr if result_cb is expression else result_cb }}
{%- if output_keys is defined %},
{{ render_output_keys(output_keys) }}
{%- endif %}
{%- endif %})
{%- if transitions is defined and parent_type != 'Concurrence' %},
{{ render_transitions(transitions) }}
{%- endif %}
{%- if remapping is defined %},
{{ render_remapping(remapping) }}
{%- endif %})
{% endblock body %}
