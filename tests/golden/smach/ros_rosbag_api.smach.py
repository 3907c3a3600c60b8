#!/usr/bin/env python

import roslib
import rospy
import smach
import smach_ros
import rosbag
import genpy
import roslib.message






from geometry_msgs.msg import Point
from geometry_msgs.msg import Point32
from geometry_msgs.msg import PointStamped







from geometry_msgs.msg import Pose
from geometry_msgs.msg import PoseStamped




















from geometry_msgs.msg import PoseArray






from sensor_msgs.msg import PointCloud
from sensor_msgs.msg import PointCloud2
from sensor_msgs import point_cloud2 as pc2







from sensor_msgs.point_cloud2 import create_cloud_xyz32






import threading


def parse_msg(msg, parsers, msg_type=None):
    """msg as a message, through parsers, a list of (message class, parse function) pairs.
    With msg_type (a type name such as geometry_msgs/PoseStamped) the parser of that type
    converts msg (ValueError when it cannot); a message of a class in parsers goes through
    its parser, any other message is returned as it is; anything else (a list) goes through
    the first parser that accepts it, else ValueError."""
    if msg_type:
        msg_class = roslib.message.get_message_class(msg_type)
        if msg_class is None:
            raise ValueError('unknown message type {}'.format(msg_type))
        for parsed_class, parser in parsers:
            if parsed_class is msg_class:
                return parser(msg)
        if isinstance(msg, msg_class):
            return msg
        raise ValueError('{!r} is not a {}'.format(msg, msg_type))
    for parsed_class, parser in parsers:
        if isinstance(msg, parsed_class):
            return parser(msg)
    if isinstance(msg, genpy.Message):
        return msg
    for _, parser in parsers:
        try:
            return parser(msg)
        except ValueError:
            pass
    raise ValueError('cannot make a message of {!r}'.format(msg))








def parse_pointstamped(point_input):
    """A PointStamped from a PointStamped (as it is), a Point, a Point32 or [x, y, z]."""
    if isinstance(point_input, PointStamped):
        return point_input
    if isinstance(point_input, (Point, Point32)):
        coordinates = [point_input.x, point_input.y, point_input.z]
    else:
        coordinates = []
        if isinstance(point_input, (list, tuple)):
            try:
                coordinates = [float(value) for value in point_input]
            except (TypeError, ValueError):
                coordinates = []
        if len(coordinates) != 3:
            raise ValueError('not a point (PointStamped, Point, Point32 or [x, y, z]): '
                             '{!r}'.format(point_input))
    stamped = PointStamped()
    stamped.point.x, stamped.point.y, stamped.point.z = coordinates
    if rospy.rostime.is_rostime_initialized():
        stamped.header.stamp = rospy.Time.now()
    return stamped










def parse_pose(pose_input):
    """A Pose from a Pose (as it is), a PoseStamped (its pose) or [position, quaternion]."""
    if isinstance(pose_input, Pose):
        return pose_input
    if isinstance(pose_input, PoseStamped):
        return pose_input.pose
    position = orientation = []
    if isinstance(pose_input, (list, tuple)) and len(pose_input) == 2:
        try:
            position = [float(value) for value in pose_input[0]]
            orientation = [float(value) for value in pose_input[1]]
        except (TypeError, ValueError):
            position = orientation = []
    if len(position) != 3 or len(orientation) != 4:
        raise ValueError('not a pose (Pose, PoseStamped or [[x, y, z], [qx, qy, qz, qw]]): '
                         '{!r}'.format(pose_input))
    pose = Pose()
    pose.position.x, pose.position.y, pose.position.z = position
    pose.orientation.x, pose.orientation.y, pose.orientation.z, pose.orientation.w = orientation
    return pose







def parse_posestamped(pose_input):
    """A PoseStamped from a PoseStamped (as it is), a Pose or [position, quaternion]."""
    if isinstance(pose_input, PoseStamped):
        return pose_input
    stamped = PoseStamped(pose=parse_pose(pose_input))
    if rospy.rostime.is_rostime_initialized():
        stamped.header.stamp = rospy.Time.now()
    return stamped















