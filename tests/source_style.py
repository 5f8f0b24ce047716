#!/usr/bin/env python3
"""The C++ sources keep .clang-format's 120 columns.

Usage: source_style.py REPOSITORY. Lists every longer line as file:line: columns and exits 1.
Columns are characters of the UTF-8 text (what clang-format counts; a tab counts as one, and the
tree has none). The tree is not reformatted wholesale (.clang-format says why): a long line is
wrapped by hand or with `clang-format -i --lines=N:N FILE`, which touches only that line.
"""
import os
import sys

LIMIT = 120
FOLDERS = ("src", "include", "tests", "bench", "study", "fuzz", os.path.join("python", "src"))
ENDINGS = (".cpp", ".h")


def sources(root):
    for folder in FOLDERS:
        for here, _, names in os.walk(os.path.join(root, folder)):
            for name in sorted(names):
                if name.endswith(ENDINGS):
                    yield os.path.join(here, name)


def long_lines(path):
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            columns = len(line.rstrip("\n"))
            if columns > LIMIT:
                yield number, columns


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: source_style.py REPOSITORY")
    root = sys.argv[1]
    files = list(sources(root))
    if len(files) < 100:  # a wrong folder would pass with nothing checked
        sys.exit(f"source_style.py: only {len(files)} C++ sources under {root}")
    found = [(os.path.relpath(path, root), number, columns)
             for path in files for number, columns in long_lines(path)]
    for path, number, columns in found:
        print(f"{path}:{number}: {columns} columns (at most {LIMIT})")
    print(f"{len(files)} sources, {len(found)} lines over {LIMIT} columns")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
