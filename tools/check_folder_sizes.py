#!/usr/bin/env python3
"""Fails (exit 1) when a folder under app/, engine/ or tests/ holds more than 20 source files.

    tools/check_folder_sizes.py [ROOT]        # ROOT: the repository (default: this script's)

A source file is code a reader opens to understand the folder: C and C++ (.c .cc .cpp .h .hpp
.inl), Python, JavaScript, shell scripts and CMake (.cmake). Data (scenes, images, corpora) and
CMakeLists.txt are not counted. Only a folder's own files count, not its subfolders': a folder
over the limit is split into rooms a newcomer would find (tests/app/lesson, app/gui/ui/panel).
Prints every folder over the limit with its count; exit codes: 0 none, 1 some, 2 bad usage.
"""

import os
import re
import sys

LIMIT = 20
CHECKED_ROOTS = ("app", "engine", "tests")
SOURCE_SUFFIXES = (".c", ".cc", ".cpp", ".cxx", ".h", ".hh", ".hpp", ".inl", ".py", ".js",
                   ".mjs", ".ts", ".sh", ".cmake")
SKIPPED_FOLDER = re.compile(r"^(\.git|build.*|node_modules|__pycache__)$")


def folder_sizes(root):
    """(folder relative to root, number of source files in it) for every folder checked."""
    sizes = []
    for top in CHECKED_ROOTS:
        for folder, subfolders, names in os.walk(os.path.join(root, top)):
            subfolders[:] = sorted(d for d in subfolders if not SKIPPED_FOLDER.match(d))
            count = sum(1 for name in names if name.endswith(SOURCE_SUFFIXES))
            sizes.append((os.path.relpath(folder, root).replace(os.sep, "/"), count))
    return sorted(sizes)


def main(argv):
    if len(argv) > 2 or (len(argv) == 2 and argv[1].startswith("-")):
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    root = argv[1] if len(argv) == 2 else os.path.join(os.path.dirname(__file__), "..")
    if not os.path.isdir(root):
        print(f"check_folder_sizes: {root}: not a folder", file=sys.stderr)
        return 2
    sizes = folder_sizes(root)
    over = [(folder, count) for folder, count in sizes if count > LIMIT]
    for folder, count in over:
        print(f"{folder}/: {count} source files (more than {LIMIT})")
    if over:
        print(f"check_folder_sizes: {len(over)} folder(s) over {LIMIT} source files: split each "
              "into rooms a newcomer would find", file=sys.stderr)
        return 1
    largest = max((count for _, count in sizes), default=0)
    print(f"check_folder_sizes: {len(sizes)} folders under {', '.join(CHECKED_ROOTS)}, "
          f"the largest with {largest} source files (limit {LIMIT})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
