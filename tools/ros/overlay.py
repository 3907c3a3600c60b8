#!/usr/bin/python3
"""Builds the ROS 1 test overlay: the frameworks Debian does not package, their messages, and
the packages generated code loads, in one folder.

  overlay.py build DIR [SOURCES]
      (re)build the overlay in DIR; prints what it took and what it skipped

Sources come from an installed ROS where it has them (a module that Debian's python3 can
already import is used as installed), else from a folder of unmodified upstream sources
(SOURCES, else $SMACHAC_ROS_SOURCES; the ctest ros/overlay names the one beside the project),
holding executive_smach, flexbe_behavior_engine, baxter_interface, baxter_common,
gazebo_ros_pkgs and control_msgs as their repositories lay them out. They are copied into DIR/src, patched there
when they need it, and their .msg/.srv/.action files are turned into Python with genpy.
DIR/overlay.json records the environment (PYTHONPATH, ROS_PACKAGE_PATH) and which frameworks
are available, with the reason when one is not; `ros_session.py` reads it.
"""
import glob
import importlib.util
import json
import os
import shutil
import subprocess
import sys

PYTHON = "/usr/bin/python3"  # Debian's: the only interpreter that sees Debian's rospy
GENMSG = "/usr/lib/genpy/genmsg_py.py"
GENSRV = "/usr/lib/genpy/gensrv_py.py"
GENACTION = "/usr/lib/actionlib_msgs/genaction.py"

# (framework, upstream folder, [(package, path in that folder, python module or None)])
FRAMEWORKS = [
    ("smach", "executive_smach", [("smach", "smach", "smach"),
                                  ("smach_ros", "smach_ros", "smach_ros"),
                                  ("smach_msgs", "smach_msgs", None)]),
    ("flexbe", "flexbe_behavior_engine", [("flexbe_core", "flexbe_core", "flexbe_core"),
                                          ("flexbe_states", "flexbe_states", "flexbe_states"),
                                          ("flexbe_testing", "flexbe_testing", "flexbe_testing"),
                                          ("flexbe_msgs", "flexbe_msgs", None)]),
    ("baxter", None, [("baxter_interface", "baxter_interface", "baxter_interface"),
                      ("baxter_core_msgs", "baxter_common/baxter_core_msgs", None),
                      ("gazebo_msgs", "gazebo_ros_pkgs/gazebo_msgs", None),
                      ("control_msgs", "control_msgs/control_msgs", None)]),
]

# Messages the tests' own servers and scripts use (written here, not taken from anywhere).
TEST_MESSAGES = {
    "srv/SetWidth.srv": "float64 width\n---\nfloat64 width\n",
    "action/Move.action": "float64 speed\n---\ngeometry_msgs/Pose final_pose\n---\n"
                          "float64 progress\n",
}

# Lines of upstream code that Debian's Python 3 cannot run, patched in the overlay's copy.
PATCHES = {
    "baxter_interface/src/baxter_interface/robot_enable.py":
        [("except OSError, e:", "except OSError as e:")],
}


def package_xml(name):
    return ('<?xml version="1.0"?>\n<package format="2"><name>%s</name><version>0.0.0</version>'
            '<description>smachac test overlay package</description>'
            '<maintainer email="smachac@example.com">smachac</maintainer><license>BSD</license>'
            '</package>\n' % name)


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def installed(module):
    return module is not None and importlib.util.find_spec(module) is not None


