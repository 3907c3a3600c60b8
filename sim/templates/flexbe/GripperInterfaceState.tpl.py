{% block meta %}
name: GripperInterfaceState
description: >
  Opens or closes a limb's electric gripper with baxter_interface.Gripper
  (calibrating it first when needed): an EventState that commands the gripper
  and polls until the fingers stop (aborted at the timeout). A variable
  left out is read from the input key of the same name (limb, command).
  Aborted when a close expected to grasp closed on nothing.
language: Python
framework: FlexBE
type: State
tags: [baxter]
includes: []
extends:
- State
variables:
- - limb:
      description: left or right (default input key limb).
      type: str
- - command:
      description: open or close (default input key command).
      type: str
- - expect_grasp:
      description: Closing must grasp an object (default true).
      type: bool
- - timeout:
      description: Seconds for the fingers to settle (default 2).
      type: float
input_keys: []
output_keys: []
outcomes: [succeeded, aborted, preempted]
{% endblock meta %}
{% extends "State.tpl.py" %}
{% from "BaxterUtils.tpl.py" import define_baxter_module, text_argument, data_argument, render_baxter_add %}
{% set state_module = '' %}
{% set state_class = 'GripperInterfaceState' %}

{% block class_defs %}
{{ define_baxter_module(defined_headers) }}


{% if 'class_GripperInterfaceState' not in defined_headers %}
class GripperInterfaceState(BaxterEventState):
    """
    Opens or closes a limb's gripper (calibrating it first when needed).

    -- limb         string  left or right (None: the input key limb).
    -- command      string  open or close (None: the input key command).
    -- expect_grasp bool    Closing must grasp an object.
    -- timeout      float   Seconds for the fingers to settle.
    -- input_keys   list    The arguments read from the userdata.

    ># limb         string  The limb, when limb is an input key.
    ># command      string  The command, when command is an input key.

    <= succeeded            The fingers settled (on an object, when expected).
    <= aborted              They did not settle, or closed on nothing.
    <= preempted            The behavior was preempted.
    """

    def __init__(self, limb=None, command=None, expect_grasp=True, timeout=2.0, input_keys=[]):
        BaxterEventState.__init__(self, dict(limb=limb, command=command,
                                             expect_grasp=expect_grasp, timeout=timeout),
                                  input_keys)

    def start(self, userdata, limb, command, expect_grasp, timeout):
        if command not in ('open', 'close'):
            raise ValueError('a gripper command is open or close, not %r' % (command,))
        self._gripper = baxter_interface.Gripper(limb, baxter_interface.CHECK_VERSION)
        if not self._gripper.calibrated():
            self._gripper.calibrate()
        self._closing = command == 'close'
        self._expect_grasp = expect_grasp
        self._deadline = rospy.get_time() + timeout
        if self._closing:
            self._gripper.close()
        else:
            self._gripper.open()
        return None

    def poll(self, userdata):
        if self._gripper.moving():
            return 'aborted' if rospy.get_time() > self._deadline else None
        if self._closing and self._expect_grasp and not self._gripper.gripping():
            return 'aborted'
        return 'succeeded'
{% do defined_headers.append('class_GripperInterfaceState') %}
{% endif %}
{% endblock class_defs %}

{% block body %}
{%- set arguments = [] %}
{%- set keys = [] %}
{%- if limb is defined %}{% do arguments.append(text_argument('limb', limb)) %}{% else %}{% do keys.append('limb') %}{% endif %}
{%- if command is defined %}{% do arguments.append(text_argument('command', command)) %}{% else %}{% do keys.append('command') %}{% endif %}
{%- if expect_grasp is defined %}{% do arguments.append('expect_grasp=' ~ ('True' if expect_grasp else 'False')) %}{% endif %}
{%- if timeout is defined %}{% do arguments.append(data_argument('timeout', timeout | float)) %}{% endif %}
{{ render_baxter_add(defined_headers, default_module, state_class, name, arguments, keys, [], transitions, autonomy, remapping) }}
{% endblock body %}