def parse_posearray(posearray_input):
    """A PoseArray from a PoseArray (as it is) or a list of poses (see parse_pose)."""
    if isinstance(posearray_input, PoseArray):
        return posearray_input
    if not isinstance(posearray_input, (list, tuple)):
        raise ValueError('not a pose array (PoseArray or a list of poses): '
                         '{!r}'.format(posearray_input))
    posearray = PoseArray(poses=[parse_pose(pose) for pose in posearray_input])
    if rospy.rostime.is_rostime_initialized():
        posearray.header.stamp = rospy.Time.now()
    return posearray








def parse_pointcloud(pointcloud_input):
    """A PointCloud from a PointCloud (as it is) or a PointCloud2 (x, y, z of each point)."""
    if isinstance(pointcloud_input, PointCloud):
        return pointcloud_input
    if not isinstance(pointcloud_input, PointCloud2):
        raise ValueError('not a point cloud (PointCloud or PointCloud2): '
                         '{!r}'.format(pointcloud_input))
    points = pc2.read_points(pointcloud_input, field_names=('x', 'y', 'z'), skip_nans=True)
    return PointCloud(header=pointcloud_input.header,
                      points=[Point32(x=x, y=y, z=z) for x, y, z in points])








def parse_pointcloud2(pointcloud_input):
    """A PointCloud2 from a PointCloud2 (as it is) or a PointCloud (its points)."""
    if isinstance(pointcloud_input, PointCloud2):
        return pointcloud_input
    if not isinstance(pointcloud_input, PointCloud):
        raise ValueError('not a point cloud (PointCloud2 or PointCloud): '
                         '{!r}'.format(pointcloud_input))
    return create_cloud_xyz32(pointcloud_input.header,
                              [[p.x, p.y, p.z] for p in pointcloud_input.points])


class MsgPublisher(object):
    """Publishes messages on topics at fixed rates until told to stop."""

    def __init__(self):
        self._lock = threading.Lock()
        self._stops = {}

    def start(self, msg, topic, rate, frame_id=''):
        if frame_id and hasattr(msg, 'header'):
            msg.header.frame_id = frame_id
        self.stop(topic)
        stop = threading.Event()
        with self._lock:
            self._stops[topic] = stop
        publisher = rospy.Publisher(topic, type(msg), queue_size=1, latch=True)

        def run():
            period = rospy.Rate(rate)
            while not stop.is_set() and not rospy.is_shutdown():
                if hasattr(msg, 'header'):
                    msg.header.stamp = rospy.Time.now()
                publisher.publish(msg)
                period.sleep()

        thread = threading.Thread(target=run)
        thread.daemon = True
        thread.start()
        return 'succeeded'

    def stop(self, topic):
        with self._lock:
            stop = self._stops.pop(topic, None)
        if stop is not None:
            stop.set()
        return 'succeeded'

    def stop_all(self):
        with self._lock:
            topics = list(self._stops)
        for topic in topics:
            self.stop(topic)
        return 'succeeded'
















class PublishMsgState(smach.State):
    """Starts or stops publishing a message through the script's MsgPublisher."""

    def __init__(self, name, msg_publisher, action, input_keys=['msg', 'topic', 'rate'],
                 output_keys=['msg', 'topic'], callbacks=[]):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=['succeeded', 'aborted'])
        self._name = name
        self._publisher = msg_publisher
        self._action = action
        # The parse function of each message class (parse_msg): points and poses are stamped.
        self._parsers = [(PointStamped, parse_pointstamped), (Point, parse_pointstamped),
                         (PoseStamped, parse_posestamped), (Pose, parse_posestamped),
                         (PoseArray, parse_posearray), (PointCloud, parse_pointcloud),
                         (PointCloud2, parse_pointcloud2)]
        
        self._cbs = []
        for cb_name in (callbacks or []):
            if cb_name in globals():
                self._cbs.append(globals()[cb_name])

        self._cb_input_keys = []
        self._cb_output_keys = []
        self._cb_outcomes = []
        for cb in self._cbs:
            if cb and smach.has_smach_interface(cb):
                self._cb_input_keys.append(cb.get_registered_input_keys())
                self._cb_output_keys.append(cb.get_registered_output_keys())
                self._cb_outcomes.append(cb.get_registered_outcomes())
                self.register_input_keys(self._cb_input_keys[-1])
                self.register_output_keys(self._cb_output_keys[-1])
                self.register_outcomes(self._cb_outcomes[-1])


    def execute(self, userdata):
        
        # Call the callbacks
        for (cb, input_keys, output_keys) in zip(self._cbs,
                                                 self._cb_input_keys,
                                                 self._cb_output_keys):
            cb(smach.Remapper(userdata, input_keys, output_keys, {}))

        topic = userdata.topic if 'topic' in self._input_keys else 'smacha/' + self._name.lower()
        if self._action == 'stop':
            return self._publisher.stop(topic)
        if self._action == 'stop_all':
            return self._publisher.stop_all()
        try:
            msg_type = userdata.msg_type if 'msg_type' in self._input_keys else None
            msg = parse_msg(userdata.msg, self._parsers, msg_type)
            rate = userdata.rate if 'rate' in self._input_keys else 100.0
            frame_id = userdata.frame_id if 'frame_id' in self._input_keys else ''
            outcome = self._publisher.start(msg, topic, rate, frame_id=frame_id)
        except Exception as e:
            rospy.logerr('Cannot publish on {}: {}'.format(topic, e))
            return 'aborted'
        for key in ['msg', 'output_msg', 'msg_output']:
            if key in self._output_keys:
                setattr(userdata, key, msg)
        for key in ['topic', 'output_topic', 'topic_output']:
            if key in self._output_keys:
                setattr(userdata, key, topic)
        return outcome

