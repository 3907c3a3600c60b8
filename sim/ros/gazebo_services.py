"""Gazebo's model services over the simulation: /gazebo/spawn_sdf_model and
/gazebo/spawn_urdf_model place a body of the MuJoCo scene (table, block1, block2) at the
requested pose, at rest, and /gazebo/delete_model forgets it. MuJoCo 2.2 cannot add or
remove bodies, so only the scene's bodies can be spawned, and a deleted one stays where it is
until it is spawned again. A model's frame is its centre (a block's) or its origin (the
table's), as in the project's own model files (sim/ros/baxter_sim_examples)."""
import xml.etree.ElementTree as ElementTree

import rospy
from gazebo_msgs.srv import DeleteModel, DeleteModelResponse, SpawnModel, SpawnModelResponse

FRAMES = {"": "world", "world": "world", "map": "world", "base": "base",
          "baxter::base": "base"}


class GazeboServices:
    def __init__(self, robot):
        self.robot = robot
        self.spawned = set()
        rospy.Service("/gazebo/spawn_sdf_model", SpawnModel, self.spawn)
        rospy.Service("/gazebo/spawn_urdf_model", SpawnModel, self.spawn)
        rospy.Service("/gazebo/delete_model", DeleteModel, self.delete)

    def spawn(self, request):
        problem = self.spawn_problem(request)
        if problem:
            return SpawnModelResponse(success=False, status_message="SpawnModel: " + problem)
        self.spawned.add(request.model_name)
        return SpawnModelResponse(success=True,
                                  status_message="SpawnModel: Successfully spawned entity")

    def spawn_problem(self, request):
        try:
            ElementTree.fromstring(request.model_xml)
        except ElementTree.ParseError as error:
            return "the model's XML does not parse: %s" % error
        frame = FRAMES.get(request.reference_frame)
        if frame is None:
            return "unknown reference frame %r" % request.reference_frame
        p, o = request.initial_pose.position, request.initial_pose.orientation
        return self.robot.place_body(request.model_name, [p.x, p.y, p.z, o.x, o.y, o.z, o.w],
                                     frame)

    def delete(self, request):
        if request.model_name not in self.spawned:
            return DeleteModelResponse(success=False,
                                       status_message="DeleteModel: model [%s] does not exist"
                                       % request.model_name)
        self.spawned.discard(request.model_name)
        return DeleteModelResponse(success=True,
                                   status_message="DeleteModel: successfully deleted model")
