"""The trace that every target's runner prints, so that runs on different frameworks compare.

A runner prints, on standard output, one line per event:
    SMACHAC-TRACE {"event": "enter", "state": "CON/FOO"}
    SMACHAC-TRACE {"event": "exit", "state": "CON/FOO", "outcome": "done"}
and once, when the top state machine returns:
    SMACHAC-RESULT {"outcome": "finished", "userdata": {"counter": 3}}
A state's path is its label and its containers' labels joined by `/`; the top state machine is
not part of it. Userdata values are JSON: tuples become lists, other non-JSON values their
repr(). parse() reads the lines back from a runner's output.
"""
import json
import sys
import threading

TRACE = "SMACHAC-TRACE "
RESULT = "SMACHAC-RESULT "
_lock = threading.Lock()


def jsonable(value):
    if value is None or isinstance(value, (bool, int, float, str)):
        return value
    if isinstance(value, (list, tuple)):
        return [jsonable(v) for v in value]
    if isinstance(value, dict):
        return {str(k): jsonable(v) for k, v in value.items()}
    return repr(value)


def _print(prefix, record):
    with _lock:
        sys.stdout.write(prefix + json.dumps(record, sort_keys=True) + "\n")
        sys.stdout.flush()


def emit(event, path, outcome=None):
    record = {"event": event, "state": path}
    if event == "exit":
        record["outcome"] = outcome
    _print(TRACE, record)


def result(outcome, userdata):
    _print(RESULT, {"outcome": outcome, "userdata": jsonable(userdata)})


def parse(text):
    """(events, result or None) from a runner's standard output."""
    events, final = [], None
    for line in text.splitlines():
        # a framework's log line without its newline may stand before the marker
        for marker in (TRACE, RESULT):
            at = line.find(marker)
            if at < 0:
                continue
            record = json.loads(line[at + len(marker):])
            if marker == TRACE:
                events.append(record)
            else:
                final = record
    return events, final
