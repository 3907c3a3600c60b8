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
    commented = smach.StateMachine(outcomes=['done'])

    with commented:
        # BEGIN: OUTER (StateMachine)
        sm_outer = smach.StateMachine(outcomes=['outer_done'])

        with sm_outer:
            # STEP (PrintUserdataState)
            smach.StateMachine.add('STEP',
                                   PrintUserdataState(),
                                   transitions={'succeeded':'outer_done'})



        smach.StateMachine.add('OUTER', sm_outer,
                               transitions={'outer_done':'done'})
        # END: OUTER

    outcome = commented.execute()


if __name__ == '__main__':
    main()
