"""PNG snapshots of the simulated scene, numbered in the order taken (NNN_<label>.png), only
when a folder is given."""
import os

import rospy


class Snapshots:
    def __init__(self, robot, folder):
        self.robot = robot
        self.folder = folder
        self.count = 0
        if folder:
            os.makedirs(folder, exist_ok=True)

    def take(self, label):
        if not self.folder:
            return
        path = os.path.join(self.folder, "%03d_%s.png" % (self.count, label))
        self.count += 1
        error = self.robot.snapshot(path)
        if error:
            rospy.logwarn("snapshot %s failed: %s", path, error)
