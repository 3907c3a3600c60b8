"""The simulated Baxter from Python: a ctypes binding of libsmachac_sim_bridge.so (its C
interface is bridge/sim_bridge.h). One SimulatedBaxter owns one MuJoCo world; every call is
serialised by its lock, so ROS callbacks in several threads can share it.

Poses are [x, y, z, qx, qy, qz, qw] in Baxter's base frame; joints [s0 s1 e0 e1 w0 w1 w2].
"""
import ctypes
import threading

SIDES = {"left": 0, "right": 1}
FRAMES = {"base": 0, "world": 1}
PLACE_ERRORS = {1: "the simulated world has no model %r",
                2: "model %r cannot be moved",
                3: "invalid pose for model %r"}

_double7 = ctypes.c_double * 7
_double6 = ctypes.c_double * 6


class BridgeError(Exception):
    """The library or the world could not be loaded; the message says why."""


def _declare(lib):
    handle = ctypes.c_void_p
    d7 = ctypes.POINTER(ctypes.c_double)
    signatures = {
        "smachac_sim_open": (handle, [ctypes.c_char_p, ctypes.c_char_p, ctypes.c_int]),
        "smachac_sim_close": (None, [handle]),
        "smachac_sim_step": (ctypes.c_double, [handle, ctypes.c_int]),
        "smachac_sim_time": (ctypes.c_double, [handle]),
        "smachac_sim_timestep": (ctypes.c_double, [handle]),
        "smachac_sim_joint_names": (None, [handle, ctypes.c_int, ctypes.c_char_p * 7]),
        "smachac_sim_joint_state": (None, [handle, ctypes.c_int, d7, d7, d7]),
        "smachac_sim_command_positions": (ctypes.c_int, [handle, ctypes.c_int, d7,
                                                         ctypes.c_double]),
        "smachac_sim_endpoint": (None, [handle, ctypes.c_int, d7, d7]),
        "smachac_sim_solve_ik": (ctypes.c_int, [handle, ctypes.c_int, d7, d7]),
        "smachac_sim_gripper_command": (None, [handle, ctypes.c_int, ctypes.c_double]),
        "smachac_sim_gripper_state": (None, [handle, ctypes.c_int, d7,
                                             ctypes.POINTER(ctypes.c_int),
                                             ctypes.POINTER(ctypes.c_int), d7]),
        "smachac_sim_place_body": (ctypes.c_int, [handle, ctypes.c_char_p, d7, ctypes.c_int]),
        "smachac_sim_body_pose": (ctypes.c_int, [handle, ctypes.c_char_p, d7]),
        "smachac_sim_report": (ctypes.c_int, [handle, ctypes.c_char_p, ctypes.c_int]),
        "smachac_sim_snapshot": (ctypes.c_int, [handle, ctypes.c_char_p, ctypes.c_char_p,
                                                ctypes.c_int]),
    }
    for name, (result, arguments) in signatures.items():
        function = getattr(lib, name)
        function.restype = result
        function.argtypes = arguments


def load_library(path):
    try:
        lib = ctypes.CDLL(path)
    except OSError as error:
        raise BridgeError("cannot load the simulation library %s: %s" % (path, error))
    _declare(lib)
    return lib


class SimulatedBaxter:
    def __init__(self, library_path, scene=None):
        self._lib = load_library(library_path)
        self.lock = threading.RLock()
        error = ctypes.create_string_buffer(1024)
        self._world = self._lib.smachac_sim_open((scene or "").encode(), error, len(error))
        if not self._world:
            raise BridgeError("cannot load the simulated world: " + error.value.decode())
        self.timestep = self._lib.smachac_sim_timestep(self._world)

    def close(self):
        with self.lock:
            if self._world:
                self._lib.smachac_sim_close(self._world)
                self._world = None

    def step(self, count):
        with self.lock:
            return self._lib.smachac_sim_step(self._world, count)

    def time(self):
        with self.lock:
            return self._lib.smachac_sim_time(self._world)

    def joint_names(self, side):
        names = (ctypes.c_char_p * 7)()
        with self.lock:
            self._lib.smachac_sim_joint_names(self._world, SIDES[side], names)
        return [n.decode() for n in names]

    def joint_state(self, side):
        position, velocity, effort = _double7(), _double7(), _double7()
        with self.lock:
            self._lib.smachac_sim_joint_state(self._world, SIDES[side], position, velocity, effort)
        return list(position), list(velocity), list(effort)

    def command_positions(self, side, goal, speed):
        with self.lock:
            return bool(self._lib.smachac_sim_command_positions(
                self._world, SIDES[side], _double7(*goal), speed))

    def endpoint(self, side):
        pose, twist = _double7(), _double6()
        with self.lock:
            self._lib.smachac_sim_endpoint(self._world, SIDES[side], pose, twist)
        return list(pose), list(twist)

    def solve_ik(self, side, pose):
        joints = _double7()
        with self.lock:
            solved = self._lib.smachac_sim_solve_ik(self._world, SIDES[side], _double7(*pose),
                                                    joints)
        return bool(solved), list(joints)

    def command_gripper(self, side, percent):
        with self.lock:
            self._lib.smachac_sim_gripper_command(self._world, SIDES[side], percent)

    def gripper_state(self, side):
        """(position percent, moving, gripping, force percent)"""
        percent, force = _double7(), _double7()
        moving, gripping = ctypes.c_int(), ctypes.c_int()
        with self.lock:
            self._lib.smachac_sim_gripper_state(self._world, SIDES[side], percent,
                                                ctypes.byref(moving), ctypes.byref(gripping),
                                                force)
        return percent[0], bool(moving.value), bool(gripping.value), force[0]

    def place_body(self, name, pose, frame):
        """Places a body at rest; returns None, or why it could not."""
        with self.lock:
            status = self._lib.smachac_sim_place_body(self._world, name.encode(),
                                                      _double7(*pose), FRAMES[frame])
        return PLACE_ERRORS[status] % name if status else None

    def body_pose(self, name):
        pose = _double7()
        with self.lock:
            found = self._lib.smachac_sim_body_pose(self._world, name.encode(), pose)
        return list(pose) if found else None

    def report(self):
        with self.lock:
            size = self._lib.smachac_sim_report(self._world, None, 0)
            text = ctypes.create_string_buffer(size + 1)
            self._lib.smachac_sim_report(self._world, text, len(text))
        return text.value.decode()

    def snapshot(self, path):
        """Writes a PNG; returns None, or why it could not."""
        error = ctypes.create_string_buffer(1024)
        with self.lock:
            ok = self._lib.smachac_sim_snapshot(self._world, path.encode(), error, len(error))
        return None if ok else error.value.decode()

