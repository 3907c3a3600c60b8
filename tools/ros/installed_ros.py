"""What an installed ROS 1 provides, as Debian's /usr/bin/python3 sees it.

A framework counts as installed when every package of it is importable and is ROS's own: a
package.xml of that name lies in a prefix above the module (`<prefix>/share/<pkg>/`, as
Debian, /opt/ros and catkin install spaces lay it out, or the package's own folder in a
source space). A module of the same name from elsewhere (PyPI's standalone-smach installs
`smach`) is not SMACH 2.5.2 and does not count.
"""
import importlib.util
import os
import re

# The Debian 12 packages of ROS 1 the tests need (tools/install-deps): package -> module.
REGISTRY = {"ROS 1 (Debian 12: rospy, rosmaster, genpy, actionlib, tf2_ros, rosbag)":
            ["rospy", "rosmaster", "genpy", "actionlib", "tf2_ros", "rosbag"]}

# Each checkout's ROS packages, with the module that an installed ROS would provide for it.
PACKAGES = {
    "executive_smach": {"smach": "smach", "smach_ros": "smach_ros", "smach_msgs": "smach_msgs.msg"},
    "flexbe_behavior_engine": {"flexbe_core": "flexbe_core", "flexbe_states": "flexbe_states",
                               "flexbe_testing": "flexbe_testing",
                               "flexbe_msgs": "flexbe_msgs.msg"},
    "baxter_interface": {"baxter_interface": "baxter_interface"},
    "baxter_common": {"baxter_core_msgs": "baxter_core_msgs.msg"},
    "gazebo_ros_pkgs": {"gazebo_msgs": "gazebo_msgs.msg"},
    "control_msgs": {"control_msgs": "control_msgs.msg"},
    "smacha": {"smacha": "smacha"},
}

ANCESTORS = 6  # how far above a module its prefix may be


def module_folder(module):
    try:
        spec = importlib.util.find_spec(module)
    except (ImportError, ValueError):
        return None
    if spec is None or not spec.origin or spec.origin in ("built-in", "frozen"):
        return None
    return os.path.dirname(spec.origin)


def ros_package_xml(package, folder):
    """The package.xml that makes folder's module ROS's package `package`, or None."""
    for _ in range(ANCESTORS):
        for candidate in (os.path.join(folder, "share", package, "package.xml"),
                          os.path.join(folder, "package.xml")):
            if os.path.isfile(candidate) and package_name(candidate) == package:
                return candidate
        parent = os.path.dirname(folder)
        if parent == folder:
            break
        folder = parent
    return None


def _tag(path, tag):
    with open(path, encoding="utf-8", errors="replace") as f:
        match = re.search(r"<%s>\s*([^<\s]+)\s*</%s>" % (tag, tag), f.read())
    return match.group(1) if match else None


def package_name(path):
    return _tag(path, "name")


def installed_package(package, module):
    """'<package> <version> (<package.xml>)' when an installed ROS provides it, else None."""
    folder = module_folder(module)
    manifest = folder and ros_package_xml(package, folder)
    if not manifest:
        return None
    return "%s %s (%s)" % (package, _tag(manifest, "version"), manifest)


def installed_checkout(checkout):
    """What an installed ROS provides of every package of checkout, or None when it lacks one."""
    found = [installed_package(p, m) for p, m in PACKAGES[checkout.folder].items()]
    return None if None in found else ", ".join(found)


def registry_status():
    """[(name, 'rospy 1.15.15 (...)' or None)] for the registry packages."""
    result = []
    for name, modules in REGISTRY.items():
        found = [installed_package(m, m) for m in modules]
        result.append((name, None if None in found else found[0]))
    return result
