#!/usr/bin/env python

import smach
import csv

import os
import glob


class WriteCSVFileState(smach.State):
    """Writes the values of the `data_keys` userdata keys as a row of the CSV `file`."""

    def __init__(self, delimiter=',', input_keys=['file', 'data_keys'], output_keys=[],
                 callbacks=[]):
        # `file` and `data_keys` are read whatever input keys the script lists, as on the
        # other targets.
        input_keys = ['file', 'data_keys'] + [key for key in input_keys
                                              if key not in ('file', 'data_keys')]
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=['succeeded', 'aborted'])
        self._delimiter = delimiter
        
        self._cbs = []
        for cb_name in (callbacks or []):
            if cb_name in globals():
                self._cbs.append(globals()[cb_name])

        self._cb_input_keys = []
        self._cb_output_keys = []
        self._cb_outcomes = []
        for cb in self._cbs:
            if cb and smach.has_smach_interface(cb):
                self._cb_input_keys.append(cb.get_registered_input_keys())
                self._cb_output_keys.append(cb.get_registered_output_keys())
                self._cb_outcomes.append(cb.get_registered_outcomes())
                self.register_input_keys(self._cb_input_keys[-1])
                self.register_output_keys(self._cb_output_keys[-1])
                self.register_outcomes(self._cb_outcomes[-1])


    def execute(self, userdata):
        
        # Call the callbacks
        for (cb, input_keys, output_keys) in zip(self._cbs,
                                                 self._cb_input_keys,
                                                 self._cb_output_keys):
            cb(smach.Remapper(userdata, input_keys, output_keys, {}))

        row = []
        for key in userdata.data_keys:
            value = userdata[key]
            row.extend(value if isinstance(value, (list, tuple)) else [value])
        try:
            with open(userdata.file, 'w', newline='') as stream:
                writer = csv.writer(stream, delimiter=self._delimiter)
                if 'header' in userdata:
                    writer.writerow(userdata.header)
                writer.writerow(row)
        except (IOError, OSError) as e:
            smach.logerr('Cannot write CSV file {}: {}'.format(userdata.file, e))
            return 'aborted'
        return 'succeeded'

class DeleteFileState(smach.State):
    """Deletes the files matching the `file` input key (a path or a glob pattern)."""

    def __init__(self, input_keys=['file'], output_keys=[], callbacks=[], outcomes=None):
        # `file` is read whatever input keys the script lists, as on the other targets.
        input_keys = ['file'] + [key for key in input_keys if key != 'file']
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=['succeeded', 'aborted'])
        
        self._cbs = []
        for cb_name in (callbacks or []):
            if cb_name in globals():
                self._cbs.append(globals()[cb_name])

        self._cb_input_keys = []
        self._cb_output_keys = []
        self._cb_outcomes = []
        for cb in self._cbs:
            if cb and smach.has_smach_interface(cb):
                self._cb_input_keys.append(cb.get_registered_input_keys())
                self._cb_output_keys.append(cb.get_registered_output_keys())
                self._cb_outcomes.append(cb.get_registered_outcomes())
                self.register_input_keys(self._cb_input_keys[-1])
                self.register_output_keys(self._cb_output_keys[-1])
                self.register_outcomes(self._cb_outcomes[-1])


    def execute(self, userdata):
        
        # Call the callbacks
        for (cb, input_keys, output_keys) in zip(self._cbs,
                                                 self._cb_input_keys,
                                                 self._cb_output_keys):
            cb(smach.Remapper(userdata, input_keys, output_keys, {}))

        try:
            for path in glob.glob(userdata.file) or [userdata.file]:
                smach.loginfo('Deleting {}'.format(path))
                os.remove(path)
        except OSError as e:
            smach.logerr('Cannot delete {}: {}'.format(userdata.file, e))
            return 'aborted'
        return 'succeeded'


def main():
    files = smach.StateMachine(outcomes=['done', 'failed'])
    files.userdata.data_keys = ['xs', 'ys']
    files.userdata.file = '/tmp/smachac_golden.csv'
    files.userdata.xs = [1, 2]
    files.userdata.ys = [3, 4]


    with files:
        smach.StateMachine.add('WRITE',
                               WriteCSVFileState(delimiter=';', input_keys = ['file', 'data_keys', 'xs', 'ys']),
                               transitions={'aborted':'failed',
                                            'succeeded':'DELETE'})

        smach.StateMachine.add('DELETE',
                               DeleteFileState(input_keys = ['file']),
                               transitions={'aborted':'failed',
                                            'succeeded':'done'})

    outcome = files.execute()


if __name__ == '__main__':
    main()
