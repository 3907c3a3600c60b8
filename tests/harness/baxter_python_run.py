#!/usr/bin/env python3
"""Runs the Baxter state classes of the expected SMACH and FlexBE outputs against stand-ins
for the Baxter SDK, ROS 1, Gazebo's services, SMACH and flexbe_core (none is installed here),
and checks what each state does: the services it calls and with what, the limb and gripper
commands, the userdata it writes and the outcome.

  baxter_python_run.py <tests/golden>

The classes come from smach_baxter/all_variables.smach.py and the states module of
flexbe_baxter/all_variables.flexbe.py (the cases that use every Baxter template). The
stand-ins only record calls and return what a scenario sets; the assertions are about the
generated code.
"""
import importlib.util
import os
import sys
import tempfile
import types

STUBS = {
    "rospy": '''
class ROSException(Exception): pass
class ServiceException(Exception): pass
class Duration:
    def __init__(self, secs=0.0): self.secs = secs
class Time:
    @staticmethod
    def now(): return "now"
clock = [0.0]
def get_time():
    clock[0] += 0.1
    return clock[0]
log = []
def logerr(*a): log.append(("err",) + a)
def logwarn(*a): log.append(("warn",) + a)
def loginfo(*a): log.append(("info",) + a)
services = {}
calls = []
def wait_for_service(name, timeout=None):
    if name not in services: raise ROSException("no service " + name)
class ServiceProxy:
    def __init__(self, name, kind): self.name = name
    def __call__(self, *args, **fields):
        calls.append((self.name, args, fields))
        return services[self.name](*args, **fields)
''',
    "smach": '''
class State:
    def __init__(self, outcomes=(), input_keys=(), output_keys=()):
        self.outcomes, self._input_keys, self.output_keys = list(outcomes), tuple(input_keys), list(output_keys)
    def get_registered_input_keys(self): return self._input_keys
    def preempt_requested(self): return False
    def service_preempt(self): pass
''',
    "flexbe_core": '''
class EventState:
    def __init__(self, outcomes=(), input_keys=(), output_keys=()):
        self.outcomes, self.input_keys, self.output_keys = list(outcomes), list(input_keys), list(output_keys)
class Logger:
    log = []
    @staticmethod
    def logerr(text): Logger.log.append(("err", text))
    @staticmethod
    def logwarn(text): Logger.log.append(("warn", text))
''',
    "baxter_interface": '''
CHECK_VERSION = True
enabled = []
class RobotEnable:
    def __init__(self, versioned): pass
    def enable(self): enabled.append(True)
class Point:
    def __init__(self, x, y, z): self.x, self.y, self.z = x, y, z
class Limb:
    reach = True
    angles = {}
    commands = []
    def __init__(self, limb): self.limb = limb
    def joint_names(self): return [self.limb + "_" + j for j in ("s0", "s1", "e0", "e1", "w0", "w1", "w2")]
    def joint_angles(self): return dict(Limb.angles) if Limb.angles else {n: 0.0 for n in self.joint_names()}
    def set_joint_position_speed(self, speed): Limb.commands.append(("speed", speed))
    def _command(self, goal):
        Limb.commands.append(("goal", dict(goal)))
        if Limb.reach: Limb.angles = dict(goal)
    def move_to_joint_positions(self, goal, timeout, threshold, test):
        Limb.commands.append(("timeout", timeout))
        self._command(goal)
    def set_joint_positions(self, goal): self._command(goal)
    def endpoint_pose(self):
        q = Point(0.1, 0.2, 0.3); q.w = 0.9
        return {"position": Point(0.7, -0.15, 0.02), "orientation": q}
class Gripper:
    holds = True
    commands = []
    def __init__(self, limb, versioned): self.limb = limb
    def calibrated(self): return False
    def calibrate(self): Gripper.commands.append((self.limb, "calibrate"))
    def open(self, block=False, timeout=5.0): Gripper.commands.append((self.limb, "open"))
    def close(self, block=False, timeout=5.0): Gripper.commands.append((self.limb, "close"))
    def moving(self): return False
    def gripping(self): return Gripper.holds
''',
    "rospkg": '''
class ResourceNotFound(Exception): pass
class RosPack:
    def get_path(self, package): return __import__("os").environ["BAXTER_SIM_EXAMPLES"]
''',
    "actionlib": '''
goals = []
error_code = [0]
class SimpleActionClient:
    def __init__(self, name, action): self.name = name
    def wait_for_server(self, timeout): return True
    def send_goal(self, goal): goals.append((self.name, goal))
    def wait_for_result(self, timeout): return True
    def get_result(self):
        from control_msgs.msg import FollowJointTrajectoryResult
        return FollowJointTrajectoryResult(error_code=error_code[0])
    def cancel_goal(self): pass
''',
}
MESSAGES = {  # module: {class: positional fields}
    "geometry_msgs.msg": {"Point": "x y z", "Quaternion": "x y z w", "Pose": "", "PoseStamped": ""},
    "std_msgs.msg": {"Header": ""},
    "gazebo_msgs.srv": {"DeleteModel": "", "SpawnModel": ""},
    "baxter_core_msgs.srv": {"SolvePositionIK": ""},
    "control_msgs.msg": {"FollowJointTrajectoryAction": "", "FollowJointTrajectoryResult": ""},
    "trajectory_msgs.msg": {"JointTrajectoryPoint": ""},
}
MESSAGE_BASE = '''
class Message:
    FIELDS = ""
    def __init__(self, *args, **fields):
        for name, value in zip(self.FIELDS.split(), args): setattr(self, name, value)
        self.__dict__.update(fields)
'''
EXTRA = {
    "baxter_core_msgs.srv": "class SolvePositionIKRequest(Message):\n"
                            "    def __init__(self): self.pose_stamp = []\n",
    "control_msgs.msg": "FollowJointTrajectoryResult.SUCCESSFUL = 0\n"
                        "class FollowJointTrajectoryGoal(Message):\n"
                        "    def __init__(self): self.trajectory = Message(header=Message(), points=[])\n",
}


