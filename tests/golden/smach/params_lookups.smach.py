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
    params = smach.StateMachine(outcomes=['final_outcome'])

    with params:
        smach.StateMachine.add('FOO_0',
                               ParamState('FOO_0', 'outcome_a', label='FOO_0_3'),
                               transitions={'outcome_a':'FOO_1',
                                            'outcome_b':'final_outcome'})

        smach.StateMachine.add('FOO_1',
                               ParamState('FOO_1_copy', 'outcome_b', label='final_outcome'),
                               transitions={'outcome_a':'FOO_1',
                                            'outcome_b':'final_outcome'})

    outcome = params.execute()


if __name__ == '__main__':
    main()
