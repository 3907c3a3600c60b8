#!/usr/bin/env python3
"""Prints why tests were skipped, after `make test`: ctest itself shows only `(Skipped)`.

  print-skips.py JUNIT_XML     (ctest --output-junit)

For a skipped test, the reason is its output (a test that skips prints why). For a test that
passed but left some of its cases out, its lines that start with `skip` are printed too, so
what did not run is visible in the ordinary output.
"""
import sys
import xml.etree.ElementTree as ET

MAX_LINES = 6
SHOWN_CASES = 4  # a test's left-out cases shown; the rest are counted


def skip_lines(output):
    return [l for l in output.splitlines() if l.lower().startswith("skip")]


def left_out_cases(test, lines):
    shown = ["%s: %s" % (test, l) for l in lines[:SHOWN_CASES]]
    if len(lines) > SHOWN_CASES:
        shown.append("%s: ... and %d more (ctest -R '%s' -V)" % (test, len(lines) - SHOWN_CASES,
                                                               test))
    return shown


def main():
    try:
        suite = ET.parse(sys.argv[1]).getroot()
    except (OSError, ET.ParseError) as error:
        print("print-skips: cannot read %s: %s" % (sys.argv[1], error))
        return 0
    report = []
    for case in suite.iter("testcase"):
        output = case.findtext("system-out") or ""
        if case.find("skipped") is not None:
            lines = skip_lines(output) or output.strip().splitlines()[-MAX_LINES:]
            report.append("%s: skipped: %s" % (case.get("name"), " / ".join(lines)))
        elif case.find("failure") is None:
            report += left_out_cases(case.get("name"), skip_lines(output))
    if report:
        print("\nNot run, and why:")
        for line in report:
            print("  " + line)
    return 0


if __name__ == "__main__":
    sys.exit(main())
