"""The anchors smachac is compared with, found on this machine, each with the reason when it is
not usable (the rows that need it print "skipped: <reason>").

  SMACHA      the original Python tool, from the frameworks folder's checkout `smacha`
              (tools/frameworks: $SMACHAC_FRAMEWORKS, else ~/.cache/smachac/frameworks).
              Its package is copied into a temporary folder and that copy is patched to
              import `unittest` instead of `unittest2` (Debian 12 has no unittest2); the
              checkout is never written.
  SMACH       the real smach library: an installed ROS's, else executive_smach/smach/src of
              the same folder; plain `smach` imports only the standard library.
  Jinja2      python3-jinja2, for bench/tmpl_bench_jinja.py's workload.
All Python runs on Debian's /usr/bin/python3 (the one that sees Debian's packages).
"""
import importlib.util
import os
import shutil
import subprocess
import sys
from pathlib import Path

PYTHON = "/usr/bin/python3"
CHECKOUT = Path(__file__).resolve().parent.parent.parent
sys.path.insert(0, str(CHECKOUT / "tools" / "ros"))

import frameworks  # noqa: E402
import installed_ros  # noqa: E402


def checkout_path(name):
    """(the frameworks folder's checkout `name`, None) or (None, why it is not usable)."""
    found = frameworks.find_checkout(name)
    if isinstance(found, frameworks.Missing):
        return None, "%s (tools/frameworks get %s)" % (found.describe(), name)
    return Path(found.path), None


def smacha_root():
    """SMACHA's repository folder (holding smacha/ and smacha_ros/), or None."""
    return checkout_path("smacha")[0]


def _python_has(module):
    """Whether Debian's python3 imports module (asked of that interpreter, not this one)."""
    if not os.path.exists(PYTHON):
        return False
    check = "import importlib.util, sys; sys.exit(importlib.util.find_spec(%r) is None)" % module
    return subprocess.run([PYTHON, "-c", check]).returncode == 0


class Smacha:
    """A patched temporary copy of SMACHA's `smacha` package; use as a context manager.

    argv(script, template_dirs, script_dirs, output) is the command line of its `generate`
    script, run on Debian's python3 with the copy on PYTHONPATH (env())."""

    def __init__(self, work_dir):
        self.root, missing = checkout_path("smacha")
        self.copy = Path(work_dir) / "smacha_copy"
        self.why_not = missing or self._why_not()

    @staticmethod
    def _why_not():
        for module, deb in (("jinja2", "python3-jinja2"), ("ruamel.yaml", "python3-ruamel.yaml")):
            if not _python_has(module):
                return "%s cannot import %s (apt-get install %s)" % (PYTHON, module, deb)
        return None

    def __enter__(self):
        if self.why_not is None:
            package = self.root / "smacha"
            shutil.copytree(package / "src", self.copy / "src")
            shutil.copytree(package / "scripts", self.copy / "scripts")
            util = self.copy / "src" / "smacha" / "util.py"
            text = util.read_text(encoding="utf-8")
            util.write_text(text.replace("import unittest2 as unittest", "import unittest"),
                            encoding="utf-8")
        return self

    def __exit__(self, *exc):
        shutil.rmtree(self.copy, ignore_errors=True)

    def env(self):
        env = dict(os.environ, PYTHONPATH=str(self.copy / "src"), PYTHONDONTWRITEBYTECODE="1")
        return env

    def argv(self, script, output, template_dirs=(), script_dirs=()):
        argv = [PYTHON, self.copy / "scripts" / "generate", script, "-o", output]
        if template_dirs:
            argv += ["-t"] + list(template_dirs)
        if script_dirs:
            argv += ["-s"] + list(script_dirs)
        return argv

    def ros_templates(self):
        """SMACHA's ROS templates (smacha_ros), which its ROS test scripts need."""
        return self.root / "smacha_ros" / "src" / "smacha_ros" / "templates"


class Smach:
    """The real SMACH library for running generated SMACH Python: env() puts it on
    PYTHONPATH (unless Debian's python3 imports an installed smach)."""

    def __init__(self):
        self.installed = installed_ros.installed_package("smach", "smach") is not None
        root, self.why_not = (None, None) if self.installed else checkout_path("executive_smach")
        self.src = root and root / "smach" / "src"

    def env(self):
        env = dict(os.environ, PYTHONDONTWRITEBYTECODE="1")
        if not self.installed:
            env["PYTHONPATH"] = str(self.src)
        return env


def jinja_why_not():
    """None when this interpreter imports jinja2 (the template row runs it in-process)."""
    if importlib.util.find_spec("jinja2") is None:
        return "python3-jinja2 is not installed"
    return None