class Overlay:
    def __init__(self, root, sources=None):
        self.root = root
        self.sources = sources or os.environ.get("SMACHAC_ROS_SOURCES")
        self.src = os.path.join(root, "src")
        self.gen = os.path.join(root, "gen")
        self.python_path = [self.gen]
        self.frameworks = {}

    def build(self):
        shutil.rmtree(self.root, ignore_errors=True)
        os.makedirs(self.src)
        os.makedirs(self.gen)
        missing_tools = [t for t in (GENMSG, GENSRV, GENACTION) if not os.path.exists(t)]
        if missing_tools:
            return self.finish("message generators missing: " + ", ".join(missing_tools) +
                               " (tools/install-deps installs them)")
        for framework, folder, packages in FRAMEWORKS:
            self.frameworks[framework] = self.take_framework(folder, packages)
        self.make_package("smacha")  # SMACHA's ROS base template loads the manifest `smacha`
        for relative, text in TEST_MESSAGES.items():
            write(os.path.join(self.src, "smachac_test_msgs", relative), text)
        self.make_package("smachac_test_msgs")
        self.generate_messages("smachac_test_msgs", os.path.join(self.src, "smachac_test_msgs"))
        return self.finish(None)

    def take_framework(self, folder, packages):
        """Copies and builds each package; returns None when usable, else why not."""
        for package, path, module in packages:
            if installed(module):
                continue
            if not self.sources:
                return ("%s is not installed and no upstream sources were given "
                        "($SMACHAC_ROS_SOURCES)" % package)
            source = os.path.join(self.sources, (folder + "/" if folder else "") + path)
            if not os.path.isdir(source):
                return "%s is not installed and its sources are not at %s" % (package, source)
            target = os.path.join(self.src, package)
            shutil.copytree(source, target)
            self.patch(package)
            if module is None:
                self.generate_messages(package, target)
            else:
                self.python_path.append(os.path.join(target, "src"))
        return None

    def patch(self, package):
        for relative, replacements in PATCHES.items():
            if not relative.startswith(package + "/"):
                continue
            path = os.path.join(self.src, relative)
            with open(path, encoding="utf-8") as f:
                text = f.read()
            for old, new in replacements:
                text = text.replace(old, new)
            write(path, text)

    def make_package(self, name):
        write(os.path.join(self.src, name, "package.xml"), package_xml(name))

    def include_flags(self, package, msg_dirs):
        flags = []
        for d in msg_dirs:
            flags += ["-I", "%s:%s" % (package, d)]
        for d in sorted(glob.glob("/usr/share/*/msg") + glob.glob(self.src + "/*/msg")):
            flags += ["-I", "%s:%s" % (os.path.basename(os.path.dirname(d)), d)]
        return flags

    def generate_messages(self, package, folder):
        out = os.path.join(self.gen, package)
        msgs = sorted(glob.glob(os.path.join(folder, "msg", "*.msg")))
        msg_dirs = [os.path.join(folder, "msg")]
        actions = sorted(glob.glob(os.path.join(folder, "action", "*.action")))
        if actions:
            action_dir = os.path.join(self.root, "actions", package)
            os.makedirs(action_dir, exist_ok=True)
            for action in actions:
                run([PYTHON, GENACTION, action, "-o", action_dir])
            msgs += sorted(glob.glob(os.path.join(action_dir, "*.msg")))
            msg_dirs.append(action_dir)
        flags = self.include_flags(package, msg_dirs)
        if msgs:
            run([PYTHON, GENMSG, "-p", package, "-o", out + "/msg"] + flags + msgs)
            run([PYTHON, GENMSG, "--initpy", "-p", package, "-o", out + "/msg"])
        srvs = sorted(glob.glob(os.path.join(folder, "srv", "*.srv")))
        if srvs:
            run([PYTHON, GENSRV, "-p", package, "-o", out + "/srv"] + flags + srvs)
            run([PYTHON, GENSRV, "--initpy", "-p", package, "-o", out + "/srv"])
        if not os.path.exists(os.path.join(out, "__init__.py")):
            write(os.path.join(out, "__init__.py"), "")

    def finish(self, problem):
        description = {
            "python_path": self.python_path,
            "package_path": [self.src],
            "frameworks": {name: why for name, why in self.frameworks.items()},
            "problem": problem,
        }
        write(os.path.join(self.root, "overlay.json"), json.dumps(description, indent=1) + "\n")
        return description


def run(argv):
    result = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if result.returncode != 0:
        raise SystemExit("overlay: %s failed:\n%s" % (" ".join(argv), result.stdout))


def main():
    if len(sys.argv) not in (3, 4) or sys.argv[1] != "build":
        print(__doc__.strip(), file=sys.stderr)
        return 2
    sources = os.path.abspath(sys.argv[3]) if len(sys.argv) == 4 else None
    description = Overlay(os.path.abspath(sys.argv[2]), sources).build()
    if description["problem"]:
        print("overlay: not built: " + description["problem"])
        return 0
    for name, why in description["frameworks"].items():
        print("overlay: %-7s %s" % (name, "ready" if why is None else "unavailable: " + why))
    return 0


if __name__ == "__main__":
    sys.exit(main())
