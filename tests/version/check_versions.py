"""The one version (issue 24 item 4): fails when any place that states the
version drifts from project(eoir VERSION X.Y.Z) in CMakeLists.txt.

Checked: the project() line itself (against the version CMake configured),
eoir.h (no literal version: it includes the generated eoir_version.h), the
generated eoir_version.h, the built library (file name libeoir.so.X.Y.Z,
soname libeoir.so.X, eoir_version() and eoir_version_string()), the Python
package (eoir/_version.py, pyproject.toml's dynamic version from it, and
eoir.__version__), `eoir --version` (every line) and CHANGELOG.md (its first
release is X.Y.Z, in Keep a Changelog's form).
"""

import argparse
import ctypes
import os
import re
import subprocess
import sys

ap = argparse.ArgumentParser()
for name in ("version", "source", "generated-header", "library", "soname", "cli"):
    ap.add_argument("--" + name, required=True)
a = ap.parse_args()
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def read(*parts):
    with open(os.path.join(*parts), encoding="utf-8") as f:
        return f.read()


v = a.version
major, minor, patch = (int(x) for x in v.split("."))

m = re.search(r"^project\(eoir VERSION ([0-9]+\.[0-9]+\.[0-9]+)", read(a.source, "CMakeLists.txt"), re.M)
check(m is not None and m.group(1) == v, f"CMakeLists.txt project(eoir VERSION {m and m.group(1)}) is {v}")

header = read(a.source, "capi", "include", "eoir", "eoir.h")
check(re.search(r"#\s*define\s+EOIR_VERSION_(MAJOR|MINOR|PATCH)", header) is None,
      "eoir.h states no version of its own")
check('#include "eoir_version.h"' in header, "eoir.h includes the generated eoir_version.h")
generated = dict(re.findall(r"#define (EOIR_VERSION_\w+) (\S+)", read(a.generated_header)))
check(generated == {"EOIR_VERSION_MAJOR": str(major), "EOIR_VERSION_MINOR": str(minor),
                    "EOIR_VERSION_PATCH": str(patch), "EOIR_VERSION_STRING": f'"{v}"'},
      f"eoir_version.h {generated}")

check(os.path.basename(os.path.realpath(a.library)) == f"libeoir.so.{v}",
      f"library file {os.path.basename(os.path.realpath(a.library))} is libeoir.so.{v}")
check(a.soname == f"libeoir.so.{major}", f"soname {a.soname} is libeoir.so.{major}")
lib = ctypes.CDLL(a.library)
lib.eoir_version.restype = ctypes.c_uint32
lib.eoir_version_string.restype = ctypes.c_char_p
check(lib.eoir_version() == major * 10000 + minor * 100 + patch, f"eoir_version() {lib.eoir_version()}")
check(lib.eoir_version_string().decode() == v, f"eoir_version_string() {lib.eoir_version_string().decode()}")

py = read(a.source, "bindings", "python", "eoir", "_version.py")
m = re.search(r'^__version__ = "([^"]+)"$', py, re.M)
check(m is not None and m.group(1) == v, f"bindings/python/eoir/_version.py {m and m.group(1)}")
pyproject = read(a.source, "bindings", "python", "pyproject.toml")
check(re.search(r'^dynamic = \["version"\]', pyproject, re.M) is not None and
      'version = {attr = "eoir._version.__version__"}' in pyproject and
      re.search(r"^version = \"", pyproject, re.M) is None,
      "pyproject.toml takes its version from eoir/_version.py")
out = subprocess.run([sys.executable, "-c", "import eoir; print(eoir.__version__, eoir.version_string())"],
                     env=dict(os.environ, EOIR_LIBRARY=a.library,
                              PYTHONPATH=os.path.join(a.source, "bindings", "python"), PYTHONDONTWRITEBYTECODE="1"),
                     capture_output=True, text=True)
check(out.returncode == 0 and out.stdout.split() == [v, v], f"eoir.__version__, eoir.version_string(): {out.stdout.strip()}"
      f"{out.stderr.strip()}")

out = subprocess.run([a.cli, "--library", a.library, "--version"], capture_output=True, text=True)
print(out.stdout, end="")
lines = out.stdout.splitlines()
expected = [f"eoir {v}", f"C ABI {major}.{minor} (this program's eoir.h {v})", f"soname libeoir.so.{major}",
            f"data {v} (built with the engine; no version of its own)",
            f"python package eoir {v} (bindings/python)"]
check(out.returncode == 0 and lines[:5] == expected, "eoir --version: program, C ABI, soname, data, Python package")
check(len(lines) == 6 and lines[5].startswith(f"engine {v} (") and f"libeoir.so.{major}" in lines[5],
      f"eoir --version: the engine loaded: {lines[5:]}")

conf = read(a.source, "docs", "conf.py")
check('re.search(r"^project\\(eoir VERSION ([0-9.]+)", cmake_lists.read(), re.M)' in conf and "version = release" in conf,
      "docs/conf.py takes the manual's release from project(eoir VERSION)")

changelog = read(a.source, "CHANGELOG.md")
check(changelog.startswith("# Changelog\n") and "https://keepachangelog.com/en/1.1.0/" in changelog
      and "## [Unreleased]" in changelog, "CHANGELOG.md: Keep a Changelog's header and Unreleased section")
releases = re.findall(r"^## \[([0-9]+\.[0-9]+\.[0-9]+)\] - [0-9]{4}-[0-9]{2}-[0-9]{2}$", changelog, re.M)
check(releases[:1] == [v], f"CHANGELOG.md's latest release {releases[:1]} is {v}")

if failures:
    print(f"check_versions: {len(failures)} place(s) drift from project(eoir VERSION {v}):", *failures, sep="\n  ")
    sys.exit(1)
print(f"check_versions: every place states {v}")
