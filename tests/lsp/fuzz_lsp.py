#!/usr/bin/env python3
"""Robustness fuzzing of `smachac lsp`: random edits and requests against the real server.

Usage: fuzz_lsp.py SMACHAC [--steps N] [--seed S]

Opens the example scripts and the code-action test scripts, then runs N seeded steps, each
one of: an incremental didChange (characters, YAML punctuation, lines, indentation, CRLF,
multi-byte and astral characters, ranges past the ends of lines and of the text, sometimes
a reversed range, which the server must ignore with the whole notification), a full-text
change, the edit of a code action the server offered (applied as an editor would), or a
burst of requests of every method of lsp/requests.def at random positions (past the end
too), some of them cancelled at once. After every step: every request has an answer (a
result, or "cancelled" for a cancelled one: any other error is a failure), the server is
alive; every 25 steps and at the end, the text the server holds is the client's: the last
publishDiagnostics carries the client's version, and replacing the whole text by the
client's gives the same diagnostics and the same answers to the whole-document requests.
Ends with shutdown/exit (exit code 0); the server is killed on any failure.

The number of steps defaults to 1000 (about 10 s); SMACHAC_LSP_FUZZ_STEPS and
SMACHAC_LSP_FUZZ_SEED override the defaults, as do --steps and --seed.
"""
import argparse
import glob
import json
import os
import random
import re
import select
import subprocess
import sys
import tempfile
import time
import urllib.parse

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
REPLY_TIMEOUT = 30.0
CHECK_EVERY = 25
REQUEST_CANCELLED = -32800

SNIPPETS = [
    ":", "-", "- ", "[", "]", "{", "}", ",", "#", "'", '"', "!", "&", "*", "|", ">", "?", "%",
    "@", "`", "!expr ", "\n", "\r\n", "\t", "  ", "    ", "é", "ü", "中文", "😀", "𝄞", "\u00a0",
    "template: ", "states:", "transitions: {", "outcomes: [", "input_keys: [", "- X:\n",
    "name: ", "script: ", "params: {a: 1}", "[params, x]", "\\", "~", "null", "0x1F", "1e99",
]

# The requests whose answer depends on the whole text only: the same text, the same answer.
WHOLE_DOCUMENT_METHODS = ("textDocument/documentSymbol", "textDocument/foldingRange",
                          "textDocument/semanticTokens/full")

CAPABILITIES = {
    "textDocument": {
        "codeAction": {"codeActionLiteralSupport": {"codeActionKind": {"valueSet": [
            "quickfix", "refactor", "refactor.rewrite", "refactor.extract"]}}},
        "documentSymbol": {"hierarchicalDocumentSymbolSupport": True},
        "completion": {"completionItem": {"snippetSupport": True}},
        "hover": {"contentFormat": ["markdown", "plaintext"]},
    },
    "workspace": {"workspaceEdit": {"documentChanges": True, "resourceOperations": ["create"]}},
}


class FuzzError(Exception):
    pass


def request_methods():
    with open(os.path.join(ROOT, "lsp", "requests.def"), encoding="utf-8") as f:
        return re.findall(r'^SMACHAC_LSP_REQUEST\("([^"]+)"', f.read(), re.MULTILINE)


def script_paths():
    paths = []
    for pattern in ("examples/core/*.yml", "examples/baxter/*.yml",
                    "tests/lsp/sessions/scripts/fix_*.yml"):
        paths += sorted(glob.glob(os.path.join(ROOT, pattern)))
    return paths


def uri_of(path):
    return "file://" + urllib.parse.quote(path)


# --- the server's view of positions (lsp/positions.cpp), on Python strings -----------------

def line_starts(text):
    starts = [0]
    for i, c in enumerate(text):
        if c == "\n":
            starts.append(i + 1)
    return starts


def line_content(text, starts, line):
    end = starts[line + 1] - 1 if line + 1 < len(starts) else len(text)
    content = text[starts[line]:end]
    return content[:-1] if content.endswith("\r") else content


