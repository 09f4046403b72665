#!/usr/bin/env python3
"""tools/check_folder_sizes.py on tiny trees written for each case: a folder of 21 source files
under app/, engine/ or tests/ is refused and named, 20 pass, data files and other trees do not
count."""

import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from tree_check import check_refuses_a_missing_folder, run_on_tree  # noqa: E402


def check(paths):
    """The script on a fresh folder holding these (empty) files: (exit code, output)."""
    return run_on_tree("check_folder_sizes.py", {path: "" for path in paths})


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
        check_refuses_a_missing_folder(self, "check_folder_sizes.py")


if __name__ == "__main__":
    unittest.main()
