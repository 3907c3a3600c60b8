"""A golden case (tests/golden/<area>/<name>.yml) as the ROS tests see it.

Its leading comment lines may hold:
    # ARGS: <smachac arguments>        as for the golden runner (the case file is appended,
                                        or put where `%s` stands)
    # OUTCOME: <outcome>               the outcome its top state machine must reach
    # EXECUTE: no (<why>)              the program cannot meaningfully run; why
"""
import os
import shlex


class GoldenCase:
    def __init__(self, yml_path, expected_extension=".smach.py"):
        self.yml = os.path.abspath(yml_path)
        self.folder, file_name = os.path.split(self.yml)
        self.name = file_name[:-len(".yml")]
        self.expected_python = os.path.join(self.folder, self.name + expected_extension)
        self.args, self.outcome, self.no_execute = [], None, None
        self._read_header()

    def _read_header(self):
        with open(self.yml, encoding="utf-8", errors="replace") as f:
            for line in f:
                if not line.startswith("#"):
                    break
                if line.startswith("# ARGS:"):
                    self.args += shlex.split(line[len("# ARGS:"):])
                elif line.startswith("# OUTCOME:"):
                    self.outcome = line[len("# OUTCOME:"):].strip()
                elif line.startswith("# EXECUTE: no"):
                    why = line[len("# EXECUTE: no"):].strip()
                    self.no_execute = why[1:-1] if why.startswith("(") else why or "not meant to run"

    def smachac_argv(self, smachac):
        """The command that compiles the case, to be run in its folder."""
        args = [a for a in self.args if a not in ("%none",)]
        if "%s" in args:
            return [smachac] + [self.name + ".yml" if a == "%s" else a for a in args]
        return [smachac] + args + [self.name + ".yml"]

    def expected(self):
        with open(self.expected_python, encoding="utf-8", newline="") as f:
            return f.read()


def cases_with_output(folder, expected_extension):
    """The cases of folder that have an expected output (fail_* cases have none), sorted."""
    return [GoldenCase(os.path.join(folder, entry[:-len(expected_extension)] + ".yml"),
                       expected_extension)
            for entry in sorted(os.listdir(folder)) if entry.endswith(expected_extension)]


def smach_cases(folder):
    return cases_with_output(folder, ".smach.py")
