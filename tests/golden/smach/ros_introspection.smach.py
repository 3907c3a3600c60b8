#!/usr/bin/env python

import roslib
import rospy
import smach
import smach_ros


class SleepState(smach.State):
    """Sleeps for a fixed time, then succeeds; with `preempted` among its outcomes it wakes
    on a preempt request and returns `preempted`."""

    def __init__(self, time, input_keys=[], output_keys=[], callbacks=[], outcomes=['succeeded']):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=outcomes)
        self._time = time

    def execute(self, userdata):
        if not rospy.rostime.is_rostime_initialized():
            rospy.rostime.set_rostime_initialized(True)  # no ROS node: rospy's time is wall time
        if 'preempted' not in self.get_registered_outcomes():
            rospy.sleep(self._time)
            return 'succeeded'
        end = rospy.get_rostime() + rospy.Duration(self._time)
        while rospy.get_rostime() < end:
            if self.preempt_requested():
                self.service_preempt()
                return 'preempted'
            rospy.sleep(min(0.01, (end - rospy.get_rostime()).to_sec()))
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
