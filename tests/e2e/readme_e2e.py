"""The README's tour shows what the files hold and what the commands print, its shell
sessions run as shown, its template table is made from the templates, and its pre-commit
set-up works as written.

A shown block may leave lines out where it has a line `...`: each run of lines between two
`...` must appear in the real text as consecutive lines, in the order shown.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

SMACHAC = os.environ["SMACHAC"]
ROOT = os.environ["SMACHAC_ROOT"]
RUNTIME_LIBRARY = os.environ.get("SMACHAC_RUNTIME_LIBRARY", "")
CXX = os.environ.get("SMACHAC_CXX", "c++")
SANITIZER_FLAGS = os.environ.get("SMACHAC_E2E_CXXFLAGS", "")  # those of a sanitized tree


def readme_blocks():
    """The fenced blocks of README.md, each as its list of lines."""
    blocks, current = [], None
    with open(os.path.join(ROOT, "README.md"), encoding="utf-8") as f:
        for line in f.read().splitlines():
            if line.startswith("```"):
                if current is None:
                    current = []
                else:
                    blocks.append(current)
                    current = None
            elif current is not None:
                current.append(line)
    return blocks


def block_starting(first_line):
    found = [b for b in readme_blocks() if b and b[0] == first_line]
    if len(found) != 1:
        raise AssertionError("README.md has %d blocks starting with %r" % (len(found), first_line))
    return found[0]


def runs_between_ellipses(shown):
    runs, current = [], []
    for line in shown:
        if line.strip() == "...":
            runs.append(current)
            current = []
        else:
            current.append(line)
    runs.append(current)
    return [r for r in runs if r]


def missing_from(shown, actual):
    """The first run of shown lines not found in order in `actual`, or None."""
    position = 0
    for run in runs_between_ellipses(shown):
        for start in range(position, len(actual) - len(run) + 1):
            if actual[start:start + len(run)] == run:
                position = start + len(run)
                break
        else:
            return run
    return None


TRACE_TIME = re.compile(r"^\[ *[0-9.]+\]")


def commands(block):
    """(command, the lines shown after it) for each `$ ` line of a session; a command may go
    on over lines that end in a backslash."""
    found = []
    for line in block:
        if line.startswith("$ "):
            found.append([line[2:], []])
        elif found and found[-1][0].endswith("\\"):
            found[-1][0] = found[-1][0][:-1] + line.strip()
        elif found:
            found[-1][1].append(line)
    return [(command, shown) for command, shown in found]


def as_built(command):
    """A README command with smachac, the runtime and its headers where this build has them."""
    command = re.sub(r"^smachac ", SMACHAC + " ", command)
    command = command.replace("build/stdlib/runtime/libsmachac_runtime.a", RUNTIME_LIBRARY)
    command = command.replace("-I stdlib/runtime/include",
                              "-I " + os.path.join(ROOT, "stdlib", "runtime", "include"))
    if not command.startswith("c++ "):
        return command
    return command.replace("c++ ", " ".join(filter(None, [CXX, SANITIZER_FLAGS])) + " ", 1)


def smachac(*args):
    result = subprocess.run([SMACHAC, *args], cwd=ROOT, capture_output=True, text=True,
                            timeout=60)
    if result.returncode != 0:
        raise AssertionError("smachac %s failed: %s" % (" ".join(args), result.stderr))
    return result.stdout


class Tour(unittest.TestCase):
    def assert_shown(self, shown, actual, what):
        run = missing_from(shown, actual)
        self.assertIsNone(run, "README.md shows lines that %s does not have:\n%s"
                          % (what, "\n".join(run or [])))

    def test_shortened_script_is_an_excerpt_of_the_example(self):
        shown = block_starting("# examples/core/nesting.yml (shortened: `...` marks what is "
                               "left out)")
        with open(os.path.join(ROOT, "examples", "core", "nesting.yml"), encoding="utf-8") as f:
            actual = f.read().splitlines()
        self.assert_shown(shown[1:], actual, "examples/core/nesting.yml")

    def test_ir_is_what_smachac_prints(self):
        command = "$ build/tools/smachac/smachac -target=ir examples/core/nesting.yml"
        shown = block_starting(command)
        actual = smachac("-target=ir", "examples/core/nesting.yml").splitlines()
        self.assert_shown(shown[1:], actual, "smachac -target=ir examples/core/nesting.yml")

    def test_smach_python_is_what_smachac_writes(self):
        shown = block_starting("$ smachac -target=smach examples/core/nesting.yml -o nesting.py")
        actual = smachac("-target=smach", "examples/core/nesting.yml").splitlines()
        main = actual[next(i for i, l in enumerate(actual) if l.startswith("def main")):]
        self.assert_shown(shown[2:], main, "the SMACH output of examples/core/nesting.yml")

    def test_the_template_table_is_made_from_the_templates(self):
        result = subprocess.run([sys.executable, os.path.join(ROOT, "tools", "template_table.py"),
                                 SMACHAC, os.path.join(ROOT, "README.md"), "--check"],
                                capture_output=True, text=True, timeout=60)
        self.assertEqual(result.returncode, 0, result.stderr)

    def test_mistakes_are_reported_as_shown(self):
        self.run_session(block_starting("$ cat broken.yml"))

    def test_the_cpp_counter_runs_as_shown(self):
        self.run_session(block_starting("$ cat counter.yml"))

    def test_render_prints_as_shown(self):
        self.run_session(block_starting("$ cat Edges.tpl"))

    def run_session(self, block):
        """Runs a README shell session in a temporary folder: `$ cat FILE` writes the lines
        shown after it; any other command runs (smachac, the compiler and the runtime as
        built), and what it prints must show the lines after it (trace times aside)."""
        with tempfile.TemporaryDirectory() as folder:
            for command, shown in commands(block):
                if command.startswith("cat "):
                    with open(os.path.join(folder, command[4:]), "w", encoding="utf-8") as f:
                        f.write("\n".join(shown) + "\n")
                    continue
                result = subprocess.run(as_built(command), shell=True, cwd=folder, text=True,
                                        stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                        timeout=120)
                actual = [TRACE_TIME.sub("[t]", l) for l in result.stdout.splitlines()]
                self.assert_shown([TRACE_TIME.sub("[t]", l) for l in shown], actual,
                                  "`%s`" % command)

    def test_an_excerpt_check_notices_a_changed_line(self):
        actual = ["a", "b", "c", "d"]
        self.assertIsNone(missing_from(["a", "...", "c", "d"], actual))
        self.assertEqual(missing_from(["a", "c"], actual), ["a", "c"])
        self.assertEqual(missing_from(["c", "...", "a"], actual), ["a"])


SCRIPT = """name: main
template: Base
outcomes: [done]
states:
  - SHOW:
      template: PrintUserdataState
      userdata: {x: 1}
      input_keys: [x]
      transitions: {succeeded: ARM}
  - ARM:
      script: arm
      transitions: {moved: done}