class ROSBagAPIThreadRecorder(object):
    """Records bag files with the rosbag API: per bag file, a thread that looks for the
    recorded topics on the master and subscribers that write their messages into the bag.
    Recordings still open when ROS shuts down are closed."""

    check_interval = 0.1  # seconds between looks at the master for the recorded topics

    class Recording(object):
        """One bag file being written."""

        def __init__(self, bag_file, topics, check_interval):
            self.bag = rosbag.Bag(bag_file, 'w')
            self.topics = set(rospy.resolve_name(topic) for topic in topics)  # empty: all
            self.lock = threading.Lock()
            self.subscribers = {}
            self.unknown = set()
            self.stopped = threading.Event()
            self.thread = threading.Thread(target=self._watch, args=(check_interval,))
            self.thread.daemon = True
            self.thread.start()

        def _watch(self, check_interval):
            while not self.stopped.is_set() and not rospy.is_shutdown():
                try:
                    published = rospy.get_published_topics()
                except Exception:
                    published = []  # the master did not answer: look again later
                for topic, type_name in published:
                    if topic in self.subscribers or (self.topics and topic not in self.topics):
                        continue
                    self._subscribe(topic, type_name)
                self.stopped.wait(check_interval)

        def _subscribe(self, topic, type_name):
            msg_class = roslib.message.get_message_class(type_name)
            if msg_class is None:
                if topic not in self.unknown:
                    rospy.logwarn('Cannot record {}: unknown type {}'.format(topic, type_name))
                    self.unknown.add(topic)
                return
            subscriber = rospy.Subscriber(topic, msg_class, self._write, callback_args=topic)
            with self.lock:
                if self.bag is not None:
                    self.subscribers[topic] = subscriber
                    return
            subscriber.unregister()  # closed meanwhile

        def _write(self, msg, topic):
            with self.lock:
                if self.bag is not None:
                    self.bag.write(topic, msg, rospy.Time.now())

        def close(self):
            self.stopped.set()
            self.thread.join()
            # The bag is taken away under the lock (a write in progress ends first, later
            # messages are dropped); rospy is called without it, so that no lock of rospy's
            # is ever waited for while a subscriber's callback waits for this one.
            with self.lock:
                bag, self.bag = self.bag, None
                subscribers, self.subscribers = list(self.subscribers.values()), {}
            for subscriber in subscribers:
                subscriber.unregister()
            bag.close()

    def __init__(self):
        self._lock = threading.Lock()
        self._recordings = {}
        rospy.on_shutdown(self.stop_all)

    def start(self, bag_file, topics):
        with self._lock:
            if bag_file in self._recordings:
                rospy.logerr('Already recording {}'.format(bag_file))
                return 'aborted'
            try:
                self._recordings[bag_file] = self.Recording(bag_file, topics, self.check_interval)
            except Exception as e:
                rospy.logerr('Cannot record {}: {}'.format(bag_file, e))
                return 'aborted'
        return 'succeeded'

    def stop(self, bag_file):
        with self._lock:
            recording = self._recordings.pop(bag_file, None)
        if recording is None:
            rospy.logerr('Not recording {}'.format(bag_file))
            return 'aborted'
        try:
            recording.close()
        except Exception as e:
            rospy.logerr('Cannot close {}: {}'.format(bag_file, e))
            return 'aborted'
        return 'succeeded'

    def stop_all(self):
        with self._lock:
            bag_files = list(self._recordings)
        outcomes = [self.stop(bag_file) for bag_file in bag_files]
        return 'aborted' if 'aborted' in outcomes else 'succeeded'
















