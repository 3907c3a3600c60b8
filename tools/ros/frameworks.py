"""Where the frameworks that generated code is verified on come from, and whether they are here.

Debian's ROS 1 comes from `tools/install-deps`. The rest is in no registry (SMACH, smach_ros,
FlexBE, the Baxter SDK and its messages, SMACHA): a user has them in an installed ROS or as
upstream checkouts in a frameworks folder outside the repository. CHECKOUTS names, for each
sub-folder of that folder, the repository, branch and commit it must hold and the git tree id
of every path the tests read at that commit; a folder counts only when each path's content
hashes to that tree id (computed as git computes it, so a `git archive` extract, a clone
checked out at the commit, or a copy of either all match, and an edited file does not).

  frameworks_folder()        $SMACHAC_FRAMEWORKS, else $XDG_CACHE_HOME/smachac/frameworks,
                             else ~/.cache/smachac/frameworks
  find_checkout(name)        a Found (where, at which commit) or a Missing (why, remedy)
  extract(checkout, source)  `git archive` of the commit from a clone or a repository URL
                             into the frameworks folder, checked before it is put in place
Nothing here writes anywhere but the frameworks folder, and nothing in it is ever patched:
users of a checkout copy it first (tools/ros/overlay.py, bench/compare/anchors.py).
"""
import hashlib
import os
import shlex
import shutil
import subprocess
import tempfile
from dataclasses import dataclass, field


@dataclass(frozen=True)
class Checkout:
    folder: str       # the sub-folder of the frameworks folder
    provides: str     # what a reader knows it as
    repository: str
    branch: str
    commit: str
    trees: dict = field(hash=False)  # path in the repository ("." for all) -> git tree id
    used_by: str = ""  # the suites that skip without it

    @property
    def paths(self):
        return list(self.trees)


CHECKOUTS = [
    Checkout("executive_smach", "SMACH 2.5.2, smach_ros, smach_msgs",
             "https://github.com/ros/executive_smach", "noetic-devel",
             "94a196d0dbe79f4ae205d13f50302316860194b8",
             {"smach": "f4e676f16f4f8d7dcd783a54e75796132f96e69e",
              "smach_ros": "483bf50b5795b152ed1648a8300daaa860d388f2",
              "smach_msgs": "6a3ec2dbada3daee04371a211ca82b7b789b7a0c"},
             "ros/smach-goldens, ros/smach-ros-states, ros/smacha-corpus, ros/differential, "
             "sim-ros/smach-*, bench-compare's SMACH rows"),
    Checkout("flexbe_behavior_engine", "FlexBE 1.4.1 (ROS 1): flexbe_core, flexbe_states, "
             "flexbe_testing, flexbe_msgs",
             "https://github.com/FlexBE/flexbe_behavior_engine", "noetic",
             "e1eab6d00e3f739b12f8ef773478a00c9e8d5348",
             {"flexbe_core": "ddb86eee7f41153abc9104c87d3ff8acdfce997f",
              "flexbe_states": "0ba43399036d96f9f92e8f37d11c93bd6efaa26a",
              "flexbe_testing": "e9e45b7f52c6bba9da8acb51990f65331bf64391",
              "flexbe_msgs": "bcf909ec449d26d7b4f6b80900c54317b4750c68"},
             "ros/flexbe-goldens, ros/flexbe-rejects, ros/differential, sim-ros/flexbe-*"),
    Checkout("baxter_interface", "the Baxter SDK 1.2.0 (baxter_interface)",
             "https://github.com/RethinkRobotics/baxter_interface", "development",
             "5527ec8d1aff0846bab33d92e688bd146a59e0bd",
             {".": "2e71fcecfb9f171c5b6e5f8624ce1a52c8271dd2"}, "sim-ros/*"),
    Checkout("baxter_common", "the Baxter SDK's messages (baxter_core_msgs)",
             "https://github.com/RethinkRobotics/baxter_common", "master",
             "6c4b0f375fe4e356a3b12df26ef7c0d5e58df86e",
             {"baxter_core_msgs": "2ecb5eb69f5f80e01c1bbad0d9f5b002f2c5cd32"}, "sim-ros/*"),
    Checkout("gazebo_ros_pkgs", "Gazebo's ROS 1 messages (gazebo_msgs)",
             "https://github.com/ros-simulation/gazebo_ros_pkgs", "noetic-devel",
             "f9e1a4607842afa5888ef01de31cd64a1e3e297f",
             {"gazebo_msgs": "6e792203ec413f74436f89a7f6beedb8e579aeee"}, "sim-ros/*"),
    Checkout("control_msgs", "ROS 1 control_msgs",
             "https://github.com/ros-controls/control_msgs", "kinetic-devel",
             "36e2e30551e3f2bfd9e55fca553f1ef019f4e4b1",
             {"control_msgs": "3d0bb020c9b7e2f2d1ac7edab173272a1e1df985"}, "sim-ros/*"),
    Checkout("smacha", "SMACHA (smacha, smacha_ros)",
             "https://github.com/ReconCell/smacha", "master",
             "253215a35d2d091bf50c28c1ba876209b82d2400",
             {"smacha": "691da350c52a67f1a941051a45f0ae76a7a50cfd",
              "smacha_ros": "14655972ea17e48cbd5600d7a740fcb144a9d9bc"},
             "ros/smacha-corpus, bench-compare's SMACHA rows"),
]