def offset_of(text, position):
    """The offset of an LSP position: characters past the line's end are clamped to it, lines
    past the text's end are its end, a position inside a surrogate pair moves past it."""
    starts = line_starts(text)
    line, units = position["line"], position["character"]
    if line >= len(starts):
        return len(text)
    content = line_content(text, starts, line)
    seen = i = 0
    while i < len(content) and seen < units:
        seen += 2 if ord(content[i]) > 0xFFFF else 1
        i += 1
    return starts[line] + i


def position_of(text, offset):
    starts = line_starts(text)
    line = max(i for i, s in enumerate(starts) if s <= offset)
    content = line_content(text, starts, line)
    column = content[:offset - starts[line]]
    return {"line": line, "character": sum(2 if ord(c) > 0xFFFF else 1 for c in column)}


def apply_changes(text, changes):
    """The text after contentChanges, or None when one is invalid (the server then ignores
    the whole notification)."""
    for change in changes:
        if "range" not in change:
            text = change["text"]
            continue
        begin = offset_of(text, change["range"]["start"])
        end = offset_of(text, change["range"]["end"])
        if end < begin:
            return None
        text = text[:begin] + change["text"] + text[end:]
    return text


# --- the server process --------------------------------------------------------------------

class Server:
    def __init__(self, smachac):
        self.stderr = tempfile.TemporaryFile()
        self.cache = tempfile.TemporaryDirectory()  # built-in templates' copies
        self.process = subprocess.Popen([smachac, "lsp"], stdin=subprocess.PIPE,
                                        stdout=subprocess.PIPE, stderr=self.stderr, cwd=ROOT,
                                        env=dict(os.environ, XDG_CACHE_HOME=self.cache.name))
        self.buffer = b""
        self.next_id = 1
        self.pending = {}        # id -> (method, cancelled)
        self.answers = {}        # id -> response
        self.published = {}      # uri -> (version, diagnostics)

    def send(self, message):
        body = json.dumps(message).encode()
        try:
            self.process.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
            self.process.stdin.flush()
        except BrokenPipeError:
            raise FuzzError("the server closed its input (did it crash?)")

    def notify(self, method, params):
        self.send({"jsonrpc": "2.0", "method": method, "params": params})

    def request(self, method, params):
        request_id = self.next_id
        self.next_id += 1
        self.pending[request_id] = (method, False)
        self.send({"jsonrpc": "2.0", "id": request_id, "method": method, "params": params})
        return request_id

    def cancel(self, request_id):
        method, _ = self.pending[request_id]
        self.pending[request_id] = (method, True)
        self.notify("$/cancelRequest", {"id": request_id})

    def _fill(self, timeout):
        """Reads what the server wrote within `timeout` seconds; False when nothing came."""
        if not select.select([self.process.stdout], [], [], max(timeout, 0))[0]:
            return False
        chunk = os.read(self.process.stdout.fileno(), 1 << 16)
        if not chunk:
            raise FuzzError("the server closed its output (exit code %s)" % self.process.poll())
        self.buffer += chunk
        return True

    def _take(self):
        """The next complete message in the buffer, or None."""
        header, separator, rest = self.buffer.partition(b"\r\n\r\n")
        if not separator:
            return None
        match = re.search(rb"Content-Length: *(\d+)", header)
        if not match:
            raise FuzzError("a message without Content-Length: %r" % header[:200])
        length = int(match.group(1))
        if len(rest) < length:
            return None
        self.buffer = rest[length:]
        return json.loads(rest[:length])

    def _read(self, deadline):
        while True:
            message = self._take()
            if message is not None:
                return message
            if not self._fill(deadline - time.monotonic()) and time.monotonic() >= deadline:
                raise FuzzError("the server did not answer in %.0f s" % REPLY_TIMEOUT)

    def handle(self, message):
        if "id" in message and "method" in message:  # a request to the client
            self.send({"jsonrpc": "2.0", "id": message["id"], "result": None})
        elif "id" in message:
            self.answer(message)
        elif message.get("method") == "textDocument/publishDiagnostics":
            params = message["params"]
            self.published[params["uri"]] = (params.get("version"), params["diagnostics"])

    def answer(self, response):
        request_id = response["id"]
        if request_id not in self.pending:
            raise FuzzError("an answer to no pending request: %s" % json.dumps(response)[:300])
        method, cancelled = self.pending.pop(request_id)
        if "result" in response:
            self.answers[request_id] = response["result"]
            return
        error = response.get("error", {})
        if not (cancelled and error.get("code") == REQUEST_CANCELLED):
            raise FuzzError("%s failed: %s" % (method, json.dumps(error)[:500]))
        self.answers[request_id] = None

    def settle(self):
        """Reads until every request has its answer."""
        deadline = time.monotonic() + REPLY_TIMEOUT
        while self.pending:
            self.handle(self._read(deadline))
        self.check_alive()

    def drain(self, quiet):
        """Reads messages until none comes for `quiet` seconds (the server publishes the
        diagnostics of documents that depend on a changed one when it is idle)."""
        while True:
            message = self._take()
            if message is not None:
                self.handle(message)
            elif not self._fill(quiet):
                return

    def wait_published(self, uri, version):
        self.drain(0.05)
        deadline = time.monotonic() + REPLY_TIMEOUT
        while self.published.get(uri, (None,))[0] != version or self.pending:
            self.handle(self._read(deadline))
        return self.published[uri][1]

    def check_alive(self):
        if self.process.poll() is not None:
            raise FuzzError("the server exited with %s" % self.process.returncode)

    def finish(self):
        request_id = self.request("shutdown", None)
        self.settle()
        del self.answers[request_id]
        self.notify("exit", None)
        self.process.stdin.close()
        try:
            code = self.process.wait(timeout=REPLY_TIMEOUT)
        except subprocess.TimeoutExpired:
            raise FuzzError("the server did not exit")
        if code != 0:
            raise FuzzError("the server exited with %d after shutdown" % code)

    def kill(self):
        """Ends the server; what it wrote to its standard error."""
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait()
        self.cache.cleanup()
        self.stderr.seek(0)
        return self.stderr.read().decode(errors="replace")[-2000:]


