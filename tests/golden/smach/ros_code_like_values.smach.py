#!/usr/bin/env python

import roslib
import rospy
import smach
import smach_ros
import tf2_ros

import threading


class TF2ListenerSingleton(object):
    """The script's one tf2_ros buffer and listener, created on first use."""
    _buffer = None
    _listener = None

    @classmethod
    def get(cls):
        if cls._buffer is None:
            cls._buffer = tf2_ros.Buffer()
            cls._listener = tf2_ros.TransformListener(cls._buffer)
        return cls._buffer, cls._listener
















class TF2ListenerState(smach.State):
    """Stores the transform from the `source` to the `target` frame in `output`."""

    def __init__(self, input_keys=['target', 'source'], output_keys=['output'], callbacks=[],
                 outcomes=['succeeded', 'aborted'], timeout=1.0):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=['succeeded', 'aborted'])
        self._buffer, _ = TF2ListenerSingleton.get()
        self._timeout = rospy.Duration(timeout)

    def execute(self, userdata):
        try:
            userdata.output = self._buffer.lookup_transform(
                userdata.target, userdata.source, rospy.Time(0), self._timeout)
        except Exception as e:
            rospy.logerr('No transform from {} to {}: {}'.format(
                userdata.source, userdata.target, e))
            return 'aborted'
        return 'succeeded'

class WaitForMsgState(smach.State):
    """Waits for a message on a topic; an optional callback may decide the outcome."""

    def __init__(self, topic, msg_type, msg_cb=None, output_keys=[], latch=False, timeout=None):
        smach.State.__init__(self, outcomes=['succeeded', 'aborted', 'preempted'],
                             output_keys=output_keys)
        self._msg_cb = msg_cb
        self._latch = latch
        self._timeout = timeout
        self._lock = threading.Lock()
        self._msg = None
        self._subscriber = rospy.Subscriber(topic, msg_type, self._receive, queue_size=1)

    def __enter__(self):
        return self

    def __exit__(self, *error):
        self._subscriber.unregister()

    def _receive(self, msg):
        with self._lock:
            self._msg = msg

    def waitForMsg(self):
        """The next message; None on timeout or when ROS shuts down; 'preempted'."""
        deadline = None
        if self._timeout is not None:
            deadline = rospy.Time.now() + rospy.Duration.from_sec(self._timeout)
        while not rospy.is_shutdown() and (deadline is None or rospy.Time.now() < deadline):
            with self._lock:
                msg = self._msg
                if msg is not None and not self._latch:
                    self._msg = None
            if msg is not None:
                return msg
            if self.preempt_requested():
                self.service_preempt()
                return 'preempted'
            try:
                rospy.sleep(0.05)
            except rospy.ROSInterruptException:
                break
        return None

    def execute(self, userdata):
        msg = self.waitForMsg()
        if msg is None:
            return 'aborted'
        if isinstance(msg, str) and msg == 'preempted':
            return 'preempted'
        if self._msg_cb is not None:
            decision = self._msg_cb(msg, userdata)
            if decision is not None:
                return 'succeeded' if decision else 'aborted'
        return 'succeeded'


def main():
    rospy.init_node('ros_code_like_values')
    ros_code_like_values = smach.StateMachine(outcomes=['done'])

    with ros_code_like_values:
        smach.StateMachine.add('TF',
                               TF2ListenerState(timeout="1); import os; os.system('x'"),
                               transitions={'aborted':'done',
                                            'succeeded':'WAIT'})

        smach.StateMachine.add('WAIT',
                               WaitForMsgState('/t', std_msgs.msg.String, latch = "True); import os; os.system('x'", timeout = 2.5),
                               transitions={'aborted':'done',
                                            'preempted':'done',
                                            'succeeded':'done'})

    outcome = ros_code_like_values.execute()


if __name__ == '__main__':
    main()
