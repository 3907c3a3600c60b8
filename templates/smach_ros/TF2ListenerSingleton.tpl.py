{% block meta %}
name: TF2ListenerSingleton
description: >
  Helper included by the TF2 states: one tf2_ros buffer and listener shared by
  every state of the generated script.
language: Python
framework: SMACH
type: None
tags: [core, ros]
includes: []
extends: []
variables: []
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% from "Utils.tpl.py" import import_module %}
{% block imports %}
{{ import_module(defined_headers, 'rospy') }}
{{ import_module(defined_headers, 'tf2_ros') }}
{% endblock imports %}

{% block class_defs %}
{% if 'class_TF2ListenerSingleton' not in defined_headers %}
class TF2ListenerSingleton(object):
    """The script's one tf2_ros buffer and listener, created on first use."""
    _buffer = None
    _listener = None

    @classmethod
    def get(cls):
        if cls._buffer is None:
            cls._buffer = tf2_ros.Buffer()
            cls._listener = tf2_ros.TransformListener(cls._buffer)
        return cls._buffer, cls._listener
{% do defined_headers.append('class_TF2ListenerSingleton') %}
{% endif %}
{% endblock class_defs %}
