"""Holds simulated time while a program connects to the robot's topics.

The Baxter SDK waits for the first message of a topic it subscribes to (robot state, joint
states, gripper state) with a timeout in simulated time. On a busy machine connecting can take
longer than the simulation needs to run through that timeout, so the node asks the master,
every few ticks, who subscribes to its topics: while a subscriber registered there is not yet
connected, simulated time stands still (for at most `patience` seconds of wall time per
subscriber, so that one that never connects, or has died, does not stop the robot).

Before the first program arrives, time does not start at all: a program that starts its
first wait before its first /clock message computes the deadline from time 0, and would miss
it at once if the simulation had already run for longer than the timeout.
"""
import time

import rosgraph


class ConnectionGate:
    def __init__(self, node_name, publishers, patience=5.0, every=25):
        self.node_name = node_name
        self.publishers = dict(publishers)  # topic -> rospy.Publisher
        self.patience = patience
        self.every = every
        self.master = rosgraph.Master(node_name)
        self.given_up = set()  # (topic, subscriber) pairs not waited for any more
        self.own = set()  # topics this node subscribes to itself
        self.ticks = 0

    def wait(self):
        """Returns once every subscriber the master lists is connected (checked every
        `every` calls), or patience has run out for those that are not."""
        self.ticks += 1
        if self.ticks % self.every:
            return
        deadline = time.monotonic() + self.patience
        while True:
            pending = self.pending()
            if not pending:
                return
            if time.monotonic() > deadline:
                self.given_up |= pending
                return
            time.sleep(0.01)

    def subscribed(self, topic):
        """Whether a node other than this one subscribes to `topic`, connected."""
        others = self.subscribers().get(topic, [])
        return bool(others) and self.connected_others(topic) >= len(others)

    def subscribers(self):
        """{topic: [subscribing nodes other than this one]} of the robot's topics."""
        try:
            _publishers, subscribers, _services = self.master.getSystemState()
        except Exception:  # the master is gone: nobody to wait for
            return {}
        self.own = {topic for topic, names in subscribers if self.node_name in names}
        return {topic: [n for n in names if n != self.node_name]
                for topic, names in subscribers if topic in self.publishers}

    def connected_others(self, topic):
        """Connections of the topic's publisher less this node's own subscription (with
        simulated time the node subscribes to its own /clock)."""
        return self.publishers[topic].get_num_connections() - (topic in self.own)

    def pending(self):
        """(topic, subscriber) pairs registered with the master beyond the connections."""
        pending = set()
        for topic, names in self.subscribers().items():
            others = [n for n in names if (topic, n) not in self.given_up]
            if len(others) > self.connected_others(topic):
                pending |= {(topic, n) for n in others}
        return pending