"""
SUB_SCRIPT = """- ARM:
    template: StateMachine
    outcomes: [moved]
    states:
      - MOVE:
          template: PrintUserdataState
          userdata: {pose: home}
          input_keys: [pose]
          transitions: {succeeded: moved}
"""


class PreCommit(unittest.TestCase):
    """A repository with scripts/ and scripts/sub/, and the README's .pre-commit-config.yaml."""

    def setUp(self):
        if shutil.which("pre-commit") is None:
            self.fail("pre-commit is missing: tools/install-deps installs it")
        self.tmp = tempfile.TemporaryDirectory()
        self.repo = os.path.join(self.tmp.name, "robot")
        self.env = dict(os.environ, HOME=self.tmp.name,
                        PRE_COMMIT_HOME=os.path.join(self.tmp.name, "pre-commit-cache"),
                        PATH=os.path.dirname(SMACHAC) + os.pathsep + os.environ["PATH"],
                        GIT_CONFIG_NOSYSTEM="1")
        self.git("init", "-q", self.repo, cwd=self.tmp.name)
        self.git("config", "user.email", "test@example.invalid")
        self.git("config", "user.name", "test")
        self.write("scripts/main.yml", SCRIPT)
        self.write("scripts/sub/arm.yml", SUB_SCRIPT)
        config = block_starting("repos:")
        self.write(".pre-commit-config.yaml", "\n".join(config) + "\n")
        self.git("add", "-A")
        self.git("commit", "-q", "-m", "scripts")

    def tearDown(self):
        self.tmp.cleanup()

    def write(self, name, text):
        path = os.path.join(self.repo, name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)

    def git(self, *args, cwd=None):
        subprocess.run(["git", *args], cwd=cwd or self.repo, env=self.env, check=True,
                       capture_output=True, timeout=60)

    def pre_commit(self, *args):
        return subprocess.run(["pre-commit", "run", *args], cwd=self.repo, env=self.env,
                              capture_output=True, text=True, timeout=120)

    def test_clean_scripts_pass(self):
        result = self.pre_commit("--all-files")
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        self.assertRegex(result.stdout, r"smachac lint\.+Passed")

    def test_every_file_with_errors_is_reported(self):
        self.write("scripts/main.yml", SCRIPT.replace("{moved: done}", "{moved: dnoe}"))
        self.write("scripts/other.yml", SCRIPT.replace("input_keys: [x]", "input_keys: [y]")
                   .replace("{moved: done}", "{moved: don}"))
        self.git("add", "-A")
        result = self.pre_commit("--all-files")
        self.assertEqual(result.returncode, 1, result.stdout)
        self.assertIn("scripts/main.yml:12:", result.stdout)
        self.assertIn("scripts/other.yml:12:", result.stdout)

    def test_a_sub_script_committed_alone_is_checked(self):
        self.write("scripts/sub/arm.yml", SUB_SCRIPT.replace("{succeeded: moved}",
                                                             "{succeeded: mvoed}"))
        self.git("add", "scripts/sub/arm.yml")
        result = self.pre_commit()  # the staged files only: the sub-script
        self.assertEqual(result.returncode, 1, result.stdout)
        self.assertIn("scripts/sub/arm.yml:9:", result.stdout)
        self.assertNotIn("scripts/main.yml", result.stdout)

    def test_the_hook_of_a_smachac_clone(self):
        head = subprocess.run(["git", "rev-parse", "HEAD"], cwd=ROOT, capture_output=True,
                              text=True)
        if head.returncode != 0:
            self.skipTest("the source tree is not a git repository")
        self.write(".pre-commit-config.yaml", CLONE_CONFIG % (ROOT, head.stdout.strip()))
        result = self.pre_commit("--all-files")
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        self.assertRegex(result.stdout, r"smachac lint\.+Passed")


# The form .pre-commit-hooks.yaml documents, with the source tree as the clone.
CLONE_CONFIG = """repos:
  - repo: %s
    rev: %s
    hooks:
      - id: smachac-lint
        files: ^scripts/.*\\.ya?ml$
        args: [-S, scripts/sub]
"""


if __name__ == "__main__":
    unittest.main()