# --- the fuzzer ----------------------------------------------------------------------------

class Document:
    def __init__(self, path):
        self.path = path
        self.uri = uri_of(path)
        with open(path, encoding="utf-8", newline="") as f:
            self.text = f.read()
        self.version = 1        # the last version sent
        self.accepted = 1       # the version of the text the server holds
        self.actions = []       # code actions offered for the current version


class Fuzzer:
    def __init__(self, server, documents, methods, rng):
        self.server = server
        self.documents = documents
        self.methods = methods
        self.rng = rng
        self.line_pool = [line for d in documents for line in d.text.split("\n")]
        self.originals = [d.text for d in documents]
        self.counts = {"requests": 0, "answers with content": 0, "edits": 0, "ignored edits": 0,
                       "code actions applied": 0, "text checks": 0}

    # positions

    def random_position(self, text):
        lines = text.split("\n")
        line = self.rng.randrange(len(lines) + 2)
        width = len(lines[line]) if line < len(lines) else 0
        return {"line": line, "character": self.rng.randrange(width + 4)}

    def nearby_position(self, text, start):
        begin = offset_of(text, start)
        end = min(len(text), begin + self.rng.choice([0, 1, 2, 5, 20, 80]))
        position = position_of(text, end)
        if self.rng.random() < 0.1:
            position["character"] += self.rng.randrange(1, 5)  # past the line's end
        return position

    # edits

    def snippet(self):
        roll = self.rng.random()
        if roll < 0.5:
            return "".join(self.rng.choice(SNIPPETS) for _ in range(self.rng.randrange(1, 4)))
        if roll < 0.8:
            return self.rng.choice(self.line_pool) + self.rng.choice(["\n", "\r\n", ""])
        return "".join(chr(self.rng.randrange(32, 127)) for _ in range(self.rng.randrange(1, 8)))

    def random_change(self, text):
        start = self.random_position(text)
        roll = self.rng.random()
        if roll < 0.1:  # indentation of a line
            line = {"line": start["line"], "character": 0}
            if self.rng.random() < 0.5:
                return {"range": {"start": line, "end": line}, "text": "  "}
            return {"range": {"start": line, "end": {"line": start["line"], "character": 2}},
                    "text": ""}
        end = self.nearby_position(text, start)
        if roll < 0.13:
            start, end = end, start  # reversed: the server ignores the notification
        replacement = "" if roll < 0.4 else self.snippet()
        return {"range": {"start": start, "end": end}, "text": replacement}

    def change(self, document, changes):
        document.version += 1
        self.server.notify("textDocument/didChange", {
            "textDocument": {"uri": document.uri, "version": document.version},
            "contentChanges": changes})
        text = apply_changes(document.text, changes)
        if text is not None:
            document.text = text
            document.accepted = document.version
        self.counts["edits" if text is not None else "ignored edits"] += 1
        document.actions = []

    def edit(self, document):
        changes, text = [], document.text
        for _ in range(self.rng.randrange(1, 4)):
            change = self.random_change(text)
            changes.append(change)
            text = apply_changes(text, [change]) if text is not None else None
            if text is None:
                break
        self.change(document, changes)

    def apply_action(self, document):
        """Applies the edit of an offered code action to the document, as an editor does."""
        for action in self.rng.sample(document.actions, len(document.actions)):
            changes = action.get("edit", {}).get("documentChanges", [])
            if any("kind" in change for change in changes):
                continue  # creates a file: not here
            for change in changes:
                identifier = change["textDocument"]
                if identifier["uri"] != document.uri:
                    continue
                if identifier["version"] != document.accepted:
                    raise FuzzError("a code action for version %s of version %s" %
                                    (identifier["version"], document.accepted))
                edits = sorted(change["edits"], key=lambda e: (e["range"]["start"]["line"],
                               e["range"]["start"]["character"]), reverse=True)
                self.change(document, [{"range": e["range"], "text": e["newText"]}
                                       for e in edits])
                self.counts["code actions applied"] += 1
                return

    def reopen(self, document):
        self.server.notify("textDocument/didClose", {"textDocument": {"uri": document.uri}})
        document.version += 1
        document.accepted = document.version
        document.actions = []
        self.server.notify("textDocument/didOpen", {"textDocument": {
            "uri": document.uri, "languageId": "yaml", "version": document.version,
            "text": document.text}})

    # requests

    def diagnostic_range(self, document):
        """The range of a diagnostic published for the current text, or None."""
        version, diagnostics = self.server.published.get(document.uri, (None, []))
        if version != document.accepted or not diagnostics:
            return None
        return self.rng.choice(diagnostics)["range"]

    def params(self, document, method):
        text = document.text
        start = self.random_position(text)
        end = self.nearby_position(text, start) if self.rng.random() < 0.7 else start
        at_diagnostic = self.diagnostic_range(document) if self.rng.random() < 0.5 else None
        if at_diagnostic:
            start, end = at_diagnostic["start"], at_diagnostic["end"]
        uri = document.uri if self.rng.random() < 0.95 else document.uri + ".closed.yml"
        context = {"diagnostics": [], "includeDeclaration": self.rng.random() < 0.5,
                   "triggerKind": 1}
        if self.rng.random() < 0.2:
            context["only"] = [self.rng.choice(["quickfix", "refactor", "refactor.extract"])]
        return {"textDocument": {"uri": uri}, "position": start,
                "range": {"start": start, "end": end}, "context": context,
                "newName": "RENAMED", "query": self.rng.choice(["", "A", "s"]),
                "options": {"tabSize": 2, "insertSpaces": True}}

    def requests(self, document):
        sent = []
        methods = [self.rng.choice(self.methods) for _ in range(self.rng.randrange(1, 4))]
        if "textDocument/codeAction" in self.methods and self.rng.random() < 0.4:
            methods.append("textDocument/codeAction")  # the fixes of a diagnostic, often
        for method in methods:
            request_id = self.server.request(method, self.params(document, method))
            sent.append((request_id, method))
            if self.rng.random() < 0.2:
                self.server.cancel(request_id)
        self.server.settle()
        for request_id, method in sent:
            result = self.server.answers.pop(request_id)
            self.counts["requests"] += 1
            self.counts["answers with content"] += 1 if result else 0
            if method == "textDocument/codeAction" and isinstance(result, list):
                document.actions = result
        if document.actions and self.rng.random() < 0.5:
            self.apply_action(document)

    # the text the server holds

    def whole_document_answers(self, document):
        ids = [self.server.request(m, {"textDocument": {"uri": document.uri}})
               for m in self.methods if m in WHOLE_DOCUMENT_METHODS]
        self.server.settle()
        return [self.server.answers.pop(i) for i in ids]

    def check_text(self, document):
        self.counts["text checks"] += 1
        before = self.server.wait_published(document.uri, document.accepted)
        answers_before = self.whole_document_answers(document)
        self.change(document, [{"text": document.text}])
        after = self.server.wait_published(document.uri, document.accepted)
        if before != after:
            raise FuzzError("%s: the server's text is not the client's: diagnostics %s, then "
                            "after a full-text change %s" % (document.path, before, after))
        if answers_before != self.whole_document_answers(document):
            raise FuzzError("%s: the server's text is not the client's (symbols or folding "
                            "ranges changed with a full-text change)" % document.path)

    # steps

    def step(self):
        document = self.rng.choice(self.documents)
        roll = self.rng.random()
        if roll < 0.45:
            self.edit(document)
        elif roll < 0.53:
            self.change(document, [{"text": self.rng.choice(self.originals)}])
        elif roll < 0.55:
            self.reopen(document)
        elif roll < 0.6 and document.actions:
            self.apply_action(document)
        else:
            self.requests(document)
        self.server.settle()

    def run(self, steps):
        for document in self.documents:
            self.server.notify("textDocument/didOpen", {"textDocument": {
                "uri": document.uri, "languageId": "yaml", "version": 1,
                "text": document.text}})
        for number in range(1, steps + 1):
            self.step()
            if number % CHECK_EVERY == 0:
                self.check_text(self.rng.choice(self.documents))
        for document in self.documents:
            self.check_text(document)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("smachac")
    parser.add_argument("--steps", type=int,
                        default=int(os.environ.get("SMACHAC_LSP_FUZZ_STEPS", "1000")))
    parser.add_argument("--seed", type=int,
                        default=int(os.environ.get("SMACHAC_LSP_FUZZ_SEED", "1")))
    args = parser.parse_args()
    rng = random.Random(args.seed)
    documents = [Document(path) for path in script_paths()]
    server = Server(args.smachac)
    started = time.monotonic()
    try:
        server.request("initialize", {"processId": None, "rootUri": uri_of(ROOT),
                                      "capabilities": CAPABILITIES})
        server.settle()
        server.notify("initialized", {})
        fuzzer = Fuzzer(server, documents, request_methods(), rng)
        fuzzer.run(args.steps)
        server.finish()
    except (FuzzError, KeyError, ValueError) as error:
        stderr = server.kill()
        print("fuzz_lsp: seed %d: %s" % (args.seed, error), file=sys.stderr)
        if stderr:
            print("the server's standard error:\n" + stderr, file=sys.stderr)
        return 1
    except BaseException:
        server.kill()
        raise
    print("fuzz_lsp: seed %d: %d steps on %d documents in %.1f s: %s" %
          (args.seed, args.steps, len(documents), time.monotonic() - started,
           ", ".join("%d %s" % (n, what) for what, n in fuzzer.counts.items())))
    return 0


if __name__ == "__main__":
    sys.exit(main())
