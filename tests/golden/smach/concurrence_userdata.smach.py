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
    sm = smach.StateMachine(outcomes=['done'])

    with sm:
        sm_con = smach.Concurrence(outcomes=['ok', 'failed'],
                                           default_outcome='failed',
                                           outcome_map={'ok': { 'A': 'succeeded', 'B': 'succeeded'}})
        sm_con.userdata.mode = 'fast'
        sm_con.userdata.shared = 1

        sm_con.userdata.a_value = 2.5

        sm_con.userdata.b_value = [1, 2]



        with sm_con:
            smach.Concurrence.add('A',
                                   PrintUserdataState(input_keys = ['shared', 'a_value']))

            smach.Concurrence.add('B',
                                   PrintUserdataState(input_keys = ['shared', 'b_value']))



        smach.StateMachine.add('CON', sm_con,
                               transitions={'failed':'done',
                                            'ok':'done'})

    outcome = sm.execute()


if __name__ == '__main__':
    main()
