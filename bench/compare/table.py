"""The one table bench-compare prints: a Row per measurement (smachac's figure, the anchor and
its figure, the ratio anchor / smachac), formatted as Markdown, and the number formats.

A ratio above 1 means smachac is that many times faster (or smaller); below 1, slower.
"""


class Row:
    def __init__(self, group, what, ours, anchor="", theirs="", ratio=None, note=""):
        self.group, self.what, self.ours = group, what, ours
        self.anchor, self.theirs, self.ratio, self.note = anchor, theirs, ratio, note


def skipped(group, what, ours, anchor, why):
    """A row whose anchor did not run."""
    return Row(group, what, ours, anchor, "skipped: " + why)


def seconds(value):
    """A time in s, ms or µs with three significant digits."""
    if value is None:
        return "—"
    if value >= 1:
        return "%.2f s" % value
    if value >= 1e-3:
        ms = value * 1e3
        return ("%.1f ms" % ms) if ms < 100 else ("%.0f ms" % ms)
    return "%.0f µs" % (value * 1e6)


def megabytes(value):
    return "—" if value is None else "%.1f MB" % value if value < 100 else "%.0f MB" % value


def ratio(value):
    if value is None:
        return "—"
    if value >= 100:
        return "%.0f×" % value
    if value >= 10:
        return "%.1f×" % value
    return "%.2f×" % value


def markdown(rows):
    lines = ["| group | measurement | smachac | anchor | anchor's figure | ratio | note |",
             "|---|---|---|---|---|---|---|"]
    for r in rows:
        cells = [r.group, r.what, r.ours, r.anchor or "—", r.theirs or "—",
                 ratio(r.ratio) if not isinstance(r.ratio, str) else r.ratio, r.note]
        lines.append("| " + " | ".join(c.replace("|", "\\|") for c in cells) + " |")
    return "\n".join(lines)
