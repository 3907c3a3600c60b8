#!/usr/bin/env python3
"""The README's table of built-in templates by target, made from their meta blocks.

  tools/template_table.py SMACHAC README.md          rewrite the table in README.md
  tools/template_table.py SMACHAC README.md --check  exit 1 when the table is out of date

The table goes between the README's lines TABLE_BEGIN and TABLE_END. Its rows are the
templates `smachac help --target=T` lists for smach, cpp and flexbe, with the first target's
one-line summary; a target that has the template gets a check mark.
"""
import subprocess
import sys

TARGETS = ("smach", "cpp", "flexbe")
TABLE_BEGIN = "<!-- template table: made by tools/template_table.py from the templates' meta -->"
TABLE_END = "<!-- end of the template table -->"


def listed(smachac, target):
    """{template: summary} as `smachac help --target TARGET` lists them."""
    result = subprocess.run([smachac, "help", "--target", target, "--no-ansi"],
                            capture_output=True, text=True, check=True)
    templates = {}
    for line in result.stdout.splitlines()[1:]:
        name, _, summary = line.strip().partition(" ")
        templates[name] = summary.strip()
    return templates


def table(smachac):
    by_target = {target: listed(smachac, target) for target in TARGETS}
    names = sorted(set().union(*by_target.values()))
    lines = ["| template | " + " | ".join(TARGETS) + " | what it is |",
             "|---|" + "---|" * len(TARGETS) + "---|"]
    for name in names:
        marks = ["✓" if name in by_target[t] else "" for t in TARGETS]
        summary = next(by_target[t][name] for t in TARGETS if name in by_target[t])
        lines.append("| `%s` | %s | %s |" % (name, " | ".join(marks), summary.replace("|", "\\|")))
    return "\n".join(lines)


def with_table(readme, smachac):
    begin = readme.index(TABLE_BEGIN) + len(TABLE_BEGIN)
    end = readme.index(TABLE_END)
    return readme[:begin] + "\n" + table(smachac) + "\n" + readme[end:]


def main():
    smachac, path = sys.argv[1], sys.argv[2]
    with open(path, encoding="utf-8") as f:
        readme = f.read()
    updated = with_table(readme, smachac)
    if "--check" in sys.argv[3:]:
        if updated != readme:
            print("%s: the template table is out of date; run tools/template_table.py %s %s"
                  % (path, smachac, path), file=sys.stderr)
            return 1
        return 0
    with open(path, "w", encoding="utf-8") as f:
        f.write(updated)
    return 0


if __name__ == "__main__":
    sys.exit(main())
