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
    sm = smach.StateMachine(outcomes=['all_done', 'not_done'])

    with sm:
        sm_con = smach.Concurrence(outcomes=['both', 'fallback'],
                                           default_outcome='fallback',
                                           outcome_map={'both': { 'LEFT': 'outcome_a', 'RIGHT': 'right_done'}})

        with sm_con:
            smach.Concurrence.add('LEFT',
                                   ParamState('LEFT', 'outcome_a'))

            sm_right = smach.StateMachine(outcomes=['right_done'])

            with sm_right:
                smach.StateMachine.add('STEP',
                                       ParamState('STEP', 'outcome_b'),
                                       transitions={'outcome_a':'right_done',
                                                    'outcome_b':'right_done'})



            smach.Concurrence.add('RIGHT', sm_right)



        smach.StateMachine.add('CON', sm_con,
                               transitions={'both':'all_done',
                                            'fallback':'not_done'})

    outcome = sm.execute()


if __name__ == '__main__':
    main()
