"""tools/frameworks and tools/ros/frameworks.py as a user meets them: a checkout counts only
at its commit (tree ids computed as git computes them), a missing one is reported with the
commands that provide it, `get` extracts and checks before it replaces anything, the overlay
says which framework it lacks and how to get it, the README's table is the table's, and no
file of a framework found here is committed to the repository.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

ROOT = os.environ["SMACHAC_ROOT"]
sys.path.insert(0, os.path.join(ROOT, "tools", "ros"))

import frameworks  # noqa: E402
import installed_ros  # noqa: E402

TOOL = os.path.join(ROOT, "tools", "frameworks")
PYTHON = "/usr/bin/python3"
SMALLEST_COMPARED = 200  # bytes: smaller files (empty __init__.py, one-line stubs) may coincide


def git(cwd, *argv):
    result = subprocess.run(["git", "-C", cwd] + list(argv), capture_output=True, text=True,
                            env=dict(os.environ, GIT_AUTHOR_NAME="t", GIT_AUTHOR_EMAIL="t@t",
                                     GIT_COMMITTER_NAME="t", GIT_COMMITTER_EMAIL="t@t"))
    if result.returncode != 0:
        raise AssertionError("git %s: %s" % (" ".join(argv), result.stderr))
    return result.stdout.strip()


def write(path, text, mode=0o644):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    os.chmod(path, mode)


def tool(*argv, env=None):
    return subprocess.run([PYTHON, TOOL] + list(argv), capture_output=True, text=True,
                          env=dict(os.environ, **(env or {})), timeout=120)


class Repository:
    """A small upstream repository made in a temporary folder: pkg/ with code, a script, a
    folder and a file whose names sort differently as git sorts trees, an empty folder, a
    symbolic link; committed, with pkg's tree id at that commit."""

    def __init__(self, folder):
        self.path = os.path.join(folder, "upstream")
        os.makedirs(self.path)
        git(self.path, "init", "-q")
        write(os.path.join(self.path, "pkg", "src", "pkg", "__init__.py"), "VALUE = 1\n")
        write(os.path.join(self.path, "pkg", "scripts", "run"), "#!/bin/sh\n", 0o755)
        write(os.path.join(self.path, "pkg", "a-b"), "file before the folder a\n")
        write(os.path.join(self.path, "pkg", "a", "x"), "in folder a\n")
        write(os.path.join(self.path, "other", "README"), "not extracted\n")
        os.symlink("src/pkg/__init__.py", os.path.join(self.path, "pkg", "link"))
        git(self.path, "add", "-A")
        git(self.path, "commit", "-q", "-m", "one")
        os.makedirs(os.path.join(self.path, "pkg", "empty"))
        self.commit = git(self.path, "rev-parse", "HEAD")
        self.checkout = frameworks.Checkout(
            "demo", "a demo framework", "unused://", "main", self.commit,
            {"pkg": git(self.path, "rev-parse", "HEAD:pkg")})


class TreeIdTest(unittest.TestCase):
    def test_tree_ids_are_gits(self):
        with tempfile.TemporaryDirectory() as folder:
            upstream = Repository(folder)
            self.assertEqual(frameworks.tree_id(os.path.join(upstream.path, "pkg")),
                             upstream.checkout.trees["pkg"])
            self.assertEqual(frameworks.tree_id(upstream.path),
                             git(upstream.path, "rev-parse", "HEAD^{tree}"))

    def test_python_caches_do_not_count_and_an_edit_does(self):
        with tempfile.TemporaryDirectory() as folder:
            upstream = Repository(folder)
            pkg = os.path.join(upstream.path, "pkg")
            write(os.path.join(pkg, "src", "pkg", "__pycache__", "x.cpython-311.pyc"), "cache")
            self.assertEqual(frameworks.mismatches(upstream.checkout, upstream.path), [])
            os.chmod(os.path.join(pkg, "scripts", "run"), 0o644)
            self.assertEqual(frameworks.mismatches(upstream.checkout, upstream.path),
                             ["pkg is not commit %s's (tree %s expected)" % (
                                 upstream.commit[:12], upstream.checkout.trees["pkg"][:12])])


