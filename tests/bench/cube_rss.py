#!/usr/bin/env python3
"""Peak memory of `eoir run --cube` against the number of frames (issue 23
item 2: the data cube is streamed to its file, never held whole).

Runs EOIR_EXE on the scenario (default tests/bench/scenes/cube_200x256.json:
256 x 256 pixels, 200 steps) without --cube over every step, and with --cube
over the first N steps for each N, one process per case; the peak resident
set of each process is its getrusage ru_maxrss (os.wait4). Writes a JSON
with the machine, date and commit, and prints a Markdown table.

usage: cube_rss.py EOIR_EXE OUT_JSON [--scenario FILE] [--frames 50,200] [--label TEXT]
"""
import argparse
import datetime
import json
import os
import platform
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def run_case(exe, scenario, frames, cube, threads):
    out = tempfile.mkdtemp(prefix="eoir_cube_rss_")
    try:
        cmd = [exe, "run", scenario, "--out", out, "--quiet", "--threads", str(threads)]
        if cube:
            cmd.append("--cube")
        if frames is not None:
            # The scenario's steps are 1 s from 18:00:00.
            stop = datetime.datetime(2010, 8, 25, 18, 0, 0) + datetime.timedelta(seconds=frames - 1)
            cmd += ["--stop", stop.strftime("%Y-%m-%dT%H:%M:%SZ")]
        began = time.monotonic()
        proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        _, status, usage = os.wait4(proc.pid, 0)
        wall = time.monotonic() - began
        err = proc.stderr.read().decode()
        proc.stderr.close()
        if os.waitstatus_to_exitcode(status) != 0:
            sys.exit(f"{' '.join(cmd)} failed: {err}")
        summary = json.load(open(os.path.join(out, "summary.json")))
        cube_bytes = 0
        for name in summary.get("cubes", {}).values():
            cube_bytes += os.path.getsize(os.path.join(out, name))
        return {"frames": len(summary["frames"]), "cube": cube, "peak_rss_MiB": usage.ru_maxrss / 1024.0,
                "wall_s": wall, "cube_file_MiB": cube_bytes / 1048576.0}
    finally:
        shutil.rmtree(out, ignore_errors=True)


def git_commit():
    try:
        return subprocess.run(["git", "-C", HERE, "rev-parse", "--short", "HEAD"], capture_output=True, text=True,
                              check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("exe")
    ap.add_argument("out_json")
    ap.add_argument("--scenario", default=os.path.join(HERE, "scenes", "cube_200x256.json"))
    ap.add_argument("--frames", default="50,200")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--label", default="")
    a = ap.parse_args()
    counts = [int(x) for x in a.frames.split(",")]
    rows = [run_case(a.exe, a.scenario, max(counts), False, a.threads)]
    rows += [run_case(a.exe, a.scenario, n, True, a.threads) for n in counts]
    result = {
        "benchmark": "cube_rss",
        "label": a.label,
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ"),
        "commit": git_commit(),
        "machine": {"cores": os.cpu_count(), "cpu": platform.processor() or platform.machine(),
                    "load_average": os.getloadavg()},
        "exe": os.path.abspath(a.exe),
        "scenario": os.path.relpath(a.scenario, os.path.dirname(HERE)),
        "rows": rows,
    }
    with open(a.out_json, "w") as f:
        json.dump(result, f, indent=2)
        f.write("\n")
    print(f"| frames | --cube | peak RSS MiB | wall s | cube file MiB |  ({a.label})")
    print("|---:|:--|---:|---:|---:|")
    for r in rows:
        print(f"| {r['frames']} | {'yes' if r['cube'] else 'no'} | {r['peak_rss_MiB']:.1f} | {r['wall_s']:.1f} | "
              f"{r['cube_file_MiB']:.1f} |")


if __name__ == "__main__":
    main()
