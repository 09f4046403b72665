#!/usr/bin/env python3
"""tools/check_folder_sizes.py on tiny trees written for each case: a folder of 21 source files
under app/, engine/ or tests/ is refused and named, 20 pass, data files and other trees do not
count."""

import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools",
                      "check_folder_sizes.py")


def check(paths):
    """Writes the (empty) files into a fresh folder and runs the script on it: (exit, output)."""
    with tempfile.TemporaryDirectory() as root:
        for path in paths:
            os.makedirs(os.path.join(root, os.path.dirname(path)), exist_ok=True)
            open(os.path.join(root, path), "w", encoding="utf-8").close()
        run = subprocess.run([sys.executable, SCRIPT, root], capture_output=True, text=True,
                             timeout=60)
        return run.returncode, run.stdout + run.stderr


def files(folder, count, suffix=".cpp"):
    return [f"{folder}/f{i}{suffix}" for i in range(count)]


class FolderSizes(unittest.TestCase):
    def test_twenty_one_source_files_are_too_many(self):
        code, out = check(files("tests/app", 11) + files("tests/app", 10, ".h"))
        self.assertEqual(code, 1, out)
        self.assertIn("tests/app/: 21 source files (more than 20)", out)

    def test_twenty_pass_and_subfolders_count_apart(self):
        code, out = check(files("app/gui/ui", 20) + files("app/gui/ui/panel", 20, ".h"))
        self.assertEqual(code, 0, out)
        self.assertIn("the largest with 20 source files", out)

    def test_scripts_count_and_data_does_not(self):
        code, out = check(files("engine/x", 18) + ["engine/x/a.py", "engine/x/b.sh"] +
                          files("engine/x", 30, ".json") + ["engine/x/CMakeLists.txt"])
        self.assertEqual(code, 0, out)
        code, out = check(files("engine/x", 18) + ["engine/x/a.py", "engine/x/b.sh", "engine/x/c.js"])
        self.assertEqual(code, 1, out)
        self.assertIn("engine/x/: 21 source files", out)

    def test_other_trees_are_not_checked(self):
        code, out = check(files("docs", 30) + files("tools", 25, ".py"))
        self.assertEqual(code, 0, out)

    def test_bad_usage(self):
        run = subprocess.run([sys.executable, SCRIPT, "/nonexistent/folder"], capture_output=True,
                             text=True, timeout=60)
        self.assertEqual(run.returncode, 2)
        self.assertIn("not a folder", run.stderr)


if __name__ == "__main__":
    unittest.main()
