{% block meta %}
name: ParsingState
description: >
  A test state: a CallbacksState whose callbacks can call every parse_*
  function of the smach_ros Parse* helpers it includes, and parse_fails.
language: Python
framework: SMACH
type: State
tags: [test]
includes: [ParseJointTrajectoryPoint, ParsePointCloud, ParsePointCloud2, ParsePointStamped, ParsePose, ParsePoseArray, ParsePoseStamped, ParseTransformStamped]
extends: [CallbacksState]
variables:
- callbacks: {description: Callbacks by output key., type: dict of str}
input_keys: []
output_keys: []
outcomes: [succeeded]
{% endblock meta %}
{% extends "CallbacksState.tpl.py" %}
{% include "ParseJointTrajectoryPoint.tpl.py" %}
{% include "ParsePointCloud.tpl.py" %}
{% include "ParsePointCloud2.tpl.py" %}
{% include "ParsePointStamped.tpl.py" %}
{% include "ParsePose.tpl.py" %}
{% include "ParsePoseArray.tpl.py" %}
{% include "ParsePoseStamped.tpl.py" %}
{% include "ParseTransformStamped.tpl.py" %}

{% block defs %}
{{ super() }}
{% if 'def_parse_fails' not in defined_headers %}
def parse_fails(parser, value):
    """Whether parser rejects value with a ValueError."""
    try:
        parser(value)
    except ValueError:
        return True
    return False
{% do defined_headers.append('def_parse_fails') %}
{% endif %}
{% endblock defs %}

{% block class_defs %}
{{ super() }}
{% if 'class_ParsingState' not in defined_headers %}
class ParsingState(CallbacksState):
    """A CallbacksState (its callbacks call the parse_* functions)."""
{% do defined_headers.append('class_ParsingState') %}
{% endif %}
{% endblock class_defs %}
