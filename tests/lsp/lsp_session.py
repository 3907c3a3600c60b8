#!/usr/bin/env python3
"""Runs scripted JSON-RPC sessions against `smachac lsp` and checks every reply exactly.

Usage: lsp_session.py SMACHAC SESSION...

A session file is a list of blocks; each starts at the beginning of a line:
  # comment
  -> {JSON}      a message the client sends
  <- {JSON}      the next message the server must send (exactly, compared as JSON)
  args: ...      extra arguments for `smachac lsp` (before the first message)
  env: NAME=val  an environment variable for the server (repeatable; substitutions apply)
  exit: N        the exit code the server must end with (default 0)
A JSON block runs until the next block. The runner sends the messages in order; before
sending the next one, it reads every `<-` reply that follows. After the last block it closes
the server's input, and the server must then end with no further output.

In message text, `$DIR` is the session file's directory (an absolute path, as in a file URI:
`file://$DIR/script.yml`), `$TMP` an empty temporary directory the runner makes for the
session and removes after it (XDG_CACHE_HOME is `$TMP/cache` unless an `env:` line says otherwise),
and `"$TEXT(name)"` the content of file `name` in that directory as a JSON string. With
SMACHAC_UPDATE_GOLDEN=1 the `<-` blocks are rewritten with what the server sent (review the
diff).
"""
import json
import os
import re
import select
import shutil
import subprocess
import sys
import tempfile
import time

REPLY_TIMEOUT = 30.0
TEXT_REF = re.compile(r'"\$TEXT\(([^)]+)\)"')


class SessionError(Exception):
    pass


def parse_session(path):
    blocks, current = [], None
    with open(path, encoding="utf-8") as f:
        for line in f:
            head = line[:3]
            if line.startswith("#"):
                current = None
                blocks.append(("comment", line))
                continue
            if head in ("-> ", "<- "):
                current = ["send" if head == "-> " else "expect", line[3:]]
                blocks.append(current)
            elif line.startswith(("args:", "exit:", "env:")):
                current = None
                key, _, value = line.partition(":")
                blocks.append((key, value.strip()))
            elif current is not None:
                current[1] += line
            elif line.strip():
                raise SessionError(f"{path}: line outside a block: {line.rstrip()}")
            else:
                blocks.append(("comment", line))
    return blocks


def substitute(text, directory, temporary):
    def read(match):
        with open(os.path.join(directory, match.group(1)), encoding="utf-8") as f:
            return json.dumps(f.read())
    return TEXT_REF.sub(read, text).replace("$DIR", directory).replace("$TMP", temporary)


def pretty(value, indent=0):
    """JSON with each object or list on one line when it fits in 96 columns."""
    flat = json.dumps(value, sort_keys=True)
    if len(flat) + indent <= 96 or not isinstance(value, (dict, list)) or not value:
        return flat
    inner = " " * (indent + 2)
    if isinstance(value, dict):
        items = [f"{inner}{json.dumps(k)}: {pretty(value[k], indent + 2)}" for k in sorted(value)]
        return "{\n" + ",\n".join(items) + "\n" + " " * indent + "}"
    items = [inner + pretty(v, indent + 2) for v in value]
    return "[\n" + ",\n".join(items) + "\n" + " " * indent + "]"


def unsubstitute(message, directory, temporary):
    return pretty(message).replace(directory, "$DIR").replace(temporary, "$TMP")


class Server:
    def __init__(self, command, env):
        self.process = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                        stderr=subprocess.PIPE, env=env)
        self.buffer = b""

    def send(self, message):
        body = json.dumps(message).encode()
        self.process.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        self.process.stdin.flush()

    def _fill(self, deadline):
        remaining = deadline - time.monotonic()
        if remaining <= 0:
            raise SessionError("timed out waiting for the server")
        ready, _, _ = select.select([self.process.stdout], [], [], remaining)
        if not ready:
            raise SessionError("timed out waiting for the server")
        chunk = os.read(self.process.stdout.fileno(), 1 << 16)
        if not chunk:
            raise SessionError("the server closed its output")
        self.buffer += chunk

    def receive(self, timeout=REPLY_TIMEOUT):
        deadline = time.monotonic() + timeout
        while b"\r\n\r\n" not in self.buffer:
            self._fill(deadline)
        header, _, rest = self.buffer.partition(b"\r\n\r\n")
        length = int(re.search(rb"Content-Length: *(\d+)", header).group(1))
        while len(rest) < length:
            self.buffer = header + b"\r\n\r\n" + rest
            self._fill(deadline)
            header, _, rest = self.buffer.partition(b"\r\n\r\n")
        self.buffer = rest[length:]
        return json.loads(rest[:length])

    def finish(self):
        self.process.stdin.close()
        try:
            code = self.process.wait(timeout=REPLY_TIMEOUT)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
            raise SessionError("the server did not end after its input was closed")
        self.buffer += self.process.stdout.read()
        return code

    def kill(self):
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait()


def run_session(smachac, path, update):
    directory = os.path.dirname(os.path.abspath(path))
    blocks = parse_session(path)
    args = [b[1] for b in blocks if b[0] == "args"]
    expected_exit = int(next((b[1] for b in blocks if b[0] == "exit"), "0"))
    command = [smachac, "lsp"] + (args[0].split() if args else [])
    temporary = tempfile.mkdtemp(prefix="lsp-session-")
    # Files the server writes (built-in templates' copies) go to the session's directory.
    env = dict(os.environ, XDG_CACHE_HOME=os.path.join(temporary, "cache"))
    for name, _, value in (b[1].partition("=") for b in blocks if b[0] == "env"):
        env[name.strip()] = substitute(value.strip(), directory, temporary)
    server = Server(command, env)
    out, failures = [], []
    try:
        for kind, text in blocks:
            if kind == "send":
                server.send(json.loads(substitute(text, directory, temporary)))
                out.append(f"-> {text}")
            elif kind == "expect":
                expected = json.loads(substitute(text, directory, temporary))
                actual = server.receive()
                if actual != expected:
                    failures.append(f"expected {json.dumps(expected, sort_keys=True)}\n"
                                    f"     got {json.dumps(actual, sort_keys=True)}")
                out.append(f"<- {unsubstitute(actual, directory, temporary)}\n")
            elif kind in ("args", "exit", "env"):
                out.append(f"{kind}: {text}\n")
            else:
                out.append(text)
        code = server.finish()
        if server.buffer:
            failures.append(f"unexpected output after the session: {server.buffer[:500]!r}")
        if code != expected_exit:
            failures.append(f"exit code {code}, expected {expected_exit}: "
                            f"{server.process.stderr.read().decode(errors='replace')[:2000]}")
    except SessionError as e:
        failures.append(str(e))
    finally:
        server.kill()
        shutil.rmtree(temporary, ignore_errors=True)
    broken = ("timed out waiting for the server", "the server closed its output",
              "the server did not end after its input was closed")
    if update and not any(f in broken for f in failures):
        with open(path, "w", encoding="utf-8") as f:
            f.write("".join(out))
        return []
    return failures


def main():
    smachac, sessions = sys.argv[1], sys.argv[2:]
    update = os.environ.get("SMACHAC_UPDATE_GOLDEN") == "1"
    failed = 0
    for path in sessions:
        failures = run_session(smachac, path, update)
        name = os.path.relpath(path)
        if failures:
            failed += 1
            print(f"FAIL {name}")
            for failure in failures:
                print("  " + failure.replace("\n", "\n  "))
        else:
            print(f"ok   {name}")
    print(f"{len(sessions) - failed}/{len(sessions)} sessions passed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
