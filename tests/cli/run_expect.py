#!/usr/bin/env python3
"""Runs a command and checks its exit status and output.

usage: run_expect.py (--ok | --fail) [--regex PATTERN]... [--stdin-file F] -- COMMAND...
--ok: exit status 0; --fail: non-zero (and not a crash). Each PATTERN must
match stdout+stderr (Python regex, searched).
"""
import re
import subprocess
import sys


def main():
    args = sys.argv[1:]
    sep = args.index("--")
    opts, cmd = args[:sep], args[sep + 1:]
    want_ok = "--ok" in opts
    patterns = [opts[i + 1] for i, o in enumerate(opts) if o == "--regex"]
    run = subprocess.run(cmd, capture_output=True, text=True)
    out = run.stdout + run.stderr
    print(f"$ {' '.join(cmd)}\nexit {run.returncode}\n{out}")
    if run.returncode < 0:
        sys.exit(f"FAILED: killed by signal {-run.returncode}")
    if want_ok and run.returncode != 0:
        sys.exit("FAILED: expected exit status 0")
    if not want_ok and run.returncode == 0:
        sys.exit("FAILED: expected a non-zero exit status")
    for p in patterns:
        if not re.search(p, out):
            sys.exit(f"FAILED: output does not match /{p}/")
    print("passed")


if __name__ == "__main__":
    main()
