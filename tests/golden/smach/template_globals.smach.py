#!/usr/bin/env python

import smach


def main():
    globals = smach.StateMachine(outcomes=['done'])

    with globals:
        # colour=red scratch=undefined sm_name=globals
        smach.StateMachine.add('BEFORE', smach.CBState(lambda ud: 'succeeded', outcomes=['succeeded']),
                               transitions={'succeeded':'PAINTER'})

        smach.StateMachine.add('PAINTER', smach.CBState(lambda ud: 'succeeded', outcomes=['succeeded']),
                               transitions={'succeeded':'AFTER'})

        # colour=yellow scratch=undefined sm_name=globals
        smach.StateMachine.add('AFTER', smach.CBState(lambda ud: 'succeeded', outcomes=['succeeded']),
                               transitions={'succeeded':'BOX'})

        sm_box = smach.StateMachine(outcomes=['box_done'])

        with sm_box:
            # colour=yellow scratch=undefined sm_name=globals
            smach.StateMachine.add('INSIDE', smach.CBState(lambda ud: 'succeeded', outcomes=['succeeded']),
                                   transitions={'succeeded':'INNER_PAINTER'})

            smach.StateMachine.add('INNER_PAINTER', smach.CBState(lambda ud: 'succeeded', outcomes=['succeeded']),
                                   transitions={'succeeded':'box_done'})



        smach.StateMachine.add('BOX', sm_box,
                               transitions={'box_done':'done'})

    outcome = globals.execute()


if __name__ == '__main__':
    main()
