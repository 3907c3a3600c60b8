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
    """Paths of the RandomOutcomeStates that choose among more than one outcome."""
    paths = []

    def walk(state, path):
        template = (state.get("template") or {}).get("text")
        if template == "RandomOutcomeState" and len(state.get("outcomes", [])) > 1:
            paths.append(path)
        for child in state.get("states", []):
            walk(child, (path + "/" if path else "") + child["name"])

    walk(ir_json["root"], "")
    return paths
