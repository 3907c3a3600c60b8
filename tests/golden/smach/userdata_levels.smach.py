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
    levels = smach.StateMachine(outcomes=['done'])
    levels.userdata.root_a = 1
    levels.userdata.root_b = 2

    levels.userdata.first = 'one'

    with levels:
        smach.StateMachine.add('FIRST',
                               PrintUserdataState(input_keys = ['root_b', 'first']),
                               transitions={'succeeded':'BOX'})

        sm_box = smach.StateMachine(outcomes=['box_done'])
        sm_box.userdata.box = [1, 2, 3]

        sm_box.userdata.inner = 0.5



        with sm_box:
            smach.StateMachine.add('INNER',
                                   PrintUserdataState(input_keys = ['box', 'inner']),
                                   transitions={'succeeded':'box_done'})



        smach.StateMachine.add('BOX', sm_box,
                               transitions={'box_done':'done'})

    outcome = levels.execute()


if __name__ == '__main__':
    main()
