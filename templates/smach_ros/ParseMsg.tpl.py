{% block meta %}
name: ParseMsg
description: >
  Helper function parse_msg: which Parse* function turns a state's `msg`
  input into the message it works on (by the `msg_type` input key, by the
  message's class, or the first that accepts a list). Included by
  PublishMsgState, PublishObserverMsgState and TransformMsgState.
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
{{ import_module(defined_headers, 'genpy') }}
{{ import_module(defined_headers, 'roslib.message') }}
{% endblock imports %}

{% block defs %}
{% if 'def_parse_msg' not in defined_headers %}
def parse_msg(msg, parsers, msg_type=None):
    """msg as a message, through parsers, a list of (message class, parse function) pairs.
    With msg_type (a type name such as geometry_msgs/PoseStamped) the parser of that type
    converts msg (ValueError when it cannot); a message of a class in parsers goes through
    its parser, any other message is returned as it is; anything else (a list) goes through
    the first parser that accepts it, else ValueError."""
    if msg_type:
        msg_class = roslib.message.get_message_class(msg_type)
        if msg_class is None:
            raise ValueError('unknown message type {}'.format(msg_type))
        for parsed_class, parser in parsers:
            if parsed_class is msg_class:
                return parser(msg)
        if isinstance(msg, msg_class):
            return msg
        raise ValueError('{!r} is not a {}'.format(msg, msg_type))
    for parsed_class, parser in parsers:
        if isinstance(msg, parsed_class):
            return parser(msg)
    if isinstance(msg, genpy.Message):
        return msg
    for _, parser in parsers:
        try:
            return parser(msg)
        except ValueError:
            pass
    raise ValueError('cannot make a message of {!r}'.format(msg))
{% do defined_headers.append('def_parse_msg') %}
{% endif %}
{% endblock defs %}
