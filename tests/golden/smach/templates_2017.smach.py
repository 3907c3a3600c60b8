#!/usr/bin/env python


import roslib
import rospy
import smach
import smach_ros
import math



class OldMove(smach.State):
    def __init__(self, input_keys=[], callbacks=[]):
        smach.State.__init__(self, outcomes=['succeeded', 'aborted'], input_keys=input_keys)

    def execute(self, userdata):
        return 'succeeded' if math.fsum(userdata.positions) > 0 else 'aborted'


@smach.cb_interface(input_keys=['positions'],
                    output_keys=['positions'],
                    outcomes=['succeeded'])
def positions_move_lambda_cb(userdata):
    lambda_cb = lambda ud: ud.positions
    userdata.positions = lambda_cb(userdata)
    return 'succeeded'


def main():
    rospy.init_node('old_style')
    old_style = smach.StateMachine(outcomes=['done'])
    old_style.userdata.positions = [0.1, 0.2]

    with old_style:
        smach.StateMachine.add('MOVE',
                               OldMove(input_keys = ['positions'], callbacks = ['positions_move_lambda_cb']),
                               transitions={'aborted':'done',
                                            'succeeded':'done'})

    outcome = old_style.execute()


if __name__ == '__main__':
    main()
