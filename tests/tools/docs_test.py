#!/usr/bin/env python3
"""The repository stands alone and its docs point at what exists:
- no tracked file refers to anything outside the repository (the old specification file, a
  sibling folder of the checkout);
- every relative link in README.md and docs/*.md, and every path of the repository written in
  backticks there (`engine/world/world.cpp`, `app/gui/*/`, `docs/tradeoff.{csv,md,png}`), names a file or
  folder that exists, so a moved file cannot leave the docs pointing at nothing."""

import glob
import os
import re
import subprocess
import sys
import unittest

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
# Top-level folders whose paths the docs name (build/ and build-web/ are made, not tracked).
TRACKED_TOPS = ("engine", "app", "tests", "tools", "scripts", "docs", "lessons", "shaders", "cmake",
                ".ci")
# Written in pieces, so that this file does not match itself.
OUTSIDE = ["SPEC" + ".md", ".." + "/shared"]


def tracked_files():
    try:
        listed = subprocess.run(["git", "-C", ROOT, "ls-files", "-z"], capture_output=True,
                                check=True, timeout=60).stdout.decode("utf-8", "replace")
        return [p for p in listed.split("\0") if p]
    except (OSError, subprocess.CalledProcessError):  # not a git checkout: every file
        return [os.path.relpath(os.path.join(d, n), ROOT) for d, _, names in os.walk(ROOT)
                if "/.git" not in d and "/build" not in d for n in names]


def doc_files():
    return [os.path.join(ROOT, "README.md")] + sorted(glob.glob(os.path.join(ROOT, "docs", "*.md")))


def expand_braces(path):
    """docs/tradeoff.{csv,md} -> docs/tradeoff.csv, docs/tradeoff.md"""
    m = re.match(r"(.*?)\{([^}]*)\}(.*)", path)
    if not m:
        return [path]
    return [p for alt in m.group(2).split(",") for p in expand_braces(m.group(1) + alt + m.group(3))]


def is_placeholder(path):
    """lessons/NAME.json, DIR/step_01.png: a segment in capitals stands for any name."""
    return any(re.fullmatch(r"[A-Z][A-Z_]*(\.\w+)?", part) for part in path.split("/"))


class Docs(unittest.TestCase):
    def test_no_file_refers_outside_the_repository(self):
        found = []
        for path in tracked_files():
            full = os.path.join(ROOT, path)
            if not os.path.isfile(full) or os.path.getsize(full) > 4 << 20:
                continue
            with open(full, "rb") as f:
                text = f.read().decode("utf-8", "replace")
            for number, line in enumerate(text.splitlines(), 1):
                if any(word in line for word in OUTSIDE):
                    found.append(f"{path}:{number}: {line.strip()[:120]}")
        self.assertEqual(found, [], "files that refer to something outside the repository "
                         "(the contract is in docs/):\n" + "\n".join(found))

    def test_paths_in_the_docs_exist(self):
        missing = []
        for doc in doc_files():
            with open(doc, encoding="utf-8") as f:
                text = f.read()
            name = os.path.relpath(doc, ROOT)
            for number, line in enumerate(text.splitlines(), 1):
                for m in re.finditer(r"\]\(([^)#\s]+)(#[^)]*)?\)", line):
                    target = m.group(1)
                    if re.match(r"[a-z]+:", target):  # https:, mailto:
                        continue
                    if not os.path.exists(os.path.join(os.path.dirname(doc), target)):
                        missing.append(f"{name}:{number}: link to {target}")
                for m in re.finditer(r"`([^`\s]+)`", line):
                    path = re.sub(r"[:,;.)]+$", "", m.group(1)).split(":")[0]
                    if "/" not in path or path.split("/")[0] not in TRACKED_TOPS:
                        continue
                    if is_placeholder(path):
                        continue
                    for candidate in expand_braces(path):
                        if not glob.glob(os.path.join(ROOT, candidate)):
                            missing.append(f"{name}:{number}: `{candidate}`")
        self.assertEqual(missing, [], "paths in the docs that do not exist (moved or renamed? "
                         "update the docs):\n" + "\n".join(missing))


if __name__ == "__main__":
    unittest.main()