class ExtractTest(unittest.TestCase):
    def test_extract_puts_the_commits_paths_in_place_and_checks_them(self):
        with tempfile.TemporaryDirectory() as folder:
            upstream = Repository(folder)
            root = os.path.join(folder, "frameworks")
            found = frameworks.extract(upstream.checkout, upstream.path, root)
            self.assertEqual(found.path, os.path.join(root, "demo"))
            self.assertEqual(sorted(os.listdir(found.path)), ["pkg"])
            self.assertTrue(os.access(os.path.join(found.path, "pkg", "scripts", "run"), os.X_OK))
            self.assertEqual(frameworks.mismatches(upstream.checkout, found.path), [])
            self.assertEqual(sorted(os.listdir(root)), ["demo"])  # nothing staged is left

    def test_a_source_without_the_commit_changes_nothing(self):
        with tempfile.TemporaryDirectory() as folder:
            upstream = Repository(folder)
            root = os.path.join(folder, "frameworks")
            frameworks.extract(upstream.checkout, upstream.path, root)
            wrong = frameworks.Checkout("demo", "", "", "main", "1" * 40, upstream.checkout.trees)
            with self.assertRaises(frameworks.ExtractError) as raised:
                frameworks.extract(wrong, upstream.path, root)
            self.assertIn("has no commit 111111111111 with pkg", str(raised.exception))
            self.assertEqual(frameworks.mismatches(upstream.checkout, os.path.join(root, "demo")),
                             [])

    def test_content_other_than_the_tables_is_refused(self):
        with tempfile.TemporaryDirectory() as folder:
            upstream = Repository(folder)
            other = frameworks.Checkout("demo", "", "", "main", upstream.commit, {"pkg": "2" * 40})
            with self.assertRaises(frameworks.ExtractError) as raised:
                frameworks.extract(other, upstream.path, os.path.join(folder, "frameworks"))
            self.assertIn("is not the expected content: pkg is not commit", str(raised.exception))
            self.assertFalse(os.path.exists(os.path.join(folder, "frameworks", "demo")))


def provided_by_installed_ros(checkout):
    return installed_ros.installed_checkout(checkout) is not None


class CommandTest(unittest.TestCase):
    def test_each_missing_framework_is_one_skip_line_with_its_commands(self):
        with tempfile.TemporaryDirectory() as empty:
            result = tool("--missing", env={"SMACHAC_FRAMEWORKS": empty})
        self.assertEqual(result.returncode, 0, result.stderr)
        lines = [l.strip() for l in result.stdout.splitlines() if l.strip().startswith("skip:")]
        expected = [c for c in frameworks.CHECKOUTS if not provided_by_installed_ros(c)]
        self.assertEqual(len(lines), len(expected), result.stdout)
        for line, checkout in zip(lines, expected):
            target = os.path.join(empty, checkout.folder)
            self.assertTrue(line.startswith("skip: missing %s (%s): no folder %s;" % (
                checkout.folder, checkout.provides, target)), line)
            self.assertIn("get it: tools/frameworks get %s, or by hand: git clone --bare "
                          "--single-branch -b %s %s /tmp/%s.git && mkdir -p %s && "
                          "git --git-dir=/tmp/%s.git archive %s %s | tar -x -C %s" % (
                              checkout.folder, checkout.branch, checkout.repository,
                              checkout.folder, target, checkout.folder, checkout.commit[:12],
                              " ".join(checkout.paths), target), line)

    def test_nothing_is_printed_for_missing_when_everything_is_found(self):
        missing = [c for c in frameworks.CHECKOUTS if not provided_by_installed_ros(c) and
                   isinstance(frameworks.find_checkout(c.folder), frameworks.Missing)]
        if missing:
            self.skipTest("frameworks missing here: " + ", ".join(c.folder for c in missing))
        self.assertEqual(tool("--missing").stdout, "")

    def test_another_version_is_reported_as_such(self):
        checkout = frameworks.BY_FOLDER["smacha"]
        with tempfile.TemporaryDirectory() as root:
            write(os.path.join(root, "smacha", "smacha", "package.xml"), "<package/>\n")
            result = tool(env={"SMACHAC_FRAMEWORKS": root})
        self.assertIn("skip: missing smacha (%s): %s holds another version: smacha is not "
                      "commit %s's (tree %s expected); smacha_ros is missing;" % (
                          checkout.provides, os.path.join(root, "smacha"), checkout.commit[:12],
                          checkout.trees["smacha"][:12]), result.stdout)

    def test_bad_arguments_exit_2(self):
        self.assertEqual(tool("get", "nonesuch").returncode, 2)
        self.assertIn("frameworks: unknown nonesuch (known: all, executive_smach,",
                      tool("get", "nonesuch").stderr)
        self.assertEqual(tool("get", "all", "--from", "/nonexistent").returncode, 2)
        self.assertEqual(tool("get").returncode, 2)
        self.assertEqual(tool("table", "smacha").returncode, 2)

    def test_get_from_a_folder_that_is_no_clone_fails_with_exit_1(self):
        with tempfile.TemporaryDirectory() as folder:
            result = tool("get", "smacha", "--from", folder,
                          env={"SMACHAC_FRAMEWORKS": os.path.join(folder, "fw")})
        self.assertEqual(result.returncode, 1)
        self.assertTrue(result.stderr.startswith("frameworks: smacha: %s has no commit "
                                                 "253215a35d2d with smacha smacha_ros" % folder),
                        result.stderr)

    def test_the_readme_table_is_the_tables(self):
        with open(os.path.join(ROOT, "README.md"), encoding="utf-8") as f:
            readme = f.read()
        begin = "<!-- frameworks table: made by tools/frameworks table -->\n"
        shown = readme[readme.index(begin) + len(begin):
                       readme.index("<!-- end of the frameworks table -->")]
        self.assertEqual(shown, tool("table").stdout)


