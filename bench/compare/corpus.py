"""SMACHA's public test scripts, with the command lines that compile each one with smachac and
with SMACHA.

The scripts are SMACHA_ROOT/{smacha,smacha_ros}/test/smacha_scripts/<group>/*.yml for the
groups smacha_test_examples and executive_smach_tutorials. Sub-scripts (included by another
script of the folder, `script: NAME` or shorthand `S: NAME`) are not programs and are left
out. Each script gets what SMACHA's own tests give it: its folder as a script directory, its
group's test templates (test/smacha_templates/<group>) as a template directory, and for
smacha_ros SMACHA's ROS templates (smachac has its ROS templates built in).
"""
import re
from pathlib import Path

PACKAGES = ("smacha", "smacha_ros")
GROUPS = ("smacha_test_examples", "executive_smach_tutorials")


class Script:
    def __init__(self, root, package, group, path):
        self.package, self.group, self.path = package, group, Path(path)
        self.name = self.path.stem
        self.label = "%s/%s/%s" % (package, group, self.name)
        test = Path(root) / package / "test"
        self.folder = self.path.parent
        templates = test / "smacha_templates" / group
        self.templates = templates if templates.is_dir() else None
        self.text = self.path.read_text(encoding="utf-8")

    def includes(self, other):
        pattern = r"\b(script|S)\s*:\s*['\"]?%s(\.yml)?\b" % re.escape(other.name)
        return other is not self and re.search(pattern, self.text) is not None

    def smachac_argv(self, smachac, output, flags=()):
        argv = [smachac, "-target=smach", "-S", self.folder] + list(flags)
        if self.templates:
            argv += ["-I", self.templates]
        return argv + [self.path, "-o", output]

    def smacha_argv(self, smacha, output):
        templates = [smacha.ros_templates()] if self.package == "smacha_ros" else []
        if self.templates:
            templates.append(self.templates)
        return smacha.argv(self.path, output, template_dirs=templates,
                           script_dirs=[self.folder])


def scripts(root):
    """Every program script of the corpus under root (SMACHA's repository folder)."""
    found = []
    for package in PACKAGES:
        for group in GROUPS:
            folder = Path(root) / package / "test" / "smacha_scripts" / group
            if not folder.is_dir():
                continue
            group_scripts = [Script(root, package, group, p) for p in sorted(folder.glob("*.yml"))]
            found += [s for s in group_scripts
                      if not any(other.includes(s) for other in group_scripts)]
    return found
