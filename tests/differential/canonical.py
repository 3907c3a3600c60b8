"""What a run did, in a form that does not depend on the framework or on thread scheduling.

A run is a list of enter/exit events (tools/ros/trace_protocol.py) and a result. Its canonical
form is one line per state execution, `PATH -> OUTCOME`, in the order the states were entered,
a state's inner executions after it; the children of a Concurrence ran at the same time, so
their executions (each with its own inner ones) are sorted by label. A state entered but never
left is `PATH -> (no outcome)`.
"""


class Execution:
    def __init__(self, path):
        self.path = path
        self.outcome = None
        self.inner = []

    def label(self):
        return self.path.rsplit("/", 1)[-1]


def parent_path(path):
    return path.rsplit("/", 1)[0] if "/" in path else ""


def executions(events):
    """The tree of executions: each enter opens one under the open execution of its parent."""
    top = Execution("")
    open_by_path = {"": top}
    for event in events:
        path = event["state"]
        if event["event"] == "enter":
            execution = Execution(path)
            open_by_path.get(parent_path(path), top).inner.append(execution)
            open_by_path[path] = execution
        elif event["event"] == "exit" and path in open_by_path:
            open_by_path.pop(path).outcome = event["outcome"]
    return top


def lines(events, concurrences):
    """Canonical lines of a run; `concurrences` holds the paths of the Concurrence states."""
    out = []

    def walk(execution):
        inner = execution.inner
        if execution.path in concurrences:
            inner = sorted(inner, key=Execution.label)
        for child in inner:
            outcome = child.outcome if child.outcome is not None else "(no outcome)"
            out.append("%s -> %s" % (child.path, outcome))
            walk(child)

    walk(executions(events))
    return out


def concurrence_paths(ir_json):
    """Paths of the Concurrence states in smachac's JSON IR (`-target=json`)."""
    paths = set()

    def walk(state, path):
        if state.get("kind") == "concurrence":
            paths.add(path)
        for child in state.get("states", []):
            walk(child, (path + "/" if path else "") + child["name"])

    walk(ir_json["root"], "")
    return paths


def random_choices(ir_json):
    """{path: [outcome, ...]} of the RandomOutcomeStates that choose among several outcomes."""
    found = {}

    def walk(state, path):
        template = (state.get("template") or {}).get("text")
        outcomes = state.get("outcomes", [])
        if template == "RandomOutcomeState" and len(outcomes) > 1:
            found[path] = [o["text"] if isinstance(o, dict) else o for o in outcomes]
        for child in state.get("states", []):
            walk(child, (path + "/" if path else "") + child["name"])

    walk(ir_json["root"], "")
    return found


def in_loop(ir_json, path):
    """Whether the state at `path` can be entered again through the transitions of its
    container (then a random draw may be what ends a loop)."""
    parts = path.split("/")
    container = ir_json["root"]
    for part in parts[:-1]:
        container = next(c for c in container.get("states", []) if c["name"] == part)
    siblings = {c["name"]: c for c in container.get("states", [])}

    def successors(name):
        return [t["target"]["text"] for t in siblings[name].get("transitions", [])
                if t.get("target_kind") == "state" and t["target"]["text"] in siblings]

    seen, frontier = set(), successors(parts[-1])
    while frontier:
        name = frontier.pop()
        if name == parts[-1]:
            return True
        if name not in seen:
            seen.add(name)
            frontier.extend(successors(name))
    return False


def typed(value):
    """A value whose comparison also compares types: Python finds 2 == 2.0 and True == 1, the
    targets must agree on int, float and bool too."""
    if isinstance(value, dict):
        return {key: typed(item) for key, item in value.items()}
    if isinstance(value, list):
        return [typed(item) for item in value]
    if isinstance(value, float):
        return ("float", repr(value))
    if isinstance(value, (bool, int)):
        return (type(value).__name__, value)
    return value
