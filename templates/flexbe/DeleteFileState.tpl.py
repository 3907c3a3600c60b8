{% block meta %}
name: DeleteFileState
description: >
  Deletes the files the `file` input key names (a path or a glob pattern);
  `aborted` when one cannot be deleted or none exists. Runs its callbacks
  first (e.g. to compute the file name). FlexBE has no library equivalent:
  the template writes an EventState class into the behavior's states module.
language: Python
framework: FlexBE
type: DeleteFileState
tags: [core]
includes: []
extends: []
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
        a backtick-wrapped Python lambda of the userdata or a portable `!expr`
        expression (a function name is not a callback here).
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
{% extends "State.tpl.py" %}
{% from "Utils.tpl.py" import file_state_args %}
{% set state_module = '' %}
{% set state_class = '' %}

{% set state_args = file_state_args(['file'], input_keys, output_keys, callbacks) %}

{% block class_defs %}
{% if 'class_DeleteFileState' not in defined_headers %}
import glob
import os


class DeleteFileState(EventState):
    """
    Deletes the files matching the `file` input key (a path or a glob pattern).

    -- input_keys   list    The userdata keys the state reads (`file` among them).
    -- output_keys  list    The userdata keys the callbacks write.
    -- callbacks    dict    Output key -> function of the userdata, run first.

    <= succeeded            The files are deleted.
    <= aborted              A file could not be deleted, or none exists.
    """

    def __init__(self, input_keys, output_keys, callbacks):
        super(DeleteFileState, self).__init__(outcomes=['succeeded', 'aborted'],
                                              input_keys=input_keys, output_keys=output_keys)
        self._callbacks = callbacks

    def execute(self, userdata):
        for key, callback in self._callbacks.items():
            userdata[key] = callback(userdata)
        try:
            for path in glob.glob(userdata.file) or [userdata.file]:
                Logger.loginfo('Deleting {}'.format(path))
                os.remove(path)
        except OSError as e:
            Logger.logerr('Cannot delete {}: {}'.format(userdata.file, e))
            return 'aborted'
        return 'succeeded'
{% do defined_headers.append('class_DeleteFileState') %}
{% endif %}
{% endblock class_defs %}
