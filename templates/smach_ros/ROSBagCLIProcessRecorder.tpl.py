{% block meta %}
name: ROSBagCLIProcessRecorder
description: >
  Helper class of RecordROSBagState (its default recorder): records each bag
  file with its own process of rosbag's command-line recorder (the program
  `rosbag record` runs), so that recording runs outside this program's Python
  threads. Stopping a recording interrupts the process and waits until it has
  closed the bag.
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
{{ import_module(defined_headers, 'roslib.packages') }}
{{ import_module(defined_headers, 'signal') }}
{{ import_module(defined_headers, 'subprocess') }}
{{ import_module(defined_headers, 'threading') }}
{% endblock imports %}

{% block class_defs %}
{% if 'class_ROSBagCLIProcessRecorder' not in defined_headers %}
class ROSBagCLIProcessRecorder(object):
    """Records bag files with rosbag's command-line recorder, one process per bag file: the
    program that `rosbag record` starts, run directly so that stopping it (SIGINT) can wait
    until the bag is closed. A bag file name without `.bag` is a prefix: rosbag adds the date
    and time. Recordings still running when ROS shuts down are stopped."""

    stop_timeout = 20.0  # seconds to wait for a `rosbag record` to close its bag

    def __init__(self):
        self._lock = threading.Lock()
        self._processes = {}
        rospy.on_shutdown(self.stop_all)

    def start(self, bag_file, topics):
        record = roslib.packages.find_node('rosbag', 'record')
        if not record:
            rospy.logerr('Cannot record {}: rosbag\'s record program is not installed'.format(
                bag_file))
            return 'aborted'
        command = [record[0], '--quiet']
        command += ['--output-name' if bag_file.endswith('.bag') else '--output-prefix', bag_file]
        command += [rospy.resolve_name(topic) for topic in topics] if topics else ['--all']
        with self._lock:
            if bag_file in self._processes:
                rospy.logerr('Already recording {}'.format(bag_file))
                return 'aborted'
            try:
                # In this program's process group: whatever stops the program stops it too.
                self._processes[bag_file] = subprocess.Popen(
                    command, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL)
            except OSError as e:
                rospy.logerr('Cannot run {}: {}'.format(' '.join(command), e))
                return 'aborted'
        rospy.loginfo('Recording {}: {}'.format(bag_file, ' '.join(command)))
        return 'succeeded'

    def stop(self, bag_file):
        with self._lock:
            process = self._processes.pop(bag_file, None)
        if process is None:
            rospy.logerr('Not recording {}'.format(bag_file))
            return 'aborted'
        if process.poll() is None:
            process.send_signal(signal.SIGINT)  # record closes the bag and exits
        try:
            process.wait(timeout=self.stop_timeout)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()
            rospy.logerr('The recording of {} did not stop; killed'.format(bag_file))
            return 'aborted'
        return 'succeeded'

    def stop_all(self):
        with self._lock:
            bag_files = list(self._processes)
        outcomes = [self.stop(bag_file) for bag_file in bag_files]
        return 'aborted' if 'aborted' in outcomes else 'succeeded'
{% do defined_headers.append('class_ROSBagCLIProcessRecorder') %}
{% endif %}
{% endblock class_defs %}