def write_stubs(directory):
    for name, source in STUBS.items():
        with open(os.path.join(directory, name + ".py"), "w") as f:
            f.write(source)
    for module, classes in MESSAGES.items():
        package, sub = module.split(".")
        os.makedirs(os.path.join(directory, package), exist_ok=True)
        open(os.path.join(directory, package, "__init__.py"), "w").close()
        with open(os.path.join(directory, package, sub + ".py"), "w") as f:
            f.write(MESSAGE_BASE)
            for cls, fields in classes.items():
                f.write(f"class {cls}(Message):\n    FIELDS = {fields!r}\n")
            f.write(EXTRA.get(module, ""))
    models = os.path.join(directory, "models")
    for model, text in (("block/model.urdf", "<robot name='block'/>"),
                        ("cafe_table/model.sdf", "<sdf/>")):
        os.makedirs(os.path.dirname(os.path.join(models, model)), exist_ok=True)
        with open(os.path.join(models, model), "w") as f:
            f.write(text)
    os.environ["BAXTER_SIM_EXAMPLES"] = directory


def load_module(name, text, directory):
    path = os.path.join(directory, name + ".py")
    with open(path, "w") as f:
        f.write(text)
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def flexbe_states_module(expected_path):
    text, inside = "", False
    with open(expected_path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("#==> "):
                inside = line.rstrip().endswith("_states.py <==")
            elif inside:
                text += line
    return text


class Userdata:
    def __init__(self, **keys):
        self.__dict__.update(keys)


def run(state, flexbe, **keys):
    """(outcome, userdata): SMACH runs execute() once, FlexBE polls it after on_enter()."""
    userdata = Userdata(**keys)
    if flexbe:
        state.on_enter(userdata)
    for _ in range(1000):
        outcome = state.execute(userdata)
        if outcome is not None or not flexbe:
            return outcome, userdata.__dict__
    return None, userdata.__dict__


class Checker:
    def __init__(self, label):
        self.label, self.failures = label, []

    def equal(self, what, actual, expected):
        if actual != expected:
            self.failures.append(f"{self.label}: {what}: {actual!r}, expected {expected!r}")

    def close(self, what, actual, expected, tolerance=1e-9):
        if len(actual) != len(expected) or any(abs(a - b) > tolerance
                                               for a, b in zip(actual, expected)):
            self.failures.append(f"{self.label}: {what}: {actual!r}, expected {expected!r}")


def reset():
    import actionlib
    import baxter_interface
    import rospy
    rospy.calls.clear()
    rospy.services.clear()
    baxter_interface.Limb.reach, baxter_interface.Limb.angles = True, {}
    baxter_interface.Limb.commands.clear()
    baxter_interface.Gripper.holds = True
    baxter_interface.Gripper.commands.clear()
    actionlib.goals.clear()
    actionlib.error_code[0] = 0
    return rospy, baxter_interface, actionlib


def check_load(m, flexbe, c):
    rospy, _, _ = reset()
    response = types.SimpleNamespace(success=True, status_message="")
    for name in ("/gazebo/delete_model", "/gazebo/spawn_urdf_model", "/gazebo/spawn_sdf_model"):
        rospy.services[name] = lambda *a, **k: response
    state = m.LoadGazeboModelState(model_name="block1", input_keys=["pose", "reference_frame"])
    outcome, _ = run(state, flexbe, pose=[[0.7, 0.15, -0.13], [0.0, 0.0, 0.0, 1.0]],
                     reference_frame="base")
    c.equal("load block1", outcome, "succeeded")
    c.equal("delete call", rospy.calls[0][:2], ("/gazebo/delete_model", ("block1",)))
    name, _, spawn = rospy.calls[1]
    c.equal("spawn service", name, "/gazebo/spawn_urdf_model")
    c.equal("spawn fields", (spawn["model_name"], spawn["model_xml"], spawn["reference_frame"]),
            ("block1", "<robot name='block'/>", "baxter::base"))
    p, q = spawn["initial_pose"].position, spawn["initial_pose"].orientation
    c.close("spawn pose", [p.x, p.y, p.z, q.x, q.y, q.z, q.w], [0.7, 0.15, -0.13, 0, 0, 0, 1])
    rospy.calls.clear()
    outcome, _ = run(m.LoadGazeboModelState(model_name="table", pose=[[1, 0, 0], [0, 0, 0, 0]]),
                     flexbe)
    q = rospy.calls[1][2]["initial_pose"].orientation
    c.equal("table", (outcome, rospy.calls[1][0], rospy.calls[1][2]["reference_frame"]),
            ("succeeded", "/gazebo/spawn_sdf_model", "world"))
    c.close("zero rotation is identity", [q.x, q.y, q.z, q.w], [0, 0, 0, 1])
    response.success = False
    outcome, _ = run(m.LoadGazeboModelState(model_name="block2", pose=[0.7, 0, -0.13]), flexbe)
    c.equal("spawn refused", outcome, "aborted")


def matrix(q):
    """The rotation matrix (row-major) of a quaternion (x, y, z, w), normalised."""
    n = sum(v * v for v in q) ** 0.5
    x, y, z, w = (v / n for v in q)
    return [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
            2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
            2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]


def product(a, b):
    return [sum(a[3 * i + k] * b[3 * k + j] for k in range(3)) for i in range(3) for j in range(3)]


def check_ik(m, flexbe, c):
    rospy, _, _ = reset()
    service = "ExternalTools/left/PositionKinematicsNode/IKService"
    names = ["left_s0", "left_s1", "left_e0", "left_e1", "left_w0", "left_w1", "left_w2"]
    valid = [True]
    rospy.services[service] = lambda request: types.SimpleNamespace(
        isValid=list(valid), joints=[types.SimpleNamespace(name=names, position=[0.5] * 7)])
    rotation, turn = [0.2, -0.4, 0.5, 0.74162], [0.1, 0.3, -0.6, 0.73485]
    state = m.PoseToJointTrajServiceState(input_keys=["limb", "poses", "offsets"])
    outcome, userdata = run(state, flexbe, limb="left", poses=[[0.7, 0.15, -0.129], rotation],
                            offsets=[[0.0, 0.0, 0.15], turn])
    c.equal("ik", outcome, "succeeded")
    c.equal("ik joints", userdata.get("joints"), dict(zip(names, [0.5] * 7)))
    stamped = rospy.calls[0][1][0].pose_stamp[0]
    p, q = stamped.pose.position, stamped.pose.orientation
    c.equal("ik frame", stamped.header.frame_id, "base")
    c.close("ik position (offset added)", [p.x, p.y, p.z], [0.7, 0.15, 0.021])
    c.close("ik rotation (offset's composed after the pose's)", matrix([q.x, q.y, q.z, q.w]),
            product(matrix(rotation), matrix(turn)))
    valid[0] = False
    outcome, _ = run(m.PoseToJointTrajServiceState(limb="left", poses=[0.9, 0, 0.5]), flexbe)
    c.equal("ik without solution", outcome, "aborted")
    outcome, _ = run(m.PoseToJointTrajServiceState(limb="left", input_keys=["poses"]), flexbe)
    c.equal("ik with a missing key", outcome, "aborted")


def check_move(m, flexbe, c):
    _, baxter, _ = reset()
    positions = [-0.08, -1.0, -1.19, 1.94, 0.67, 1.03, -0.5]
    goal = dict(zip(baxter.Limb("left").joint_names(), positions))
    outcome, _ = run(m.MoveToJointPositionsState(speed=0.5, input_keys=["limb", "positions"]),
                     flexbe, limb="left", positions=positions)
    c.equal("move", outcome, "succeeded")
    c.equal("move speed", baxter.Limb.commands[0], ("speed", 0.5))
    c.equal("move goal", [cmd for cmd in baxter.Limb.commands if cmd[0] == "goal"][0], ("goal", goal))
    baxter.Limb.reach, baxter.Limb.angles = False, {}
    outcome, _ = run(m.MoveToJointPositionsState(limb="left", positions=positions, timeout=2.0),
                     flexbe)
    c.equal("move that does not reach", outcome, "aborted")
    outcome, _ = run(m.MoveToJointPositionsState(limb="left", positions=positions[:6]), flexbe)
    c.equal("six joint positions", outcome, "aborted")


def check_follow(m, flexbe, c):
    _, baxter, actionlib = reset()
    points = [[0.3] * 7, [0.0] * 7]
    outcome, _ = run(m.FollowJointTrajActionState(limb="right", points=points, speed=0.5), flexbe)
    c.equal("follow", (outcome, len(actionlib.goals)), ("succeeded", 1))
    if not actionlib.goals:
        return
    server, goal = actionlib.goals[0]
    c.equal("follow server", server, "robot/limb/right/follow_joint_trajectory")
    c.equal("follow joints", goal.trajectory.joint_names, baxter.Limb("right").joint_names())
    c.equal("follow points", [p.positions for p in goal.trajectory.points], points)
    c.close("follow times (0.3 rad at 0.5 x 2 rad/s, twice)",
            [p.time_from_start.secs for p in goal.trajectory.points], [0.3, 0.6])
    actionlib.error_code[0] = -1
    outcome, _ = run(m.FollowJointTrajActionState(limb="right", points=points), flexbe)
    c.equal("follow refused", outcome, "aborted")


def check_gripper(m, flexbe, c):
    _, baxter, _ = reset()
    outcome, _ = run(m.GripperInterfaceState(command="close", input_keys=["limb"]), flexbe,
                     limb="left")
    c.equal("close", (outcome, baxter.Gripper.commands),
            ("succeeded", [("left", "calibrate"), ("left", "close")]))
    baxter.Gripper.holds = False
    outcome, _ = run(m.GripperInterfaceState(limb="left", command="close"), flexbe)
    c.equal("close on nothing", outcome, "aborted")
    outcome, _ = run(m.GripperInterfaceState(limb="left", command="close", expect_grasp=False),
                     flexbe)
    c.equal("close on nothing, not expecting a grasp", outcome, "succeeded")
    outcome, _ = run(m.GripperInterfaceState(limb="right", command="open"), flexbe)
    c.equal("open", (outcome, baxter.Gripper.commands[-1]), ("succeeded", ("right", "open")))
    outcome, _ = run(m.GripperInterfaceState(limb="right", command="shut"), flexbe)
    c.equal("unknown command", outcome, "aborted")


def check_read(m, flexbe, c):
    reset()
    outcome, userdata = run(m.ReadEndpointPoseState(input_keys=["limb"]), flexbe, limb="right")
    c.equal("read", (outcome, userdata.get("pose")),
            ("succeeded", [[0.7, -0.15, 0.02], [0.1, 0.2, 0.3, 0.9]]))


CHECKS = [check_load, check_ik, check_move, check_follow, check_gripper, check_read]


def main():
    golden = sys.argv[1]
    failures = []
    with tempfile.TemporaryDirectory() as scratch:
        write_stubs(scratch)
        sys.path.insert(0, scratch)
        with open(os.path.join(golden, "smach_baxter", "all_variables.smach.py")) as f:
            smach_module = load_module("baxter_smach", f.read(), scratch)
        flexbe_module = load_module("baxter_flexbe_states", flexbe_states_module(
            os.path.join(golden, "flexbe_baxter", "all_variables.flexbe.py")), scratch)
        for label, module, flexbe in (("smach", smach_module, False),
                                      ("flexbe", flexbe_module, True)):
            checker = Checker(label)
            for check in CHECKS:
                check(module, flexbe, checker)
            failures += checker.failures
        import baxter_interface
        if len(baxter_interface.enabled) != 1:
            failures.append(f"flexbe: the robot was enabled {len(baxter_interface.enabled)} "
                            "times, expected once")
    for failure in failures:
        print("FAIL " + failure)
    print(f"{len(CHECKS)} Baxter state checks on each of smach, flexbe: "
          f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
