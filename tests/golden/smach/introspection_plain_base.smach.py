#!/usr/bin/env python

import smach


class PrintUserdataState(smach.State):
    """Logs every input key with its value, in the order given, then succeeds."""

    def __init__(self, input_keys=[], output_keys=[], callbacks=[], outcomes=['succeeded']):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=outcomes)
        self._keys = list(dict.fromkeys(input_keys))  # in order (SMACH keeps a set)

    def execute(self, userdata):
        for key in self._keys:
            smach.loginfo('userdata.{}: {}'.format(key, userdata[key]))
        return 'succeeded'


def main():
    plain = smach.StateMachine(outcomes=['done'])

    with plain:
        smach.StateMachine.add('SHOW',
                               PrintUserdataState(),
                               transitions={'succeeded':'done'})

    outcome = plain.execute()


if __name__ == '__main__':
    main()
