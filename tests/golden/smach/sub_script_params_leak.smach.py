#!/usr/bin/env python

import smach


class ParamState(smach.State):
    def __init__(self, name, outcome, label=''):
        smach.State.__init__(self, outcomes=['outcome_a', 'outcome_b'])
        self._name, self._outcome, self._label = name, outcome, label

    def execute(self, userdata):
        smach.loginfo('{} ({}) returns {}'.format(self._name, self._label, self._outcome))
        return self._outcome


def main():
    sm = smach.StateMachine(outcomes=['done'])

    with sm:
        sm_sub = smach.StateMachine(outcomes=['sub_outcome_1', 'sub_outcome_2'])

        with sm_sub:
            smach.StateMachine.add('FOO_0',
                                   ParamState('S_0', 'outcome_a'),
                                   transitions={'outcome_a':'FOO_1',
                                                'outcome_b':'sub_outcome_1'})

            smach.StateMachine.add('FOO_1',
                                   ParamState('S_1', 'outcome_a'),
                                   transitions={'outcome_a':'sub_outcome_2',
                                                'outcome_b':'sub_outcome_1'})



        smach.StateMachine.add('SUB', sm_sub,
                               transitions={'sub_outcome_1':'done',
                                            'sub_outcome_2':'LAST'})

        smach.StateMachine.add('LAST',
                               ParamState('S_0', 'outcome_a'),
                               transitions={'outcome_a':'done',
                                            'outcome_b':'done'})

    outcome = sm.execute()


if __name__ == '__main__':
    main()
