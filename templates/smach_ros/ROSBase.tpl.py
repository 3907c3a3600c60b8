{% block meta %}
name: ROSBase
description: >
  The base template of a ROS SMACH script: the Base layout plus roslib, rospy
  and smach_ros imports, `rospy.init_node`, and with -i an introspection
  server (for smach_viewer) and `rospy.spin()`.
language: Python
framework: SMACH
type: Base
tags: [core, ros]
includes: []
extends:
- Base
variables:
- outcomes:
    description: The outcomes of the top state machine.
    type: list of str
- - manifest:
      description: The ROS manifest (package) to load with roslib.
      type: str
- - node_name:
      description: The ROS node name (default the script's name).
      type: str
- - userdata:
      description: Userdata of the top state machine, by key.
      type: dict
- - function_name:
      description: The name of the generated main function (default main).
      type: str
- - import_modules:
      description: >
        Modules that the script's code uses, each written `import <module>`
        (e.g. [std_msgs.msg] for msg_type std_msgs.msg.String).
      type: list of str
- - from_imports:
      description: >
        Names that the script's code uses, by module, each written `from
        <module> import <name>` (e.g. {std_srvs.srv: [Trigger]}).
      type: dict of list of str
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% from "Utils.tpl.py" import import_module %}
{% from "ScriptImports.tpl.py" import render_script_imports %}
{% extends "Base.tpl.py" %}
{%- block imports %}

{{ import_module(defined_headers, 'roslib') }}{% if manifest is defined %}; roslib.load_manifest({{ manifest | pyrepr }}){% endif %}
{{ import_module(defined_headers, 'rospy') }}
{{ import_module(defined_headers, 'smach') }}
{{ import_module(defined_headers, 'smach_ros') }}
{%- set script_imports = render_script_imports(defined_headers, import_modules if import_modules is defined else [], from_imports if from_imports is defined else {}) %}
{%- if script_imports %}
{{ script_imports }}
{%- endif %}
{%- if imports %}
{{ imports }}
{%- endif %}
{%- endblock imports %}
{%- block main_def %}


def {{ main_function }}():
    rospy.init_node({{ (node_name if node_name is defined else name) | pyrepr }})
{%- if main_def %}

    {{ main_def | indent(4) }}
{%- endif %}
{%- endblock main_def %}
{%- block introspection_server %}

    sis = smach_ros.IntrospectionServer({{ (node_name if node_name is defined else name) | pyrepr }}, {{ sm_name }}, {{ ('/' + name) | pyrepr }})
    sis.start()
{%- endblock introspection_server %}
{%- block spin %}

    rospy.spin()
{%- endblock spin %}
