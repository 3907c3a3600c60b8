{% block meta %}
name: BaxterUtils
description: >
  Macro library of the Baxter SMACH templates: the BaxterState base class and
  the pose functions (each written once per generated file, tracked in
  defined_headers), the userdata keys a state reads in place of variables the
  script leaves out, and the line that adds a Baxter state to its container.
language: Python
framework: SMACH
type: None
tags: [baxter]
includes: []
extends: []
variables: []
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% from "Utils.tpl.py" import import_module, from_import, render_list, render_transitions, render_remapping %}

{# The imports of every Baxter state class. #}
{% macro import_baxter_state(defined_headers) -%}
{{ join_imports([import_module(defined_headers, 'rospy'), import_module(defined_headers, 'smach')]) }}
{%- endmacro %}

{# The base class of the Baxter states: fixed outcomes, arguments that the userdata
   overrides for the keys named in input_keys, preemption before the work starts, and any
   error (ROS, a missing key, malformed data) logged and returned as `aborted`. #}
{% macro define_baxter_state(defined_headers) -%}
{% if 'class_BaxterState' not in defined_headers -%}
class BaxterState(smach.State):
    """A Baxter state: outcomes succeeded, aborted, preempted. Each argument named in
    input_keys is read from the userdata key of that name instead."""

    def __init__(self, arguments, input_keys=(), output_keys=()):
        smach.State.__init__(self, outcomes=['succeeded', 'aborted', 'preempted'],
                             input_keys=list(input_keys), output_keys=list(output_keys))
        self._arguments = dict(arguments)

    def arguments(self, userdata):
        values = dict(self._arguments)
        for key in self.get_registered_input_keys():
            values[key] = getattr(userdata, key)
        return values

    def execute(self, userdata):
        if self.preempt_requested():
            self.service_preempt()
            return 'preempted'
        try:
            return self.run(userdata, **self.arguments(userdata))
        except Exception as error:  # ROS, a missing key, malformed data: an outcome
            rospy.logerr('%s: %s', type(self).__name__, error)
            return 'aborted'

    def run(self, userdata, **arguments):
        raise NotImplementedError
{% do defined_headers.append('class_BaxterState') %}
{%- endif %}
{%- endmacro %}

{# Poses as the scripts write them, [[x, y, z], [qx, qy, qz, qw]] (or flat), to
   geometry_msgs, and offsets added to them (a rotation of all zeros is none). #}
{% macro define_pose_functions(defined_headers) -%}
{% if 'def_baxter_pose_functions' not in defined_headers -%}
def baxter_pose_parts(pose):
    """([x, y, z], [qx, qy, qz, qw]) of a pose given nested, flat or as a position."""
    flat = [float(v) for v in (list(pose[0]) + list(pose[1]) if len(pose) == 2 else pose)]
    if len(flat) == 3:
        flat += [0.0, 0.0, 0.0, 0.0]
    if len(flat) != 7:
        raise ValueError('a pose is [[x, y, z], [qx, qy, qz, qw]], not %r' % (pose,))
    return flat[:3], flat[3:]


def baxter_quaternion_product(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return [aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz]


def baxter_offset_pose(pose, offset):
    """The pose moved by the offset's position, then turned by its rotation (if any)."""
    position, rotation = baxter_pose_parts(pose)
    shift, turn = baxter_pose_parts(offset)
    position = [p + s for p, s in zip(position, shift)]
    if any(turn):
        rotation = baxter_quaternion_product(rotation, turn)
    return [position, rotation]


def baxter_pose_msg(pose):
    position, rotation = baxter_pose_parts(pose)
    if not any(rotation):
        rotation = [0.0, 0.0, 0.0, 1.0]
    return Pose(position=Point(*position), orientation=Quaternion(*rotation))
{% do defined_headers.append('def_baxter_pose_functions') %}
{%- endif %}
{%- endmacro %}

{% macro import_pose_functions(defined_headers) -%}
{{ join_imports([from_import(defined_headers, 'geometry_msgs.msg', 'Point'),
                 from_import(defined_headers, 'geometry_msgs.msg', 'Pose'),
                 from_import(defined_headers, 'geometry_msgs.msg', 'Quaternion')]) }}
{%- endmacro %}

{# Joint positions as the scripts write them, [s0, s1, e0, e1, w0, w1, w2] (or a
   {joint: angle} dict), as the {joint: angle} dict baxter_interface.Limb takes. #}
{% macro define_joint_function(defined_headers) -%}
{% if 'def_baxter_joint_positions' not in defined_headers -%}
def baxter_joint_positions(limb_interface, positions):
    if isinstance(positions, dict):
        return dict(positions)
    names = limb_interface.joint_names()
    if len(positions) != len(names):
        raise ValueError('joint positions are %d angles, not %r' % (len(names), positions))
    return dict(zip(names, [float(q) for q in positions]))
{% do defined_headers.append('def_baxter_joint_positions') %}
{%- endif %}
{%- endmacro %}

{# Module-level definitions, two blank lines apart (PEP 8); empty ones are left out. (The
   generator strips each state's block, so states' definitions are one blank line apart.) #}
{% macro join_definitions(definitions) -%}
{{ definitions | map('trim') | select | join('\n\n\n') }}
{%- endmacro %}

{# Import lines, one each; empty ones (already imported) are left out. #}
{% macro join_imports(imports) -%}
{{ imports | map('trim') | select | join('\n') }}
{%- endmacro %}

{# `name=value` for a variable the script gives: text quoted, data as Python literals
   (`pyliteral`: nan and inf as float('nan'), float('inf')). #}
{% macro text_argument(name, value) -%}
{{ name }}={{ value | string | pyrepr }}
{%- endmacro %}

{% macro data_argument(name, value) -%}
{{ name }}={{ value | pyliteral }}
{%- endmacro %}

{# Adds a Baxter state to its container: `<Class>(<arguments>, input_keys=[...])` with the
   script's transitions (none in a Concurrence) and remapping. #}
{% macro render_baxter_state(parent_type, name, class_name, arguments, input_keys, transitions, remapping) -%}
{% set all_arguments = arguments + ['input_keys=' ~ render_list(input_keys)] -%}
smach.{{ parent_type }}.add({{ name | pyrepr }},
                       {{ class_name }}({{ all_arguments | join(', ') }})
{%- if transitions is defined and parent_type != 'Concurrence' %},
{{ render_transitions(transitions) }}
{%- endif %}
{%- if remapping is defined %},
{{ render_remapping(remapping) }}
{%- endif %})
{%- endmacro %}