class RecordROSBagState(smach.State):
    """Starts or stops a recording of the script's bag recorder."""

    def __init__(self, name, bag_recorder, action, input_keys=['file', 'topics'], output_keys=[],
                 callbacks=[]):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=['succeeded', 'aborted'])
        self._name = name
        self._recorder = bag_recorder
        self._action = action
        
        self._cbs = []
        for cb_name in (callbacks or []):
            if cb_name in globals():
                self._cbs.append(globals()[cb_name])

        self._cb_input_keys = []
        self._cb_output_keys = []
        self._cb_outcomes = []
        for cb in self._cbs:
            if cb and smach.has_smach_interface(cb):
                self._cb_input_keys.append(cb.get_registered_input_keys())
                self._cb_output_keys.append(cb.get_registered_output_keys())
                self._cb_outcomes.append(cb.get_registered_outcomes())
                self.register_input_keys(self._cb_input_keys[-1])
                self.register_output_keys(self._cb_output_keys[-1])
                self.register_outcomes(self._cb_outcomes[-1])


    def execute(self, userdata):
        
        # Call the callbacks
        for (cb, input_keys, output_keys) in zip(self._cbs,
                                                 self._cb_input_keys,
                                                 self._cb_output_keys):
            cb(smach.Remapper(userdata, input_keys, output_keys, {}))

        if self._action == 'stop_all':
            return self._recorder.stop_all()
        if self._action not in ('start', 'record', 'stop'):
            rospy.logerr('Unknown action {} (start, record, stop or stop_all)'.format(self._action))
            return 'aborted'
        bag_file = userdata.file if 'file' in self._input_keys else None
        if not isinstance(bag_file, str) or not bag_file:
            rospy.logerr('The input key file must name the bag file, not {!r}'.format(bag_file))
            return 'aborted'
        if self._action == 'stop':
            return self._recorder.stop(bag_file)
        topics = userdata.topics if 'topics' in self._input_keys else []
        if isinstance(topics, str):
            topics = [topics] if topics else []
        if not all(isinstance(topic, str) for topic in topics):
            rospy.logerr('The input key topics must list topic names, not {!r}'.format(topics))
            return 'aborted'
        return self._recorder.start(bag_file, list(topics))

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

class CallbacksState(smach.State):
    """Runs its callbacks on the userdata, then succeeds."""

    def __init__(self, input_keys=[], output_keys=[], callbacks=[], outcomes=['succeeded']):
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=outcomes)
        
        self._cbs = []
        for cb_name in (callbacks or []):
            if cb_name in globals():
                self._cbs.append(globals()[cb_name])

        self._cb_input_keys = []
        self._cb_output_keys = []
        self._cb_outcomes = []
        for cb in self._cbs:
            if cb and smach.has_smach_interface(cb):
                self._cb_input_keys.append(cb.get_registered_input_keys())
                self._cb_output_keys.append(cb.get_registered_output_keys())
                self._cb_outcomes.append(cb.get_registered_outcomes())
                self.register_input_keys(self._cb_input_keys[-1])
                self.register_output_keys(self._cb_output_keys[-1])
                self.register_outcomes(self._cb_outcomes[-1])


    def execute(self, userdata):
        
        # Call the callbacks
        for (cb, input_keys, output_keys) in zip(self._cbs,
                                                 self._cb_input_keys,
                                                 self._cb_output_keys):
            cb(smach.Remapper(userdata, input_keys, output_keys, {}))

        return 'succeeded'

