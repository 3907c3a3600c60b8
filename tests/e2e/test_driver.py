"""The smachac driver as a user runs it: exit codes, atomic output, limits, determinism."""
import json
import os
import stat
import subprocess
import tempfile
import threading
import unittest

SMACHAC = os.environ["SMACHAC"]
ROOT = os.environ["SMACHAC_ROOT"]
EXAMPLES = os.path.join(ROOT, "examples", "core")
VALID = "name: t\ntemplate: Base\noutcomes: [done]\nstates:\n  - A: {template: S, transitions: {x: done}}\n"


def current_umask():
    mask = os.umask(0)
    os.umask(mask)
    return mask


def run(*args, cwd=None, env=None):
    return subprocess.run([SMACHAC, *args], capture_output=True, text=True, cwd=cwd, env=env,
                          timeout=120)


class TempDirTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def write(self, name, text):
        path = os.path.join(self.dir, name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(text)
        return path


class ExitCodes(TempDirTest):
    def test_success_writes_output_file(self):
        script = self.write("ok.yml", VALID)
        out = os.path.join(self.dir, "ok.ir")
        r = run("-target=ir", script, "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stdout, "")
        with open(out) as f:
            self.assertTrue(f.read().startswith("base t template=Base @1:1\n"))

    def test_output_into_a_fifo_keeps_the_fifo(self):
        # `-o /dev/null` as root once replaced the device with a file: a destination that is no
        # regular file is written into, not renamed over (a FIFO shows it without touching /dev).
        script = self.write("ok.yml", VALID)
        fifo = os.path.join(self.dir, "out.fifo")
        os.mkfifo(fifo)
        received = []

        def read():
            with open(fifo) as f:
                received.append(f.read())

        reader = threading.Thread(target=read)
        reader.start()
        r = run("-target=ir", script, "-o", fifo)
        reader.join(timeout=30)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertTrue(stat.S_ISFIFO(os.stat(fifo).st_mode))
        self.assertTrue(received and received[0].startswith("base t template=Base @1:1\n"))
        self.assertEqual(sorted(os.listdir(self.dir)), ["ok.yml", "out.fifo"])

    def test_output_over_existing_files(self):
        # An existing regular file is replaced by a new one (exchanged with the staged file,
        # tools/smachac/output.cpp): a hard link to it keeps the old content, nothing is left
        # behind. A symbolic link is replaced by the file, a directory refused, as by a rename.
        script = self.write("ok.yml", VALID)
        out = self.write("out.ir", "old\n")
        os.link(out, os.path.join(self.dir, "old.ir"))
        target = self.write("target.ir", "target\n")
        link = os.path.join(self.dir, "link.ir")
        os.symlink(target, link)
        os.mkdir(os.path.join(self.dir, "dir.ir"))
        for path in (out, link):
            r = run("-target=ir", script, "-o", path)
            self.assertEqual(r.returncode, 0, r.stderr)
            with open(path) as f:
                self.assertTrue(f.read().startswith("base t template=Base @1:1\n"))
            self.assertEqual(stat.S_IMODE(os.stat(path).st_mode), 0o666 & ~current_umask())
        self.assertFalse(os.path.islink(link))
        with open(os.path.join(self.dir, "old.ir")) as f:
            self.assertEqual(f.read(), "old\n")
        with open(target) as f:
            self.assertEqual(f.read(), "target\n")
        self.assertEqual(run("-target=ir", script, "-o", os.path.join(self.dir, "dir.ir")).returncode, 2)
        self.assertTrue(os.path.isdir(os.path.join(self.dir, "dir.ir")))
        self.assertEqual(sorted(os.listdir(self.dir)),
                         ["dir.ir", "link.ir", "ok.yml", "old.ir", "out.ir", "target.ir"])

    def test_double_dash_spelling(self):
        script = self.write("ok.yml", VALID)
        self.assertEqual(run("--target=ir", script).stdout, run("-target=ir", script).stdout)

    def test_usage_errors_exit_2(self):
        script = self.write("ok.yml", VALID)
        self.assertEqual(run("-target=nope", script).returncode, 2)
        self.assertEqual(run("--no-such-option", script).returncode, 2)
        self.assertEqual(run("-target=ir").returncode, 2)
        r = run("-target=ir", script, "-o", os.path.join(self.dir, "missing_dir", "x.ir"))
        self.assertEqual(r.returncode, 2)
        self.assertIn("cannot create a file in", r.stderr)

    def test_version_and_help(self):
        r = run("--version")
        self.assertEqual((r.returncode, r.stdout.strip()), (0, "smachac 0.1.0"))
        r = run("--help")
        self.assertEqual(r.returncode, 0)
        self.assertIn("-target", r.stdout.replace("--target", "-target"))
        self.assertIn("Subcommands: lint, render, contain, extract, lsp, help (", r.stdout)

    def test_lsp_usage_errors_exit_2(self):
        for args, message in ((["--target=nope"], "unknown target `nope`"),
                              (["-Wbogus"], "unknown diagnostic kind `bogus`")):
            with self.subTest(args=args):
                r = run("lsp", *args)
                self.assertEqual(r.returncode, 2)
                self.assertIn(message, r.stderr)
                self.assertEqual(r.stdout, "")


class CommandLine(TempDirTest):
    def test_standard_input(self):
        self.write("sub/greet.yml", "- G: {template: S, outcomes: [x]}\n")
        script = VALID + "  - B: {script: sub/greet, transitions: {x: done}}\n"
        r = subprocess.run([SMACHAC, "-target=ir", "-"], input=script, capture_output=True,
                           text=True, cwd=self.dir, timeout=120)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("leaf B template=S", r.stdout)  # sub/greet.yml, found from the cwd
        r = subprocess.run([SMACHAC, "lint", "-target=ir", "-"], input="name: t\n---\n",
                           capture_output=True, text=True, timeout=120)
        self.assertEqual(r.returncode, 1)
        self.assertTrue(r.stderr.startswith("<stdin>:2:1: error: a second YAML document"),
                        r.stderr)

    def test_usage_names_the_program(self):
        self.assertIn("Usage: smachac [OPTIONS]", run("--help").stdout)
        for command in ("lint", "render", "help", "contain", "extract"):
            with self.subTest(command=command):
                self.assertIn(f"Usage: smachac {command} [OPTIONS]", run(command, "--help").stdout)

    def test_lint_without_input(self):
        r = run("lint")
        self.assertEqual((r.returncode, r.stdout), (2, ""))
        self.assertEqual(r.stderr,
                         "smachac: error: lint: no input script (see `smachac lint --help`)\n")

    def test_help_lists_the_warning_flags(self):
        for args in (["--help"], ["lint", "--help"], ["lsp", "--help"]):
            with self.subTest(args=args):
                text = run(*args).stdout
                for flag in ("-Wno-<kind>", "-Werror=<kind>", "-Wall", "-Wextra", "-Weverything",
                             "--list-warnings"):
                    self.assertIn(flag, text)

    def test_list_warnings(self):
        for args in (["--list-warnings"], ["-list-warnings"], ["lint", "--list-warnings"],
                     ["lsp", "--list-warnings"]):
            with self.subTest(args=args):
                r = run(*args)
                self.assertEqual(r.returncode, 0, r.stderr)
                lines = r.stdout.splitlines()
                self.assertIn("unused-userdata-key                  warning (-Wall)", lines)
                self.assertIn("unknown-transition-target            error, -Wno-error=<kind> "
                              "makes it a warning", lines)

    def test_warning_groups(self):
        script = self.write("s.yml", "name: t\ntemplate: Base\noutcomes: [done]\n"
                            "userdata: {u: 1, v: 2}\nstates:\n"
                            "  - A: {template: S, input_keys: [v], transitions: {x: done}}\n")
        self.assertIn("[unused-userdata-key]", run("lint", "-target=ir", script).stderr)
        self.assertEqual(run("lint", "-target=ir", "-Wno-all", script).stderr, "")
        r = run("lint", "-target=ir", "-Wno-all", "-Wextra", "-Werror", script)
        self.assertEqual(r.returncode, 1)
        self.assertIn("error: userdata key `u` is set but never read", r.stderr)
        r = run("lint", "-Wunknown-root", script)
        self.assertEqual(r.returncode, 2)
        self.assertIn("did you mean one of `unknown-root-key`, `unknown-root-state`?", r.stderr)

    def test_python_syntax_can_be_downgraded(self):
        script = self.write("s.yml", "name: t\ntemplate: Base\noutcomes: [done]\n"
                            "userdata: {n: '`f(a=1, 2)`'}\nstates:\n"
                            "  - A: {template: PrintUserdataState, input_keys: [n],\n"
                            "        transitions: {succeeded: done}}\n")
        out = os.path.join(self.dir, "s.py")
        r = run("-target=smach", script, "-o", out)
        self.assertEqual(r.returncode, 1)
        self.assertIn("error: userdata `n` of `t` is not a Python expression: positional "
                      "argument after a keyword argument at character 8", r.stderr)
        self.assertFalse(os.path.exists(out))
        r = run("lint", script)  # lint (the pre-commit hook) checks the code too
        self.assertEqual(r.returncode, 1)
        self.assertIn("[python-syntax]", r.stderr)
        self.assertEqual(run("lint", "-target=ir", script).returncode, 0)  # no Python written
        r = run("-target=smach", "-Wno-error=python-syntax", script, "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("warning: userdata `n` of `t` is not a Python expression", r.stderr)
        with open(out) as f:
            self.assertIn("t.userdata.n = f(a=1, 2)\n", f.read())

    def test_render_keeps_the_json_key_order(self):
        self.write("Keys.tpl", "{% for k, v in d.items() %}{{ k }}={{ v }} {% endfor %}")
        context = self.write("ctx.json", '{"d": {"zeta": 1, "alpha": 2, "mid": 3}}')
        r = run("render", "Keys", "--context", context, "-I", self.dir)
        self.assertEqual((r.returncode, r.stdout), (0, "zeta=1 alpha=2 mid=3 "), r.stderr)


class AtomicOutput(TempDirTest):
    def test_failure_leaves_existing_file_untouched(self):
        out = self.write("out.ir", "previous contents\n")
        bad = self.write("bad.yml", "name: t\ntemplate: Base\nstates: [A: {outcomes: x}]\n")
        r = run("-target=ir", bad, "-o", out)
        self.assertEqual(r.returncode, 1)
        with open(out) as f:
            self.assertEqual(f.read(), "previous contents\n")
        self.assertEqual(sorted(os.listdir(self.dir)), ["bad.yml", "out.ir"])

    def test_failure_creates_no_file(self):
        bad = self.write("bad.yml", "states: [\n")
        out = os.path.join(self.dir, "new.ir")
        self.assertEqual(run("-target=ir", bad, "-o", out).returncode, 1)
        self.assertFalse(os.path.exists(out))
        self.assertEqual(os.listdir(self.dir), ["bad.yml"])


class Limits(TempDirTest):
    def test_script_too_large(self):
        path = os.path.join(self.dir, "huge.yml")
        with open(path, "w") as f:
            f.write("name: t\n")
            f.truncate(33 * 1024 * 1024)
        r = run("-target=ir", path)
        self.assertEqual(r.returncode, 1)
        self.assertEqual(r.stderr, f"smachac: error: `{path}` is 34603008 bytes; scripts are "
                                   "limited to 33554432 bytes [file-too-large]\n")

    def test_include_chain_too_deep(self):
        for i in range(70):
            self.write(f"s{i}.yml", f"- X:\n    template: StateMachine\n    outcomes: [done]\n"
                                    f"    states:\n      - N: {{script: s{i + 1}}}\n")
        self.write("main.yml", "name: t\ntemplate: Base\nstates:\n  - A: {script: s0}\n")
        r = run("-target=ir", "main.yml", cwd=self.dir)
        self.assertEqual(r.returncode, 1)
        self.assertIn("s63.yml:5:21: error: sub-scripts nested more than 64 deep "
                      "[include-too-deep]\n", r.stderr)

    def test_fifo_is_not_read(self):
        fifo = os.path.join(self.dir, "pipe.yml")
        os.mkfifo(fifo)
        r = run("-target=ir", fifo)
        self.assertEqual(r.returncode, 2)  # an I/O error
        self.assertEqual(r.stderr, f"smachac: error: cannot read `{fifo}`: it is not a regular "
                                   "file [unreadable-file]\n")


class Determinism(TempDirTest):
    def test_same_bytes_across_runs_directories_and_locales(self):
        script = os.path.join(EXAMPLES, "sub_scripts.yml")
        first = run("-target=json", script)
        env = dict(os.environ, LC_ALL="de_DE.UTF-8", LANG="de_DE.UTF-8")
        second = run("-target=json", script, cwd=self.dir, env=env)
        self.assertEqual(first.returncode, 0, first.stderr)
        self.assertEqual(first.stdout, second.stdout)


class Targets(unittest.TestCase):
    def test_every_example_compiles_to_ir_and_json(self):
        for name in sorted(os.listdir(EXAMPLES)):
            if not name.endswith(".yml"):
                continue
            path = os.path.join(EXAMPLES, name)
            with self.subTest(example=name):
                ir = run("-target=ir", path)
                self.assertEqual((ir.returncode, ir.stderr), (0, ""))
                doc = json.loads(run("-target=json", path).stdout)
                self.assertEqual(doc["format"], "smachac-ir")
                self.assertEqual(doc["root"]["kind"], "base")

    def test_lint_checks_several_files(self):
        files = [os.path.join(EXAMPLES, n) for n in ("sequence.yml", "nesting.yml")]
        r = run("lint", *files)
        self.assertEqual((r.returncode, r.stdout, r.stderr), (0, "", ""))

    def test_syntax_only_writes_nothing(self):
        r = run("-fsyntax-only", os.path.join(EXAMPLES, "sequence.yml"))
        self.assertEqual((r.returncode, r.stdout, r.stderr), (0, "", ""))


class QuickCommandLines(TempDirTest):
    """The common compile lines are read without CLI11 (tools/smachac/quick_args.h): each must
    do what CLI11 makes of it. `--fdiagnostics-format=text` (the default) sends a line to CLI11."""

    def outcome(self, args, out):
        if os.path.exists(out):
            os.remove(out)
        r = run(*args)
        text = open(out).read() if os.path.exists(out) else None
        return r.returncode, r.stdout, r.stderr, text

    def test_quick_lines_mean_what_cli11_reads(self):
        nesting = os.path.join(EXAMPLES, "nesting.yml")
        sub = os.path.join(EXAMPLES, "sub_scripts.yml")
        valid = self.write("ok.yml", VALID)
        out = os.path.join(self.dir, "out.txt")
        lines = [
            ["-target=smach", nesting, "-o", out],
            ["--target", "smach", nesting, "-o", out, "-c", "-i"],
            ["-target=smach", "-O", "--comments", "--output=" + out, nesting],
            ["-target=ir", "-I", self.dir, "-S", os.path.join(EXAMPLES, "sub"),
             "--template-dir=" + EXAMPLES, sub, "-o", out],
            ["-fsyntax-only", nesting, valid],
            ["-target=cpp", "--introspection", "--optimize", nesting, "-o", out],
            ["-target=nosuch", nesting, "-o", out],
            [nesting, valid, "-o", out],
            [],
            # not quick: combined flags, a repeated option, an empty or missing value
            ["-target=smach", "-ci", nesting, "-o", out],
            ["-o", out, "-o", out, nesting],
            ["-target=", nesting],
            [nesting, "-o"],
            ["-target=smach", nesting, "-o", "-"],
        ]
        for line in lines:
            with self.subTest(line=line):
                quick = self.outcome(line, out)
                cli11 = self.outcome(["--fdiagnostics-format=text"] + line, out)
                self.assertEqual(quick, cli11)


if __name__ == "__main__":
    unittest.main()
