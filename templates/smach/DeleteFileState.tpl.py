{% block meta %}
name: DeleteFileState
description: >
  A SMACH state that deletes the files the `file` input key names (a path or
  a glob pattern); `aborted` when one cannot be deleted or none exists. Runs
  its callbacks first (e.g. to compute the file name).
language: Python
framework: SMACH
type: State
tags: [core]
includes: []
extends:
- State
variables:
- - input_keys:
      description: The userdata keys the state reads (`file` is added).
      type: list of str
- - output_keys:
      description: The userdata keys the callbacks write (each callback's key is added).
      type: list of str
- - callbacks:
      description: >
        Callbacks by output key, run in the script's order before the files
        are deleted (e.g. to compute the file name), each computing the value
        of its key from the userdata:
        the name of a function the program defines (in a custom template), a
        backtick-wrapped Python lambda of the userdata, or a portable `!expr`
        expression.
      type: dict of str
input_keys:
- file:
    description: The path or glob pattern of the files to delete.
    type: str
output_keys: []
outcomes:
- succeeded
- aborted
{% endblock meta %}
{% from "Utils.tpl.py" import import_module, render_init_callbacks, render_execute_callbacks %}
{% extends "State.tpl.py" %}

{% block imports %}
{{ super() }}
{{ import_module(defined_headers, 'os') }}
{{ import_module(defined_headers, 'glob') }}
{% endblock imports %}

{% block class_defs %}
{{ super() }}
{% if 'class_DeleteFileState' not in defined_headers %}
class DeleteFileState(smach.State):
    """Deletes the files matching the `file` input key (a path or a glob pattern)."""

    def __init__(self, input_keys=['file'], output_keys=[], callbacks=[], outcomes=None):
        # `file` is read whatever input keys the script lists, as on the other targets.
        input_keys = ['file'] + [key for key in input_keys if key != 'file']
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=['succeeded', 'aborted'])
        {{ render_init_callbacks() }}

    def execute(self, userdata):
        {{ render_execute_callbacks() }}
        try:
            for path in glob.glob(userdata.file) or [userdata.file]:
                smach.loginfo('Deleting {}'.format(path))
                os.remove(path)
        except OSError as e:
            smach.logerr('Cannot delete {}: {}'.format(userdata.file, e))
            return 'aborted'
        return 'succeeded'
{% do defined_headers.append('class_DeleteFileState') %}
{% endif %}
{% endblock class_defs %}
