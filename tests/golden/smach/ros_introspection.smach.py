#!/usr/bin/env python

import roslib
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
    rospy.init_node('Viewer_Demo')
    viewer_demo = smach.StateMachine(outcomes=['done'])

    with viewer_demo:
        smach.StateMachine.add('NAP',
                               SleepState(1),
                               transitions={'succeeded':'done'})

    sis = smach_ros.IntrospectionServer('Viewer_Demo', viewer_demo, '/Viewer_Demo')
    sis.start()

    outcome = viewer_demo.execute()

    rospy.spin()


if __name__ == '__main__':
    main()
