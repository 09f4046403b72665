#!/usr/bin/env python3
"""tools/check_include_cycles.py on tiny trees written for each case: a cycle is found and printed
with the includes that close it, a folder cycle under engine/ or app/ too, a tree without one
passes, an ambiguous include is refused."""

import os
import subprocess
import sys
import tempfile
import unittest

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools",
                      "check_include_cycles.py")


def check(files):
    """Writes {path: text} into a fresh folder and runs the script on it: (exit code, output)."""
    with tempfile.TemporaryDirectory() as root:
        for path, text in files.items():
            os.makedirs(os.path.join(root, os.path.dirname(path)), exist_ok=True)
            with open(os.path.join(root, path), "w", encoding="utf-8") as f:
                f.write(text)
        run = subprocess.run([sys.executable, SCRIPT, root], capture_output=True, text=True,
                             timeout=60)
        return run.returncode, run.stdout + run.stderr


class IncludeCycles(unittest.TestCase):
    def test_a_cpp_and_its_header_are_one_unit(self):
        # a.cpp needs b, b.cpp needs a: no header includes another, still a cycle.
        code, out = check({
            "src/a.h": "#pragma once\nint a();\n",
            "src/a.cpp": '#include "a.h"\n\n#include "b.h"\nint a() { return b(); }\n',
            "lib/b.h": "#pragma once\nint b();\n",
            "lib/b.cpp": '#include "b.h"\n#include "a.h"\nint b() { return a(); }\n',
        })
        self.assertEqual(code, 1, out)
        self.assertIn("include cycle: lib/b -> src/a -> lib/b", out)
        self.assertIn('src/a.cpp:3: #include "b.h"', out)
        self.assertIn('lib/b.cpp:2: #include "a.h"', out)

    def test_headers_in_a_ring_of_three(self):
        code, out = check({
            "x.h": '#include "y.h"\n',
            "y.h": '#include "z.h"\n',
            "z.h": '// the ring closes here\n#include "x.h"\n',
        })
        self.assertEqual(code, 1, out)
        self.assertIn("include cycle: x -> y -> z -> x", out)
        self.assertIn('z.h:2: #include "x.h"', out)

    def test_two_cycles_through_one_unit_are_both_printed(self):
        code, out = check({
            "app.h": '#include "lesson.h"\n#include "mouse.h"\n',
            "lesson.h": "#pragma once\n",
            "mouse.h": "#pragma once\n",
            "lesson.cpp": '#include "app.h"\n',
            "mouse.cpp": '#include "app.h"\n',
        })
        self.assertEqual(code, 1, out)
        self.assertIn("include cycle: app -> lesson -> app", out)
        self.assertIn("include cycle: app -> mouse -> app", out)

    def test_a_tree_without_a_cycle_passes(self):
        code, out = check({
            "engine/world/world.h": '#pragma once\n#include "vec2.h"\n#include <vector>\n',
            "engine/world/world.cpp": '#include "world.h"\n',
            "engine/world/vec2.h": "#pragma once\n",
            "engine/step/step.cpp": '#include "world.h"\n#include "methods.h"\n',
            "engine/methods/methods.h": '#include "world.h"\n',
            "engine/methods/perfect.cpp": '#include "methods.h"\n',
            # Not the project's: a system or generated header, and a commented-out include.
            "app/main.cpp": '#include "imgui.h"\n#include "world.h"\n'
                            '// #include "main_loop.h"\n/* #include "step.h"\n*/\n',
            "app/main_loop.h": '#include "main.h"\n',
            "app/main.h": "#pragma once\n",
            "build/generated/world.h": '#include "main.h"\n',  # a build tree is not read
        })
        self.assertEqual(code, 0, out)
        self.assertIn("no cycle among", out)

    def test_folders_that_include_each_other_are_a_cycle(self):
        # No two files include each other, yet engine/ needs engine/methods/ (step.cpp) and
        # engine/methods/ needs engine/ (resolve.h): the folders are not layers.
        code, out = check({
            "engine/world.h": "#pragma once\n",
            "engine/step.cpp": '#include "world.h"\n#include "methods.h"\n',
            "engine/methods/methods.h": '#pragma once\n#include "resolve.h"\n',
            "engine/methods/resolve.h": '#pragma once\n\n#include "world.h"\n',
        })
        self.assertEqual(code, 1, out)
        self.assertNotIn("include cycle:", out)
        self.assertIn("folder cycle: engine/ -> engine/methods/ -> engine/", out)
        self.assertIn('engine/step.cpp:2: #include "methods.h"', out)
        self.assertIn('engine/methods/resolve.h:3: #include "world.h"', out)
        self.assertIn("1 folder cycle(s)", out)

    def test_a_folder_cycle_through_three_folders_under_app(self):
        code, out = check({
            "app/gui/app/app.h": '#pragma once\n#include "csv_export.h"\n',
            "app/gui/explain/csv_export.h": '#pragma once\n#include "table.h"\n',
            "app/analysis/table.h": "#pragma once\n",
            "app/analysis/table.cpp": '#include "table.h"\n#include "app.h"\n',
        })
        self.assertEqual(code, 1, out)
        self.assertIn("folder cycle: app/analysis/ -> app/gui/app/ -> app/gui/explain/ -> "
                      "app/analysis/", out)
        self.assertIn('app/analysis/table.cpp:2: #include "app.h"', out)

    def test_folders_outside_engine_and_app_may_include_each_other(self):
        # Tests and tools are not layers: a test folder may share a fixture both ways.
        code, out = check({
            "tests/a/fixture.h": '#pragma once\n#include "helper.h"\n',
            "tests/b/helper.h": "#pragma once\n",
            "tests/b/b_test.cpp": '#include "fixture.h"\n',
        })
        self.assertEqual(code, 0, out)
        self.assertIn("no cycle among", out)

    def test_the_file_beside_the_including_one_wins(self):
        # As the preprocessor does for "x.h": the including file's folder first, so two util.h
        # in two folders are not ambiguous to a file next to one of them.
        code, out = check({
            "a/util.h": "#pragma once\n",
            "a/a.cpp": '#include "util.h"\n',
            "b/util.h": "#pragma once\n",
            "b/b.cpp": '#include "util.h"\n',
        })
        self.assertEqual(code, 0, out)

    def test_an_ambiguous_include_is_refused_naming_the_candidates(self):
        code, out = check({
            "a/util.h": "#pragma once\n",
            "b/util.h": "#pragma once\n",
            "c/c.cpp": '#include "util.h"\n',
        })
        self.assertEqual(code, 2, out)
        self.assertIn('c/c.cpp: #include "util.h" could be any of: a/util.h, b/util.h', out)

    def test_a_path_in_the_include_picks_one_of_two(self):
        # c.h names a/util.h; taking b/util.h instead would make the cycle b/util -> c -> b/util.
        code, out = check({
            "a/util.h": "#pragma once\n",
            "b/util.h": '#include "c.h"\n',
            "c/c.h": '#include "a/util.h"\n',
        })
        self.assertEqual(code, 0, out)

    def test_bad_usage(self):
        code, out = check({})
        self.assertEqual(code, 0, out)  # an empty tree has no cycle
        run = subprocess.run([sys.executable, SCRIPT, "/nonexistent/folder"], capture_output=True,
                             text=True, timeout=60)
        self.assertEqual(run.returncode, 2)
        self.assertIn("not a folder", run.stderr)


if __name__ == "__main__":
    unittest.main()
