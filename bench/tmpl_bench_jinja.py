#!/usr/bin/python3
"""The SMACHA-shaped template workload of tmpl_bench.cpp run with python3-jinja2, configured
like SMACHA (lstrip_blocks, jinja2.ext.do, skip-block token filter, one cached environment per
(template, block) pair, warm template caches).

usage: tmpl_bench_jinja.py [RESULTS_DIR]
Prints the workload time; with RESULTS_DIR (bench/run.sh's JSON results of bench_tmpl) also
prints smachac's time and the speed-up.
"""
import json
import sys
import time
from pathlib import Path

import jinja2

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests" / "tmpl_diff"))
import smacha_jinja  # noqa: E402  (the SMACHA-configured Jinja2 shared with the diff tests)

TEMPLATES = HERE / "tmpl_templates"
COUNT = 1000


def make_env(skip=()):
    return smacha_jinja.make_env(jinja2.FileSystemLoader(str(TEMPLATES)), skip)


class Templater:
    def __init__(self):
        self.main = make_env()
        self.block_envs = {}
        self.block_lists = {}

    def blocks(self, name):
        if name not in self.block_lists:
            self.block_lists[name] = sorted(smacha_jinja.all_blocks(self.main, name))
        return self.block_lists[name]

    def render_block(self, name, block, context):
        key = (name, block)
        if key not in self.block_envs:
            self.block_envs[key] = make_env(smacha_jinja.block_skip_list(self.blocks(name), block))
        return smacha_jinja.strip_block(self.block_envs[key].get_template(name).render(context))

    def render(self, name, context):
        if ("render", name) not in self.block_envs:
            self.block_envs[("render", name)] = make_env(["meta"])
        return self.block_envs[("render", name)].get_template(name).render(context)


def state_context(i, count, defined_headers):
    return {
        "name": f"STATE_{i}", "class_name": "WorkState", "parent_type": "StateMachine",
        "parent_sm_name": "sm_top", "outcomes": ["succeeded", "aborted"],
        "input_keys": ["in_a", "in_b"], "output_keys": ["out_x"],
        "transitions": {"succeeded": f"STATE_{i + 1}" if i + 1 < count else "done",
                        "aborted": "failed"},
        "remapping": {"in_a": f"data_{i}", "in_b": "shared"},
        "userdata": {f"x_{i}": i * 0.5, "label": f"state {i}", "target": "pkg.msg.Obj"},
        "duration": (i % 5) * 0.1, "defined_headers": defined_headers,
    }


def workload(templater, count):
    state = "WorkState.tpl.py"
    blocks = [b for b in templater.blocks(state) if b != "meta"]
    defined_headers = []
    buffers = {}
    for i in range(count):
        ctx = state_context(i, count, defined_headers)
        for block in blocks:
            code = templater.render_block(state, block, ctx)
            if code:
                buffers.setdefault(block, []).append(code)
    base = {"name": "top", "outcomes": ["done", "failed"]}
    for name in ("base_header", "imports", "defs", "class_defs", "cb_defs", "main_def", "body",
                 "footer", "execute", "base_footer"):
        base[name] = "".join(c + "\n" for c in buffers.get(name, [])).strip()
    base["header"] = {"sm_top": "".join(c + "\n" for c in buffers.get("header", [])).strip()}
    return len(templater.render("Base.tpl.py", base))


def main():
    templater = Templater()
    workload(templater, COUNT)  # warm every environment's compiled-template cache
    best = min(timed(templater) for _ in range(3))
    print(f"tmpl workload ({COUNT} states), python3-jinja2 {jinja2.__version__}: {best:.1f} ms")
    if len(sys.argv) > 1:
        results = Path(sys.argv[1]) / "bench_tmpl.json"
        if results.exists():
            ours = next(b for b in json.loads(results.read_text())["benchmarks"]
                        if b["name"] == "BM_TmplSmachaWorkload1000")
            ms = ours["cpu_time"] if ours["time_unit"] == "ms" else ours["cpu_time"] / 1e6
            print(f"tmpl workload ({COUNT} states), smachac: {ms:.1f} ms "
                  f"(target < 50 ms) -> {best / ms:.1f}x faster than Jinja2 (target >= 20x)")


def timed(templater):
    start = time.process_time()
    workload(templater, COUNT)
    return (time.process_time() - start) * 1000


if __name__ == "__main__":
    main()
