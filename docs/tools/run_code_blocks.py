"""Runs every ```python block of the Markdown files given, each in a fresh
interpreter (this one) from the top of the source tree, and every ```sh
block of the files given after --sh, each in bash (-e) in a fresh folder
where `build/bin/eoir` is $EOIR_CLI and `scenarios/` the tree's, so that a
snippet of the README or the manual that no longer runs fails a test
(docs.code_blocks). The manual's other ```sh blocks are the two commands
of the README (run by CI itself), the manual's own build and the
tutorials' commands (each run by its docs.tutorial.* test).

    /usr/bin/python3 docs/tools/run_code_blocks.py README.md [MORE.md ...] [--sh MORE.md ...]
"""
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BLOCK = re.compile(r"^```(python|sh)\n(.*?)^```", re.S | re.M)


def run_sh(code):
    with tempfile.TemporaryDirectory() as work:
        os.makedirs(os.path.join(work, "build", "bin"))
        os.symlink(os.environ["EOIR_CLI"], os.path.join(work, "build", "bin", "eoir"))
        os.symlink(os.path.join(ROOT, "scenarios"), os.path.join(work, "scenarios"))
        return subprocess.run(["bash", "-e", "-c", code], cwd=work, capture_output=True, text=True, timeout=600)


def main(args):
    failures, count = 0, 0
    shell = False
    for path in args:
        if path == "--sh":
            shell = True
            continue
        text = open(path).read()
        for m in BLOCK.finditer(text):
            if m.group(1) == "sh" and not shell:
                continue
            count += 1
            line = text.count("\n", 0, m.start()) + 1
            if m.group(1) == "sh":
                run = run_sh(m.group(2))
            else:
                run = subprocess.run([sys.executable, "-c", m.group(2)], cwd=ROOT, capture_output=True, text=True)
            status = "ok" if run.returncode == 0 else "FAILED"
            print(f"{path}:{line}: {m.group(1)} block {status}")
            if run.returncode != 0:
                failures += 1
                print(run.stdout + run.stderr)
    if count == 0:
        print("no code blocks found")
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
