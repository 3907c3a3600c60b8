{% block meta %}
name: Base
description: >
  The 2017 base template, which templates written for SMACHA 2017 extend. In
  2017 the base was the ROS one, so this is ROSBase.tpl.py under its old name.
language: Python
framework: SMACH
type: Base
tags: [core, ros]
includes: []
extends:
- ROSBase
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
      description: Modules that the script's code uses, each written `import <module>`.
      type: list of str
- - from_imports:
      description: Names that the script's code uses, by module (`from <module> import <name>`).
      type: dict of list of str
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% extends "ROSBase.tpl.py" %}
