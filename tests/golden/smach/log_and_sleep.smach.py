#!/usr/bin/env python

import smach
import rospy


class LogState(smach.State):
    """Logs a text, then returns `done`."""

    def __init__(self, text):
        smach.State.__init__(self, outcomes=['done'])
        self._text = text

    def execute(self, userdata):
        smach.loginfo(self._text)
        return 'done'

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
    log_and_sleep = smach.StateMachine(outcomes=['finished', 'stopped'])

    with log_and_sleep:
        smach.StateMachine.add('SAY',
                               LogState('going to sleep'),
                               transitions={'done':'NAP'})

        smach.StateMachine.add('NAP',
                               SleepState(0.2, outcomes=['succeeded', 'preempted']),
                               transitions={'preempted':'stopped',
                                            'succeeded':'finished'})

    outcome = log_and_sleep.execute()


if __name__ == '__main__':
    main()
