"""Every relative link and image of the Markdown files given points to a file
of the source tree (test docs.readme_links; the manual's own links are checked
by its build, sphinx-build -W -n).

    /usr/bin/python3 docs/tools/check_links.py README.md [MORE.md ...]
"""
import os
import re
import sys

LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")


def main(paths):
    broken, count = [], 0
    for path in paths:
        base = os.path.dirname(os.path.abspath(path))
        for n, line in enumerate(open(path), 1):
            for target in LINK.findall(line):
                if re.match(r"^[a-z]+:", target) or target.startswith("#"):
                    continue
                count += 1
                if not os.path.exists(os.path.join(base, target.split("#")[0])):
                    broken.append(f"{path}:{n}: {target}")
    print(f"{count} relative links checked")
    for b in broken:
        print("broken:", b)
    return 1 if broken or count == 0 else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
