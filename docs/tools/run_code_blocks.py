"""Runs every ```python block of the Markdown files given, each in a fresh
interpreter (this one) from the top of the source tree, so that a snippet of
the README or the manual that no longer runs fails a test (docs.code_blocks).

    /usr/bin/python3 docs/tools/run_code_blocks.py README.md [MORE.md ...]
"""
import os
import re
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BLOCK = re.compile(r"^```python\n(.*?)^```", re.S | re.M)


def main(paths):
    failures, count = 0, 0
    for path in paths:
        text = open(path).read()
        for m in BLOCK.finditer(text):
            count += 1
            line = text.count("\n", 0, m.start()) + 1
            run = subprocess.run([sys.executable, "-c", m.group(1)], cwd=ROOT, capture_output=True, text=True)
            status = "ok" if run.returncode == 0 else "FAILED"
            print(f"{path}:{line}: python block {status}")
            if run.returncode != 0:
                failures += 1
                print(run.stdout + run.stderr)
    if count == 0:
        print("no python blocks found")
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
