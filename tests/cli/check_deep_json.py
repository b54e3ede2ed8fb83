#!/usr/bin/env python3
"""A scenario nested 100,000 arrays deep (and one nested 100,000 objects deep)
is refused with exit status 2 and a message naming the limit, instead of
crashing the CLI with a stack overflow.

usage: check_deep_json.py EOIR_EXE
"""
import os
import subprocess
import sys
import tempfile


def main():
    exe = sys.argv[1]
    depth = 100000
    cases = {
        "arrays.json": '{"format": "eoir-scenario", "version": 1, "name": "deep", "start": "2010-01-01", '
                       '"description": ' + "[" * depth + "]" * depth + "}",
        "objects.json": '{"format": "eoir-scenario", "version": 1, "name": "deep", "start": "2010-01-01", '
                        '"objects": [{"name": "S", "kind": "satellite", "properties": '
                        + '{"a": ' * depth + "1" + "}" * depth + "}]}",
    }
    with tempfile.TemporaryDirectory() as tmp:
        for name, text in cases.items():
            path = os.path.join(tmp, name)
            with open(path, "w") as f:
                f.write(text)
            r = subprocess.run([exe, "validate", path], capture_output=True, text=True, timeout=60)
            assert r.returncode == 2, f"{name}: exit {r.returncode} (a crash is negative): {r.stderr[-500:]}"
            assert "nested deeper than 64 arrays/objects" in r.stderr, r.stderr[-500:]
            print(f"{name}: refused: {r.stderr.strip()[:160]}")
    print("passed")


if __name__ == "__main__":
    main()