BY_FOLDER = {checkout.folder: checkout for checkout in CHECKOUTS}

# What a tree id leaves out: git's own folder (a clone) and what Python writes beside code run
# in place.
IGNORED_NAMES = {".git", "__pycache__"}
IGNORED_SUFFIXES = (".pyc",)


def frameworks_folder():
    explicit = os.environ.get("SMACHAC_FRAMEWORKS")
    if explicit:
        return os.path.abspath(explicit)
    cache = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(os.path.abspath(cache), "smachac", "frameworks")


def shown_path(path):
    """path with the home folder written ~, as a user types it."""
    home = os.path.expanduser("~")
    return "~" + path[len(home):] if path == home or path.startswith(home + os.sep) else path


def _git_object_id(kind, data):
    return hashlib.sha1(b"%s %d\0" % (kind, len(data)) + data).hexdigest()


def _entry(folder, name):
    """(mode, name, object id) of one entry as git records it, or None when git would not."""
    path = os.path.join(folder, name)
    if os.path.islink(path):
        return b"120000", name, _git_object_id(b"blob", os.fsencode(os.readlink(path)))
    if os.path.isdir(path):
        tree = tree_id(path)
        return None if tree is None else (b"40000", name, tree)
    with open(path, "rb") as f:
        blob = _git_object_id(b"blob", f.read())
    return (b"100755" if os.stat(path).st_mode & 0o100 else b"100644"), name, blob


def tree_id(folder):
    """The git tree id of folder's content, or None for a folder git would not record (one
    that holds no file)."""
    names = [n for n in os.listdir(folder)
             if n not in IGNORED_NAMES and not n.endswith(IGNORED_SUFFIXES)]
    entries = [e for e in (_entry(folder, n) for n in names) if e is not None]
    if not entries:
        return None
    # git orders a tree's entries by name, a folder's name as if it ended in "/"
    entries.sort(key=lambda e: os.fsencode(e[1]) + (b"/" if e[0] == b"40000" else b""))
    data = b"".join(b"%s %s\0" % (mode, os.fsencode(name)) + bytes.fromhex(oid)
                    for mode, name, oid in entries)
    return _git_object_id(b"tree", data)


@dataclass
class Found:
    checkout: Checkout
    path: str

    def describe(self):
        return "%s at %s, commit %s" % (self.checkout.folder, shown_path(self.path),
                                         self.checkout.commit[:12])


@dataclass
class Missing:
    checkout: Checkout
    why: str

    def describe(self):
        return "%s (%s): %s" % (self.checkout.folder, self.checkout.provides, self.why)