class ConditionalOutcomeState(smach.State):
    """Ends with the first outcome whose callback output is true, else `default`."""

    def __init__(self, input_keys=[], output_keys=[], callbacks=[], outcomes=[]):
        # Each condition's callback writes the key named like the outcome, which execute()
        # then reads: it is both an output and an input key.
        self._conditions = [o for o in outcomes if o != 'default']
        input_keys = list(input_keys) + [o for o in self._conditions if o not in input_keys]
        output_keys = list(output_keys) + [o for o in self._conditions if o not in output_keys]
        if 'outcome' not in output_keys:
            output_keys.append('outcome')
        smach.State.__init__(self, input_keys=input_keys, output_keys=output_keys,
                             outcomes=self._conditions + ['default'])
        
        self._cbs = []
        for cb_name in (callbacks or []):
            if cb_name in globals():
                self._cbs.append(globals()[cb_name])

        self._cb_input_keys = []
        self._cb_output_keys = []
        self._cb_outcomes = []
        for cb in self._cbs:
            if cb and smach.has_smach_interface(cb):
                self._cb_input_keys.append(cb.get_registered_input_keys())
                self._cb_output_keys.append(cb.get_registered_output_keys())
                self._cb_outcomes.append(cb.get_registered_outcomes())
                self.register_input_keys(self._cb_input_keys[-1])
                self.register_output_keys(self._cb_output_keys[-1])
                self.register_outcomes(self._cb_outcomes[-1])


    def execute(self, userdata):
        
        # Call the callbacks
        for (cb, input_keys, output_keys) in zip(self._cbs,
                                                 self._cb_input_keys,
                                                 self._cb_output_keys):
            cb(smach.Remapper(userdata, input_keys, output_keys, {}))

        for outcome in self._conditions:
            if outcome in userdata and userdata[outcome]:
                userdata.outcome = outcome
                return outcome
        userdata.outcome = 'default'
        return 'default'


@smach.cb_interface(input_keys=['point_bag', 'both_bag'],
                    output_keys=['point_bag_topics'],
                    outcomes=[])
def point_bag_topics_read_back_032ece6c7e0c4587a501b14eff50f20f_lambda_cb(userdata):
    lambda_cb = lambda ud: {topic: [info.msg_type, info.message_count] for topic, info in rosbag.Bag(ud.point_bag).get_type_and_topic_info().topics.items()}
    userdata.point_bag_topics = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=['point_bag', 'both_bag'],
                    output_keys=['both_bag_topics'],
                    outcomes=[])
def both_bag_topics_read_back_032ece6c7e0c4587a501b14eff50f20f_lambda_cb(userdata):
    lambda_cb = lambda ud: {topic: [info.msg_type, info.message_count] for topic, info in rosbag.Bag(ud.both_bag).get_type_and_topic_info().topics.items()}
    userdata.both_bag_topics = lambda_cb(userdata)
    return 'succeeded'

@smach.cb_interface(input_keys=['point_bag_topics', 'both_bag_topics'],
                    output_keys=['ok'],
                    outcomes=['ok', 'default'])
def ok_check_31db3352cc014f299504f13716cd56e8_lambda_cb(userdata):
    lambda_cb = lambda ud: sorted(ud.point_bag_topics) == ["/smachac/bag/point"] and sorted(ud.both_bag_topics) == ["/smachac/bag/point", "/smachac/bag/pose"] and ud.point_bag_topics["/smachac/bag/point"][0] == "geometry_msgs/PointStamped" and ud.both_bag_topics["/smachac/bag/pose"][0] == "geometry_msgs/PoseStamped" and ud.point_bag_topics["/smachac/bag/point"][1] >= 25 and ud.both_bag_topics["/smachac/bag/pose"][1] >= 25 and 25 <= ud.both_bag_topics["/smachac/bag/point"][1] - ud.point_bag_topics["/smachac/bag/point"][1] <= 100
    userdata.ok = lambda_cb(userdata)
    return 'succeeded'


