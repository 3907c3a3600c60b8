{% block meta %}
name: BaxterBase
description: >
  The base template of a Baxter SMACH script (Baxter SDK, ROS 1): the core
  Base (imports, definitions, main(), the __main__ guard) plus rospy and
  baxter_interface, a ROS node named after the script, and the robot enabled
  (as baxter_tools' enable_robot.py -e) before the machine is built and run.
language: Python
framework: SMACH
type: Base
tags: [baxter]
includes: []
extends:
- Base
variables:
- outcomes:
    description: The outcomes of the top state machine.
    type: list of str
- - userdata:
      description: Userdata of the top state machine, by key.
      type: dict
- - function_name:
      description: The name of the generated main function (default main).
      type: str
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% from "Utils.tpl.py" import import_module %}
{% extends "Base.tpl.py" %}
{%- block imports %}

{{ import_module(defined_headers, 'rospy') }}
{{ import_module(defined_headers, 'smach') }}

{{ import_module(defined_headers, 'baxter_interface') }}
{%- if imports %}
{{ imports }}
{%- endif %}
{%- endblock imports %}
{%- block main_def %}


def {{ main_function }}():
    rospy.init_node({{ (name if name is defined else 'sm') | pyrepr }})
    robot = baxter_interface.RobotEnable(baxter_interface.CHECK_VERSION)
    robot.enable()
{%- if main_def %}

    {{ main_def | indent(4) }}
{%- endif %}
{%- endblock main_def %}
{%- block execute %}
{{ super() }}
    rospy.loginfo('outcome: %s', outcome)
{%- endblock execute %}
