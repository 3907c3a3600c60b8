{% block meta %}
name: ROSBagAPIThreadRecorder
description: >
  Helper class of RecordROSBagState (with `recorder:
  ROSBagAPIThreadRecorder`): records bag files with the rosbag Python API in
  this program, a thread per bag subscribing to the recorded topics as they
  appear on the master (recording shares this program's Python threads).
language: Python
framework: SMACH
type: None
tags: [core, ros]
includes: []
extends: []
variables: []
input_keys: []
output_keys: []
outcomes: []
{% endblock meta %}
{% from "Utils.tpl.py" import import_module %}
{% block imports %}
{{ import_module(defined_headers, 'rospy') }}
{{ import_module(defined_headers, 'rosbag') }}
{{ import_module(defined_headers, 'roslib.message') }}
{{ import_module(defined_headers, 'threading') }}
{% endblock imports %}

{% block class_defs %}
{% if 'class_ROSBagAPIThreadRecorder' not in defined_headers %}
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
{% do defined_headers.append('class_ROSBagAPIThreadRecorder') %}
{% endif %}
{% endblock class_defs %}
