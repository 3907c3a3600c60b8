{% block meta %}
name: MsgPublisherObserver
description: >
  Helper class of PublishObserverMsgState: publishes its messages, each on
  its topic, every time a message arrives on the topic it observes (e.g. tf),
  so that they go out at that topic's rate.
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
{{ import_module(defined_headers, 'threading') }}
{% endblock imports %}

{% block class_defs %}
{% if 'class_MsgPublisherObserver' not in defined_headers %}
class MsgPublisherObserver(object):
    """Publishes messages on their topics whenever a message arrives on sub_topic."""

    def __init__(self, sub_topic='tf'):
        self._sub_topic = sub_topic
        self._subscriber = None
        self._lock = threading.Lock()
        self._msgs = {}
        self._publishers = {}

    def _observed(self, _msg):
        with self._lock:
            outgoing = [(self._publishers[topic], msg) for topic, msg in self._msgs.items()]
        for publisher, msg in outgoing:
            if hasattr(msg, 'header'):
                msg.header.stamp = rospy.Time.now()
            try:
                publisher.publish(msg)
            except rospy.ROSException as e:
                rospy.logwarn('Cannot publish on {}: {}'.format(publisher.resolved_name, e))

    def add(self, msg, topic, frame_id=None):
        if frame_id and hasattr(msg, 'header'):
            msg.header.frame_id = frame_id
        try:
            publisher = rospy.Publisher(topic, type(msg), queue_size=10)
        except Exception as e:
            rospy.logerr('Cannot publish on {}: {}'.format(topic, e))
            return 'aborted'
        with self._lock:
            previous = self._publishers.pop(topic, None)
            self._msgs[topic] = msg
            self._publishers[topic] = publisher
            if self._subscriber is None:
                # Any message type: only the arrival times matter.
                self._subscriber = rospy.Subscriber(self._sub_topic, rospy.AnyMsg,
                                                    self._observed, queue_size=1)
        if previous is not None and previous is not publisher:
            previous.unregister()
        return 'succeeded'

    def remove(self, topic):
        with self._lock:
            self._msgs.pop(topic, None)
            publisher = self._publishers.pop(topic, None)
        if publisher is not None:
            publisher.unregister()
        return 'succeeded'

    def remove_all(self):
        with self._lock:
            topics = list(self._publishers)
        for topic in topics:
            self.remove(topic)
        return 'succeeded'
{% do defined_headers.append('class_MsgPublisherObserver') %}
{% endif %}
{% endblock class_defs %}
