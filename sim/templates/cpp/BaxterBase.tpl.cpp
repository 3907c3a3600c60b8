{% block meta %}
name: BaxterBase
description: >
  The base template of a Baxter program on the MuJoCo simulation: the core
  Base (includes, definitions, main()) plus the robot library
  (smachac/robot/robot.h), the robot set up with smachac::robot::setUpBaxter before the
  machine is built (it takes the robot flags --snapshots=DIR, --scene=PATH,
  --start-pose=..., --no-report, --robot-quiet out of argv), and the machine
  run with smachac::robot::runBaxter, which runs it as rt::runMain does (--trace=json|log,
  --trace-file=PATH, --seed=N, --quiet; prints `outcome: <outcome>`), lets the
  blocks settle and prints the scene report (block positions, stacked verdict).
  The states' code refers to the robot context as `*baxter_robot` (names in
  smachac::robot are written in full, so no script name can hide them).
language: C++
framework: smachac runtime
type: Base
tags: [baxter, sim]
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
      description: >
        The name of the generated function that builds and runs the machine
        (default main; any other name gets a main() that calls it).
      type: str
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% extends "Base.tpl.cpp" %}
{% from "Utils.tpl.cpp" import include_header %}

{% block imports %}

{{ include_header(defined_headers, 'cstdint') }}
{{ include_header(defined_headers, 'limits') }}
{{ include_header(defined_headers, 'memory') }}
{{ include_header(defined_headers, 'string') }}

{{ include_header(defined_headers, 'smachac/robot/robot.h') }}
{{ include_header(defined_headers, 'smachac/runtime/runtime.h') }}
{%- if imports %}
{{ imports }}
{%- endif %}

namespace rt = smachac::runtime;
{%- endblock imports %}

{%- block main_def %}{{ super() }}
  auto baxter_robot = smachac::robot::setUpBaxter(argc, argv);
  if (!baxter_robot) return 2;
{%- endblock main_def %}

{%- block execute %}
{%- if execute %}

  {{ execute | indent(2) }}
{%- endif %}

  int exit_code = smachac::robot::runBaxter({{ name | lower if name is defined else 'sm' }}, *baxter_robot, argc, argv);
{%- endblock execute %}