def mismatches(checkout, path):
    """The paths of checkout under path whose content is not the commit's, each with why."""
    problems = []
    for relative, expected in checkout.trees.items():
        folder = os.path.normpath(os.path.join(path, relative))
        if not os.path.isdir(folder):
            problems.append("%s is missing" % relative)
        elif tree_id(folder) != expected:
            problems.append("%s is not commit %s's (tree %s expected)" % (
                relative, checkout.commit[:12], expected[:12]))
    return problems


def find_checkout(name, root=None):
    checkout = BY_FOLDER[name]
    path = os.path.join(root or frameworks_folder(), checkout.folder)
    if not os.path.isdir(path):
        return Missing(checkout, "no folder %s" % shown_path(path))
    problems = mismatches(checkout, path)
    if problems:
        return Missing(checkout, "%s holds another version: %s" % (shown_path(path),
                                                                    "; ".join(problems)))
    return Found(checkout, path)


def shell_path(path):
    """path as a shell word, under the home folder written ~/..."""
    home = os.path.expanduser("~")
    if path.startswith(home + os.sep):
        return "~/" + shlex.quote(path[len(home) + 1:])
    return shlex.quote(path)


def manual_commands(checkout, root=None):
    """The shell commands that put checkout in place with git alone (what extract does)."""
    target = shell_path(os.path.join(root or frameworks_folder(), checkout.folder))
    clone = "/tmp/%s.git" % checkout.folder
    return ("git clone --bare --single-branch -b %s %s %s && mkdir -p %s && "
            "git --git-dir=%s archive %s %s | tar -x -C %s" % (
                checkout.branch, checkout.repository, clone, target, clone,
                checkout.commit[:12], " ".join(checkout.paths), target))


def remedy(checkout):
    return "tools/frameworks get %s, or by hand: %s" % (checkout.folder,
                                                         manual_commands(checkout))


class ExtractError(Exception):
    """A checkout could not be extracted; the message says why."""


def _git(argv, **kwargs):
    return subprocess.run(["git"] + argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          **kwargs)


def _git_dir(source, work):
    """A git folder holding the commit: source itself when it is a local clone, else a bare
    clone of the branch made in work."""
    if os.path.isdir(source):
        return source
    clone = os.path.join(work, "clone.git")
    result = _git(["clone", "--quiet", "--bare", "--single-branch", "-b", _branch_of(source),
                   source, clone])
    if result.returncode != 0:
        raise ExtractError("git clone %s failed: %s" % (source, result.stderr.decode().strip()))
    return clone


def _branch_of(source):
    for checkout in CHECKOUTS:
        if checkout.repository == source:
            return checkout.branch
    return "HEAD"


def extract(checkout, source, root=None):
    """Puts checkout's paths at its commit into the frameworks folder from source (a local
    clone or mirror, or the repository's URL), checked against the table before it replaces
    what was there. Returns the Found."""
    root = root or frameworks_folder()
    os.makedirs(root, exist_ok=True)
    target = os.path.join(root, checkout.folder)
    with tempfile.TemporaryDirectory(prefix=".extract-", dir=root) as work:
        git_dir = _git_dir(source, work)
        staged = os.path.join(work, checkout.folder)
        os.makedirs(staged)
        archive = _git(["-C", git_dir, "archive", "--format=tar", checkout.commit] +
                       checkout.paths)
        if archive.returncode != 0:
            raise ExtractError("%s has no commit %s with %s: %s" % (
                source, checkout.commit[:12], " ".join(checkout.paths),
                archive.stderr.decode().strip()))
        subprocess.run(["tar", "-x", "-C", staged], input=archive.stdout, check=True)
        problems = mismatches(checkout, staged)
        if problems:
            raise ExtractError("what %s gave is not the expected content: %s" % (
                source, "; ".join(problems)))
        if os.path.lexists(target):
            os.rename(target, os.path.join(work, "replaced"))
        os.rename(staged, target)
    return Found(checkout, target)