class OverlayTest(unittest.TestCase):
    def test_the_overlay_names_each_missing_framework_and_its_command(self):
        with tempfile.TemporaryDirectory() as folder:
            overlay = os.path.join(folder, "overlay")
            env = dict(os.environ, SMACHAC_FRAMEWORKS=os.path.join(folder, "none"))
            subprocess.run([PYTHON, os.path.join(ROOT, "tools", "ros", "overlay.py"), "build",
                            overlay], env=env, check=True, capture_output=True, timeout=300)
            with open(os.path.join(overlay, "overlay.json"), encoding="utf-8") as f:
                description = json.load(f)
        if description["problem"]:
            self.skipTest(description["problem"])
        none = os.path.join(folder, "none")
        expected = {
            "smach": "executive_smach is missing: no folder %s/executive_smach; "
                     "`tools/frameworks get executive_smach` provides it" % none,
            "flexbe": "flexbe_behavior_engine is missing: no folder %s/flexbe_behavior_engine; "
                      "`tools/frameworks get flexbe_behavior_engine` provides it" % none,
        }
        for name, why in expected.items():
            if not provided_by_installed_ros(frameworks.BY_FOLDER[why.split()[0]]):
                self.assertEqual(description["frameworks"][name], why)
        self.assertTrue(description["frameworks"]["baxter"].endswith(
            "`tools/frameworks get baxter_interface baxter_common gazebo_ros_pkgs control_msgs` "
            "provides them"), description["frameworks"]["baxter"])


def committed_blobs():
    listing = git(ROOT, "ls-files", "-s")
    return {line.split()[1] for line in listing.splitlines()}


def framework_blobs(path):
    for folder, names, files in os.walk(path):
        names[:] = [n for n in names if n not in frameworks.IGNORED_NAMES]
        for name in files:
            file_path = os.path.join(folder, name)
            if os.path.islink(file_path) or os.path.getsize(file_path) < SMALLEST_COMPARED:
                continue
            with open(file_path, "rb") as f:
                yield frameworks._git_object_id(b"blob", f.read()), file_path


class RepositoryTest(unittest.TestCase):
    def test_no_file_of_a_framework_found_here_is_committed(self):
        if not os.path.isdir(os.path.join(ROOT, ".git")):
            self.skipTest("not a git checkout")
        found = [frameworks.find_checkout(c.folder) for c in frameworks.CHECKOUTS]
        found = [f for f in found if isinstance(f, frameworks.Found)]
        if not found:
            self.skipTest("no framework checkout here to compare with")
        blobs = committed_blobs()
        copied = [path for f in found for blob, path in framework_blobs(f.path) if blob in blobs]
        self.assertEqual(copied, [])

    def test_nothing_names_the_old_vendor_folder(self):
        if not os.path.isdir(os.path.join(ROOT, ".git")):
            self.skipTest("not a git checkout")
        old = "shared/" + "vendor"  # written in two parts, so that this file does not name it
        result = subprocess.run(["git", "-C", ROOT, "grep", "-n", old], capture_output=True,
                                text=True)
        self.assertEqual(result.stdout, "")


if __name__ == "__main__":
    unittest.main()
