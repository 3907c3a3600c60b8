#!/usr/bin/env python

import roslib; roslib.load_manifest('smacha')
import rospy
import smach
import smach_ros


class SleepState(smach.State):
    """Sleeps for a fixed time, then succeeds."""

    def __init__(self, time, input_keys=[], output_keys=[], callbacks=[], outcomes=['succeeded']):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=outcomes)
        self._time = time

    def execute(self, userdata):
        rospy.sleep(self._time)
        return 'succeeded'


def main():
    rospy.init_node('demo_node')
    ros_demo = smach.StateMachine(outcomes=['done'])
    ros_demo.userdata.duration = 0.5


    with ros_demo:
        smach.StateMachine.add('NAP',
                               SleepState(0.25),
                               transitions={'succeeded':'done'})

    outcome = ros_demo.execute()


if __name__ == '__main__':
    main()
