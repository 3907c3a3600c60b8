"""The bag files a SMACHA rosbag script records, for smacha_corpus.py.

SMACHA's rosbag scripts name absolute bag files in /tmp (`/tmp/rosbag_api_recording_1.bag`)
and cannot be changed, so a run of one holds an exclusive lock on /tmp (flock of the folder:
two runs, of this test or another's, never write the same file at once), deletes what an
earlier run may have left, and after the run reads the bags back and deletes them.

    with Bags(script_text) as bags:       # nothing to do for a script that records nothing
        ...run the program...
        problem = bags.problem()          # None, or what is wrong with the bags
    bags.summary()                        # " (bags: NAME TOPIC=COUNT ...)" for the report
"""
import fcntl
import os

import rosbag
import yaml

RECORD_ACTIONS = ("start", "record")


def recordings(script_text):
    """{bag file: [topic, ...]} of the RecordROSBagStates that start a recording, their file
    and topics read from the userdata their remapping names (state's, then the script's)."""
    script = yaml.safe_load(script_text) or {}
    found = {}

    def visit(states, userdata):
        for entry in states or []:
            for state in entry.values():
                data = dict(userdata, **(state.get("userdata") or {}))
                visit(state.get("states"), data)
                if state.get("template") != "RecordROSBagState" or \
                        state.get("action") not in RECORD_ACTIONS:
                    continue
                remapping = state.get("remapping") or {}
                bag = data.get(remapping.get("file", "file"))
                topics = data.get(remapping.get("topics", "topics")) or []
                found[bag] = ["/" + t.lstrip("/") for t in topics]

    visit(script.get("states"), script.get("userdata") or {})
    return found


class Bags:
    def __init__(self, script_text):
        self.expected = recordings(script_text)
        self.found = {}
        self._lock = None

    def __enter__(self):
        if self.expected:
            self._lock = os.open("/tmp", os.O_RDONLY)
            fcntl.flock(self._lock, fcntl.LOCK_EX)
            self._delete()
        return self

    def __exit__(self, *_exc):
        if self._lock is not None:
            self._delete()
            os.close(self._lock)  # releases the lock
        return False

    def _delete(self):
        for bag in self.expected:
            for path in (bag, bag + ".active"):
                if os.path.isfile(path):
                    os.remove(path)

    def problem(self):
        """None when every bag holds exactly its topics, each with messages."""
        for bag, topics in self.expected.items():
            if not os.path.isfile(bag):
                return "no bag file %s" % bag
            with rosbag.Bag(bag) as b:
                info = b.get_type_and_topic_info().topics
            self.found[bag] = {topic: info[topic].message_count for topic in sorted(info)}
            if sorted(info) != sorted(topics):
                return "%s holds %s, expected %s" % (bag, sorted(info), sorted(topics))
            empty = [topic for topic in topics if info[topic].message_count == 0]
            if empty:
                return "%s has no message of %s" % (bag, ", ".join(empty))
        return None

    def summary(self):
        if not self.found:
            return ""
        return " (bags: %s)" % "; ".join(
            "%s %s" % (os.path.basename(bag), " ".join("%s=%d" % kv for kv in counts.items()))
            for bag, counts in sorted(self.found.items()))
