"""What every group of rows needs: the build tree's programs, a scratch folder, the anchors,
and progress messages (on standard error, so the table alone goes to standard output)."""
import sys
import time
from pathlib import Path

import anchors

ROOT = anchors.CHECKOUT
TEMPLATES = Path(__file__).resolve().parent / "templates"  # WorkState, for the flat script


class Context:
    def __init__(self, build, work, smacha):
        self.build = Path(build).resolve()
        self.work = Path(work)
        self.smachac = self.build / "tools" / "smachac" / "smachac"
        self.runtime = self.build / "stdlib" / "runtime" / "libsmachac_runtime.a"
        self.runtime_include = ROOT / "stdlib" / "runtime" / "include"
        self.bench_tmpl = self.build / "bench" / "bench_tmpl"
        self.smacha = smacha
        self.smach = anchors.Smach()
        self.started = time.monotonic()

    def path(self, name):
        return self.work / name

    def write(self, name, text):
        path = self.work / name
        path.write_text(text, encoding="utf-8")
        return path

    def elapsed(self):
        return time.monotonic() - self.started

    def say(self, message):
        print("[bench-compare %5.0f s] %s" % (self.elapsed(), message), file=sys.stderr,
              flush=True)
