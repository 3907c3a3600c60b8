#!/usr/bin/python3
"""Builds the ROS 1 test overlay: the frameworks Debian does not package, their messages, and
the packages generated code loads, in one folder.

  overlay.py build DIR [FRAMEWORKS]
      (re)build the overlay in DIR; prints what it took and what it skipped

Each package comes from an installed ROS where it has it (installed_ros.py: importable by
Debian's python3 and ROS's own), else from the upstream checkout in the frameworks folder
(FRAMEWORKS, else frameworks.py's default: $SMACHAC_FRAMEWORKS or ~/.cache/smachac/frameworks),
used only when it is the commit frameworks.py names. Checkouts are copied into DIR/src,
patched there when Debian's Python 3 needs it (never in place), and their .msg/.srv/.action
files are turned into Python with genpy. DIR/overlay.json records the environment
(PYTHONPATH, ROS_PACKAGE_PATH), which frameworks are available and where each came from, and
for each one that is not, why and the command that provides it; `ros_session.py` reads it.
"""
import glob
import json
import os
import shutil
import subprocess
import sys

import frameworks
import installed_ros

PYTHON = "/usr/bin/python3"  # Debian's: the only interpreter that sees Debian's rospy
GENMSG = "/usr/lib/genpy/genmsg_py.py"
GENSRV = "/usr/lib/genpy/gensrv_py.py"
GENACTION = "/usr/lib/actionlib_msgs/genaction.py"

# (framework, [(checkout of frameworks.py, package, its path in the checkout, has Python
# code in <path>/src: else it holds messages)])
FRAMEWORKS = [
    ("smach", [("executive_smach", "smach", "smach", True),
               ("executive_smach", "smach_ros", "smach_ros", True),
               ("executive_smach", "smach_msgs", "smach_msgs", False)]),
    ("flexbe", [("flexbe_behavior_engine", "flexbe_core", "flexbe_core", True),
                ("flexbe_behavior_engine", "flexbe_states", "flexbe_states", True),
                ("flexbe_behavior_engine", "flexbe_testing", "flexbe_testing", True),
                ("flexbe_behavior_engine", "flexbe_msgs", "flexbe_msgs", False)]),
    ("baxter", [("baxter_interface", "baxter_interface", ".", True),
                ("baxter_common", "baxter_core_msgs", "baxter_core_msgs", False),
                ("gazebo_ros_pkgs", "gazebo_msgs", "gazebo_msgs", False),
                ("control_msgs", "control_msgs", "control_msgs", False)]),
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


def unavailable(missing):
    """Why a framework is not usable: each checkout it lacks, and the command that gets them."""
    folders = list(dict.fromkeys(m.checkout.folder for m in missing))
    whys = list(dict.fromkeys("%s is missing: %s" % (m.checkout.folder, m.why) for m in missing))
    return "%s; `tools/frameworks get %s` provides %s" % (
        "; ".join(whys), " ".join(folders), "it" if len(folders) == 1 else "them")


def resolve(packages, frameworks_root):
    """Where each package of a framework comes from: ([(package, checkout path to copy, has
    code)], [where each came from], [frameworks.Missing for each absent checkout])."""
    sources, origins, missing = [], [], []
    for folder, package, path, has_code in packages:
        installed = installed_ros.installed_package(
            package, package if has_code else package + ".msg")
        found = None if installed else frameworks.find_checkout(folder, frameworks_root)
        if isinstance(found, frameworks.Missing):
            missing.append(found)
            continue
        if found:
            sources.append((package, os.path.join(found.path, path), has_code))
        origins.append("installed ROS: " + installed if installed else found.describe())
    return sources, list(dict.fromkeys(origins)), missing


def now_complete(description, frameworks_root=None):
    """Whether an overlay described so would lack nothing if it were built again now."""
    if description["problem"]:
        return False
    return all(not resolve(packages, frameworks_root)[2] for name, packages in FRAMEWORKS
               if description["frameworks"].get(name))


class Overlay:
    def __init__(self, root, frameworks_root=None):
        self.root = root
        self.frameworks_root = frameworks_root or frameworks.frameworks_folder()
        self.src = os.path.join(root, "src")
        self.gen = os.path.join(root, "gen")
        self.python_path = [self.gen]
        self.frameworks = {}
        self.origins = {}

    def build(self):
        shutil.rmtree(self.root, ignore_errors=True)
        os.makedirs(self.src)
        os.makedirs(self.gen)
        missing_tools = [t for t in (GENMSG, GENSRV, GENACTION) if not os.path.exists(t)]
        if missing_tools:
            return self.finish("message generators missing: " + ", ".join(missing_tools) +
                               " (tools/install-deps installs them)")
        for framework, packages in FRAMEWORKS:
            self.frameworks[framework] = self.take_framework(framework, packages)
        self.make_package("smacha")  # SMACHA's ROS base template loads the manifest `smacha`
        for relative, text in TEST_MESSAGES.items():
            write(os.path.join(self.src, "smachac_test_msgs", relative), text)
        self.make_package("smachac_test_msgs")
        self.generate_messages("smachac_test_msgs", os.path.join(self.src, "smachac_test_msgs"))
        return self.finish(None)

    def take_framework(self, framework, packages):
        """Copies and builds each package that no installed ROS has; returns None when the
        framework is usable, else why not."""
        sources, origins, missing = resolve(packages, self.frameworks_root)
        if missing:
            return unavailable(missing)
        for package, source, has_code in sources:
            target = os.path.join(self.src, package)
            shutil.copytree(os.path.normpath(source), target)
            self.patch(package)
            if has_code:
                self.python_path.append(os.path.join(target, "src"))
            else:
                self.generate_messages(package, target)
        self.origins[framework] = origins
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
            "origins": self.origins,
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
    folder = os.path.abspath(sys.argv[3]) if len(sys.argv) == 4 else None
    description = Overlay(os.path.abspath(sys.argv[2]), folder).build()
    if description["problem"]:
        print("overlay: not built: " + description["problem"])
        return 0
    for name, why in description["frameworks"].items():
        if why is None:
            print("overlay: %-7s ready: %s" % (name, "; ".join(description["origins"][name])))
        else:
            print("overlay: %-7s unavailable: %s" % (name, why))
    return 0


if __name__ == "__main__":
    sys.exit(main())
