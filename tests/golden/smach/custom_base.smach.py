#!/usr/bin/env python


import smach
import logging




def run_machine():
    hooks_first = []

    hooks_second = []
    logging.basicConfig(level=logging.INFO)

    custom_base = smach.StateMachine(outcomes=['done'])

    with custom_base:
        smach.StateMachine.add('FIRST', smach.CBState(lambda ud: 'succeeded', outcomes=['succeeded']),
                               transitions={'succeeded':'SECOND'})

        smach.StateMachine.add('SECOND', smach.CBState(lambda ud: 'succeeded', outcomes=['succeeded']),
                               transitions={'succeeded':'done'})
        # footer of SECOND

        # footer of FIRST

    logging.info('about to run, hook second')

    logging.info('about to run, hook first')

    outcome = custom_base.execute()

    logging.info('finished with %s', outcome)



if __name__ == '__main__':
    run_machine()
