{% block meta %}
name: MsgPublisher
description: >
  Helper included by PublishMsgState: one object per script that keeps
  publishing messages on topics at given rates, in background threads, until
  stopped.
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
{% if 'class_MsgPublisher' not in defined_headers %}
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
{% do defined_headers.append('class_MsgPublisher') %}
{% endif %}
{% endblock class_defs %}
