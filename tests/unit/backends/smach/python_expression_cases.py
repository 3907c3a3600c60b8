#!/usr/bin/python3
"""Checks the labels of python_expression_cases.txt against CPython: a line `ok<TAB>code`
must parse with ast.parse(code, mode="eval"), a line `error<TAB>code` must not (`{NL}` in
the code is a line break). The C++ recogniser is tested against the same file, so this makes
CPython the judge of both.

  python_expression_cases.py CASES.txt
"""
import ast
import sys
import warnings


def parses(code):
    warnings.simplefilter("ignore")  # `1if x else 2` warns, but parses
    try:
        ast.parse(code, mode="eval")
        return True
    except (SyntaxError, ValueError, MemoryError, RecursionError):
        return False


def main():
    failed = 0
    with open(sys.argv[1], encoding="utf-8") as f:
        lines = f.read().splitlines()
    for number, line in enumerate(lines, 1):
        label, _, code = line.partition("\t")
        if label not in ("ok", "error") or parses(code.replace("{NL}", "\n")) != (label == "ok"):
            print("FAIL line %d: %r is labelled %s; CPython says %s"
                  % (number, code, label, "ok" if parses(code.replace("{NL}", "\n")) else "error"))
            failed += 1
    print("%d passed, %d failed" % (len(lines) - failed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
