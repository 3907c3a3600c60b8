#!/usr/bin/env python3
"""Runs e2e.lua in a headless Neovim against `smachac lsp`.

Usage: nvim_e2e.py SMACHAC EDITORS_DIR
Exit 0 when Neovim's LSP client got the diagnostics, jumped to the definition and applied the
code action; 1 on a failure; 77 (skipped) when nvim is not installed. Neovim and the server
are killed if they are still running after the time limit.
"""
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
TIME_LIMIT = 90


def main():
    smachac, editors = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    nvim = shutil.which("nvim")
    if not nvim:
        print("SKIP: nvim is not installed (tools/install-deps installs Debian's neovim)")
        return 77
    with tempfile.TemporaryDirectory() as work:
        script = os.path.join(work, "pick.yml")
        shutil.copy(os.path.join(HERE, "pick.yml"), script)
        env = dict(os.environ, SMACHAC=smachac, SMACHAC_EDITORS=editors, SCRIPT=script,
                   HOME=work, XDG_CONFIG_HOME=work, XDG_DATA_HOME=work, XDG_STATE_HOME=work,
                   XDG_CACHE_HOME=work)
        command = [nvim, "--headless", "--clean", "-n", "-i", "NONE", "-u", "NONE",
                   "-c", "luafile " + os.path.join(HERE, "e2e.lua")]
        process = subprocess.Popen(command, cwd=work, env=env, stdin=subprocess.DEVNULL,
                                   stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                   start_new_session=True)
        try:
            out, err = process.communicate(timeout=TIME_LIMIT)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, 9)
            out, err = process.communicate()
            print(out.decode(errors="replace") + err.decode(errors="replace"))
            print(f"FAIL: Neovim did not finish in {TIME_LIMIT} s")
            return 1
        finally:
            try:
                os.killpg(process.pid, 9)  # the server, should it outlive Neovim
            except ProcessLookupError:
                pass
        print(out.decode(errors="replace") + err.decode(errors="replace"))
        return 0 if process.returncode == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
