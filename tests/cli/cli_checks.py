"""What the CLI's check scripts share: check(cond, what) prints ok/FAIL and
keeps the failures; run(*cmd) runs a command and returns its exit status and
output; first_frame(exe, scenario, out) runs `eoir run` of a scenario's
first frame into a fresh folder and returns its summary.json (exits on a
failed run)."""
import json
import os
import shutil
import subprocess
import sys

failures = []


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures.append(what)


def run(*cmd, timeout=600):
    r = subprocess.run(list(cmd), capture_output=True, text=True, timeout=timeout)
    return r.returncode, r.stdout + r.stderr


def first_frame(exe, scenario, out):
    shutil.rmtree(out, ignore_errors=True)
    start = json.load(open(scenario))["start"]
    code, text = run(exe, "run", scenario, "--out", out, "--stop", start, "--quiet")
    if code != 0:
        sys.exit(f"eoir run {scenario} failed ({code}): {text}")
    return json.load(open(os.path.join(out, "summary.json")))
