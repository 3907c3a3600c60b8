{% block meta %}
name: ServiceState
description: >
  Calls a ROS service through smach_ros.ServiceState. The request is a fixed
  expression (request), built from userdata slots (request_slots) or by a
  callback (request_cb); the response goes to userdata slots (response_slots)
  or to a callback (response_cb).
language: Python
framework: SMACH
type: State
tags: [core, ros]
includes: []
extends:
- State
variables:
- service_namespace:
    description: The service's name, e.g. /robot/gripper_service.
    type: str
- service:
    description: The service type (a Python expression, e.g. GripperSrv).
    type: str
- - request:
      description: The request, a Python expression.
      type: str
  - request_slots:
      description: Request fields filled from the userdata keys of the same names.
      type: list of str
  - request_cb:
      description: A function (a name or a backtick-wrapped lambda) that builds the request from the userdata.
      type: [function, str]
- - response_slots:
      description: Response fields stored in the userdata keys of the same names.
      type: list of str
  - response_cb:
      description: A function (a name or a backtick-wrapped lambda) called with the userdata and the response.
      type: [function, str]
- - input_keys:
      description: The userdata keys the request callback reads.
      type: list of str
- - output_keys:
      description: The userdata keys the response callback writes.
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
{% from "Utils.tpl.py" import render_request_slots, render_response_slots %}
{% from "ScriptImports.tpl.py" import render_script_imports %}
{% extends "State.tpl.py" %}

{% block imports %}
{{ super() }}
{{ render_script_imports(defined_headers, import_modules if import_modules is defined else [], from_imports if from_imports is defined else {}) }}
{% endblock imports %}

{% block body %}
smach.{{ parent_type }}.add({{ name | pyrepr }},
                       smach_ros.ServiceState({{ service_namespace | pyrepr }}, {{ service }}
{%- if request is defined %},
{{ ' ' * 51 }}request = {{ request }}
{%- elif request_slots is defined %},
{{ render_request_slots(request_slots) }}
{%- elif request_cb is defined %},
{{ ' ' * 51 }}request_cb = {{ request_cb | exptostr if request_cb is expression else request_cb }}
{%- if input_keys is defined %},
{{ render_input_keys(input_keys) }}
{%- endif %}
{%- endif %}
{%- if response_slots is defined %},
{{ render_response_slots(response_slots) }}
{%- elif response_cb is defined %},
{{ ' ' * 51 }}response_cb = {{ response_cb | exptostr if response_cb is expression else response_cb }}
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
