"""Random draws made deterministic, so that scripts with a random choice are compared too.

Python's `random` and the C++ runtime's generator draw differently (and SMACH's Concurrence
draws in threads, in no fixed order), so a script whose RandomOutcomeStates choose among several
outcomes cannot be compared as it is. It is compared once per combination of their outcomes
instead: in each variant every such state becomes a ConditionalOutcomeState with the same
outcomes whose one true condition is the outcome pinned (`!expr 'True'`; its `default` goes
where that outcome goes), so every path the script can take runs on every target. Like the
random state it writes `outcome`; its condition's key is remapped to `pinned_<state>` (states
of a Concurrence share their userdata, and would read each other's conditions).

A variant is the script re-written (PyYAML, tags such as `!expr` kept) into a copy of its
folder, so that its sub-scripts are found; its header comments are kept but `# EXPECT:` (the
outcome may differ by path). A script whose random state is in a sub-script, or that has
per-target variants, is not pinned (None); nor is one whose random state is in a loop (the
caller checks, canonical.in_loop): pinned, the loop might never end.
"""
import itertools
import os
import shutil

import yaml

MAX_VARIANTS = 16


class Tagged:
    """A scalar with a local tag (`!expr 'x + 1'`, `!str 5`), written back as it was."""

    def __init__(self, tag, value):
        self.tag = tag
        self.value = value


class Loader(yaml.SafeLoader):
    pass


class Dumper(yaml.SafeDumper):
    pass


Loader.add_multi_constructor("!", lambda loader, suffix, node:
                             Tagged("!" + suffix, loader.construct_scalar(node)))
Dumper.add_representer(Tagged, lambda dumper, data:
                       dumper.represent_scalar(data.tag, data.value, style="'"))


def find_state(states, parts):
    """The body of the state at `parts` (a path split at `/`) in a `states` list, or None."""
    for item in states or []:
        if isinstance(item, list):
            found = find_state(item, parts)
        elif isinstance(item, dict) and len(item) == 1:
            name, body = next(iter(item.items()))
            found = None
            if name == parts[0] and isinstance(body, dict):
                found = body if len(parts) == 1 else find_state(body.get("states"), parts[1:])
        else:
            found = None
        if found is not None:
            return found
    return None


def pin_state(name, body, outcome):
    """A RandomOutcomeState's body made to end with `outcome` every time."""
    body["template"] = "ConditionalOutcomeState"
    body["outcomes"] = list(body["outcomes"]) + ["default"]
    callbacks = dict(body.get("callbacks") or {})
    callbacks[outcome] = Tagged("!expr", "True")
    body["callbacks"] = callbacks
    transitions = body.get("transitions")
    if isinstance(transitions, dict) and outcome in transitions:
        body["transitions"] = dict(transitions, default=transitions[outcome])
    body["remapping"] = dict(body.get("remapping") or {}, **{outcome: "pinned_" + name})


def header_lines(path):
    lines = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            if not line.startswith("#"):
                break
            if not line.startswith("# EXPECT:"):
                lines.append(line)
    return "".join(lines)


def pinned_text(script, choice_by_path):
    with open(script, encoding="utf-8") as f:
        document = yaml.load(f, Loader=Loader)
    for path, outcome in choice_by_path.items():
        body = find_state(document.get("states"), path.split("/"))
        if body is None:
            return None
        pin_state(path.rsplit("/", 1)[-1], body, outcome)
    return header_lines(script) + yaml.dump(document, Dumper=Dumper, sort_keys=False,
                                            allow_unicode=True)


def variants(name, script, outcomes_by_path, work_dir):
    """[(name, script path)], one per combination of outcomes; None if it cannot be pinned."""
    paths = sorted(outcomes_by_path)
    combinations = list(itertools.product(*(outcomes_by_path[p] for p in paths)))
    if len(combinations) > MAX_VARIANTS:
        return None
    folder = os.path.join(work_dir, "pinned", name.replace("/", "__"))
    shutil.copytree(os.path.dirname(script), folder, dirs_exist_ok=True)
    found = []
    for number, combination in enumerate(combinations):
        choice = dict(zip(paths, combination))
        text = pinned_text(script, choice)
        if text is None:
            return None
        target = os.path.join(folder, "pinned_%d_%s" % (number, os.path.basename(script)))
        with open(target, "w", encoding="utf-8") as f:
            f.write(text)
        label = ", ".join("%s=%s" % item for item in choice.items())
        found.append(("%s {%s}" % (name, label), target))
    return found
