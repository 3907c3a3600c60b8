#!/usr/bin/env python3
"""Fails when an entry of the diagnostic registry has no test that shows it.

* A kind of ir/support/diagnostic_kinds.def is covered when `[kind-name]` appears in some
  tests/golden/**/*.stderr file (text diagnostics end with the kind in brackets) or in an
  assertion of tests/e2e/*.py.
* A note of ir/support/diagnostic_notes.def is covered when some note shown by a test matches
  its format (each `{}` standing for any text): a `note: ...` line of a golden .stderr file or
  of an e2e assertion, or a related message of an LSP session (tests/lsp/sessions).
* A choice text of ir/support/diagnostic_arg_types.h (the closed sets of texts that some
  kinds and notes take as arguments) is covered when some message shown by those tests holds
  it (its `{}`, in a Numbered choice, standing for a number), or is listed below with the
  reason no test can show it."""
import glob
import os
import re
import sys


# Choice texts that no input reaches today, each with the reason (measured, not assumed).
UNREACHABLE_CHOICES = {
    # The value builder's depth limit (frontend kMaxYamlDepth, 1000 levels): yaml-cpp's own
    # guard stops first (about 500 levels of block mappings, fewer of flow collections), and
    # the simple reader gives up silently on deep input and hands it to yaml-cpp.
    "nested more than {} levels deep",
}


def read(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        return f.read()


def def_formats(text, macro):
    """(identifier, format) of each entry of a .def file, its string pieces joined."""
    entries = []
    for m in re.finditer(r"^" + macro + r"\((\w+),(.*?)\)\n(?=\S|$)", text, re.M | re.S):
        pieces = re.findall(r'"((?:[^"\\]|\\.)*)"', m.group(2))
        entries.append((m.group(1), pieces))
    return entries


def choice_texts(text):
    """(type, text) of each case of the choiceText functions."""
    texts = []
    for m in re.finditer(r"choiceText\((\w+) \w+\) \{(.*?)\n\}", text, re.S):
        for ret in re.finditer(r'return ((?:"(?:[^"\\]|\\.)*"\s*)+);', m.group(2)):
            texts.append((m.group(1), "".join(re.findall(r'"((?:[^"\\]|\\.)*)"', ret.group(1)))))
    return texts


def pattern(format_text, field):
    """A regex for a message of `format_text`, each `{}` standing for `field`."""
    parts = format_text.replace("{{", "{").replace("}}", "}").split("{}")
    return field.join(re.escape(p) for p in parts)


def shown_messages(root):
    """The notes and all messages that the golden, e2e and LSP tests show."""
    notes, messages = [], []
    for path in glob.glob(os.path.join(root, "tests/golden/**/*.stderr"), recursive=True):
        for line in read(path).splitlines():
            m = re.search(r"\b(error|warning|note): (.*?)( \[[a-z0-9-]+\])?$", line)
            if m:
                messages.append(m.group(2))
                if m.group(1) == "note":
                    notes.append(m.group(2))
    for path in glob.glob(os.path.join(root, "tests/e2e/*.py")):
        for m in re.finditer(r"note: ([^\n\"'\\]*)", read(path)):
            notes.append(m.group(1))
            messages.append(m.group(1))
    for path in glob.glob(os.path.join(root, "tests/lsp/sessions/*.session")):
        for m in re.finditer(r'"message": "((?:[^"\\]|\\.)*)"', read(path)):
            text = m.group(1).replace('\\"', '"').replace("\\\\", "\\")
            notes.append(text)
            messages.append(text)
    return notes, messages


def uncovered_kinds(root):
    kinds = [pieces[0] for _, pieces in
             def_formats(read(os.path.join(root, "ir/support/diagnostic_kinds.def")),
                         "SMACHAC_DIAGNOSTIC")]
    seen = set()
    for path in glob.glob(os.path.join(root, "tests/golden/**/*.stderr"), recursive=True):
        seen.update(re.findall(r"\[([a-z0-9-]+)\]$", read(path), re.M))
    # End-to-end tests cover the kinds whose inputs cannot be committed (a 33 MB script, a
    # chain of 70 sub-scripts): they assert the full diagnostic line, kind included.
    for path in glob.glob(os.path.join(root, "tests/e2e/*.py")):
        seen.update(re.findall(r"\[([a-z0-9-]+)\]", read(path)))
    missing = [f"diagnostic kind `{k}`" for k in kinds if k not in seen]
    return len(kinds), missing


def uncovered_notes(root, notes):
    entries = def_formats(read(os.path.join(root, "ir/support/diagnostic_notes.def")),
                          "SMACHAC_DIAGNOSTIC_NOTE")
    missing = []
    for name, pieces in entries:
        regex = re.compile(pattern("".join(pieces), ".+"))
        if not any(regex.fullmatch(n) for n in notes):
            missing.append(f"note `{name}` (\"{''.join(pieces)}\")")
    return len(entries), missing


def uncovered_choices(root, messages):
    texts = [(type_name, text)
             for type_name, text in choice_texts(
                 read(os.path.join(root, "ir/support/diagnostic_arg_types.h")))
             if text not in UNREACHABLE_CHOICES]
    missing = []
    for type_name, text in texts:
        regex = re.compile(pattern(text, r"\d+"))
        if not any(regex.search(m) for m in messages):
            missing.append(f"choice of {type_name} (\"{text}\")")
    return len(texts), missing


def main():
    root = sys.argv[1]
    notes, messages = shown_messages(root)
    failed = False
    for what, (count, missing) in (("diagnostic kinds", uncovered_kinds(root)),
                                   ("notes", uncovered_notes(root, notes)),
                                   ("choice texts", uncovered_choices(root, messages))):
        for m in missing:
            print(f"{m} has no test that shows it (golden .stderr, e2e or LSP session)")
        print(f"{count - len(missing)} of {count} {what} covered")
        failed = failed or bool(missing) or count == 0
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