def main():
    rospy.init_node('ros_rosbag_api')

    msg_publisher = MsgPublisher()

    bag_recorder = ROSBagAPIThreadRecorder()
    ros_rosbag_api = smach.StateMachine(outcomes=['done', 'failed', 'wrong'])
    ros_rosbag_api.userdata.rate = 100.0

    ros_rosbag_api.userdata.rate = 100.0

    ros_rosbag_api.userdata.topics = ''

    ros_rosbag_api.userdata.file = ''
    ros_rosbag_api.userdata.topics = ''

    ros_rosbag_api.userdata.rate = 100.0
    ros_rosbag_api.userdata.topic = ''
    ros_rosbag_api.userdata.both_bag = 'api_both.bag'
    ros_rosbag_api.userdata.both_topics = ['/smachac/bag/point', 'smachac/bag/pose']
    ros_rosbag_api.userdata.point = [1.0, 2.0, 3.0]
    ros_rosbag_api.userdata.point_bag = 'api_point.bag'
    ros_rosbag_api.userdata.point_topic = '/smachac/bag/point'
    ros_rosbag_api.userdata.point_topics = ['/smachac/bag/point']
    ros_rosbag_api.userdata.pose = [[1.0, 2.0, 3.0], [0.0, 0.0, 0.0, 1.0]]
    ros_rosbag_api.userdata.pose_topic = '/smachac/bag/pose'
    ros_rosbag_api.userdata.rate = 50.0


    with ros_rosbag_api:
        smach.StateMachine.add('PUBLISH_POINT',
                               PublishMsgState('PUBLISH_POINT', msg_publisher, 'start', input_keys = ['msg', 'topic', 'rate']),
                               transitions={'aborted':'failed',
                                            'succeeded':'PUBLISH_POSE'},
                               remapping={'msg':'point',
                                          'topic':'point_topic'})

        smach.StateMachine.add('PUBLISH_POSE',
                               PublishMsgState('PUBLISH_POSE', msg_publisher, 'start', input_keys = ['msg', 'topic', 'rate']),
                               transitions={'aborted':'failed',
                                            'succeeded':'RECORD_POINT'},
                               remapping={'msg':'pose',
                                          'topic':'pose_topic'})

        smach.StateMachine.add('RECORD_POINT',
                               RecordROSBagState('RECORD_POINT', bag_recorder, 'start'),
                               transitions={'aborted':'failed',
                                            'succeeded':'RECORD_BOTH'},
                               remapping={'file':'point_bag',
                                          'topics':'point_topics'})

        smach.StateMachine.add('RECORD_BOTH',
                               RecordROSBagState('RECORD_BOTH', bag_recorder, 'start'),
                               transitions={'aborted':'failed',
                                            'succeeded':'RECORDING'},
                               remapping={'file':'both_bag',
                                          'topics':'both_topics'})

        smach.StateMachine.add('RECORDING',
                               SleepState(2.0),
                               transitions={'succeeded':'STOP_POINT'})

        smach.StateMachine.add('STOP_POINT',
                               RecordROSBagState('STOP_POINT', bag_recorder, 'stop', input_keys = ['file']),
                               transitions={'aborted':'failed',
                                            'succeeded':'STILL_RECORDING'},
                               remapping={'file':'point_bag'})

        smach.StateMachine.add('STILL_RECORDING',
                               SleepState(1.0),
                               transitions={'succeeded':'STOP_ALL'})

        smach.StateMachine.add('STOP_ALL',
                               RecordROSBagState('STOP_ALL', bag_recorder, 'stop_all'),
                               transitions={'aborted':'failed',
                                            'succeeded':'UNPUBLISH'})

        smach.StateMachine.add('UNPUBLISH',
                               PublishMsgState('UNPUBLISH', msg_publisher, 'stop_all'),
                               transitions={'aborted':'failed',
                                            'succeeded':'READ_BACK'})

        smach.StateMachine.add('READ_BACK',
                               CallbacksState(input_keys = ['point_bag', 'both_bag'], output_keys = ['point_bag_topics', 'both_bag_topics'], callbacks = ['point_bag_topics_read_back_032ece6c7e0c4587a501b14eff50f20f_lambda_cb', 'both_bag_topics_read_back_032ece6c7e0c4587a501b14eff50f20f_lambda_cb']),
                               transitions={'succeeded':'CHECK'})

        smach.StateMachine.add('CHECK',
                               ConditionalOutcomeState(input_keys = ['point_bag_topics', 'both_bag_topics'], callbacks = ['ok_check_31db3352cc014f299504f13716cd56e8_lambda_cb'], outcomes=['ok', 'default']),
                               transitions={'default':'wrong',
                                            'ok':'done'})

    outcome = ros_rosbag_api.execute()


if __name__ == '__main__':
    main()
