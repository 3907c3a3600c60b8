"""Rows: compiles of big generated scripts, where the compile itself dominates process start.

For each size of config.SCALE_SIZES the flat script (scripts.flat_script: one container of N
WorkState leaves in a chain with back edges, bench/passes_bench.cpp's `flat`) is
  compiled to SMACH Python: `smachac -target=smach -I templates` vs SMACHA's generator with
    the same template folder (up to config.SMACHA_MAX_STATES: SMACHA is slow), wall time and
    peak RSS (os.wait4's ru_maxrss of the process);
  checked: `smachac lint -I templates` (SMACHA has no checker: no anchor).
Then the growth from the smallest to the largest size, and size by size (a linear compiler
grows like the number of states; the smallest figure includes process start-up).
"""
import config
import measure
import scripts
import table
from context import TEMPLATES

GROUP = "big scripts"


def label(n):
    return "%dk" % (n // 1000) if n % 1000 == 0 else str(n)


def rows(ctx):
    compile_rows, rss_rows, lint_rows = [], [], []
    figures = {}  # (kind, n): (wall, rss) of smachac
    smacha_seconds = {}  # n: SMACHA's median wall time
    for n in config.SCALE_SIZES:
        script = ctx.write("flat_%d.yml" % n, scripts.flat_script(n))
        ours_out, theirs_out = ctx.path("flat_%d_smachac.py" % n), ctx.path("flat_smacha.py")

        def ours():
            return measure.run([ctx.smachac, "-target=smach", "-I", TEMPLATES, script,
                                "-o", ours_out])

        def anchor():
            return measure.run(ctx.smacha.argv(script, theirs_out, template_dirs=[TEMPLATES]),
                               env=ctx.smacha.env())

        what = "flat %s states → SMACH Python" % label(n)
        if ctx.smacha.why_not or n > config.SMACHA_MAX_STATES:
            ctx.say("compile flat %s (smachac)" % label(n))
            result = measure.pair(config.REPEATS, ours, None, anchor_repeats=0)
            why = ctx.smacha.why_not or too_slow(smacha_seconds)
            compile_rows.append(table.skipped(GROUP, what + " (wall)",
                                              table.seconds(result.median("ours", "wall")),
                                              "SMACHA", why))
            rss_rows.append(table.skipped(GROUP, what + " (peak RSS)",
                                          table.megabytes(result.median("ours", "rss_mb")),
                                          "SMACHA", why))
        else:
            runs = config.SMACHA_SCALE_REPEATS.get(n, config.REPEATS)
            ctx.say("compile flat %s (smachac %d runs, SMACHA %d)" % (label(n), config.REPEATS,
                                                                      runs))
            result = measure.pair(config.REPEATS, ours, anchor, anchor_repeats=runs)
            smacha_seconds[n] = result.median("anchor", "wall")
            note = "median of %d runs (SMACHA %d)" % (config.REPEATS, runs)
            compile_rows.append(table.Row(
                GROUP, what + " (wall)", table.seconds(result.median("ours", "wall")), "SMACHA",
                table.seconds(result.median("anchor", "wall")), result.ratio("wall"), note))
            rss_rows.append(table.Row(
                GROUP, what + " (peak RSS)", table.megabytes(result.median("ours", "rss_mb")),
                "SMACHA", table.megabytes(result.median("anchor", "rss_mb")),
                result.ratio("rss_mb"), note))
        figures[("compile", n)] = (result.median("ours", "wall"), result.median("ours", "rss_mb"))
        ctx.say("lint flat %s" % label(n))
        lint = measure.repeat(config.REPEATS, lambda: measure.run(
            [ctx.smachac, "lint", "-I", TEMPLATES, script]))
        wall = measure.median([s.wall for s in lint])
        rss = measure.median([s.rss_mb for s in lint])
        figures[("lint", n)] = (wall, rss)
        lint_rows.append(table.Row(GROUP, "`smachac lint` flat %s states (wall / peak RSS)"
                                   % label(n), "%s / %s" % (table.seconds(wall),
                                                            table.megabytes(rss)),
                                   "", "no anchor (SMACHA has no checker)", "—",
                                   "median of %d runs" % config.REPEATS))
    return compile_rows + rss_rows + lint_rows + growth_rows(figures)


def too_slow(smacha_seconds):
    why = "SMACHA is run up to %s states only (it is slow" % label(config.SMACHA_MAX_STATES)
    if smacha_seconds:
        largest = max(smacha_seconds)
        why += ": %s at %s" % (table.seconds(smacha_seconds[largest]), label(largest))
    return why + ")"


def growth_rows(figures):
    sizes = config.SCALE_SIZES
    small, big = sizes[0], sizes[-1]
    if small == big:
        return []
    out = []
    for kind, name in (("compile", "smachac compile → SMACH Python"), ("lint", "`smachac lint`")):
        steps = ", ".join("%s→%s %.1f×" % (label(a), label(b), figures[(kind, b)][0] /
                                            figures[(kind, a)][0])
                          for a, b in zip(sizes, sizes[1:]))
        (w0, r0), (w1, r1) = figures[(kind, small)], figures[(kind, big)]
        out.append(table.Row(
            GROUP, "growth of %s, flat %s → %s states" % (name, label(small), label(big)),
            "wall %.0f×, peak RSS %.0f×" % (w1 / w0, r1 / r0), "",
            "linear: %d×" % (big // small), "—",
            "wall step by step: %s (linear: %s)" % (
                steps, ", ".join("%.0f×" % (b / a) for a, b in zip(sizes, sizes[1:])))))
    return out
