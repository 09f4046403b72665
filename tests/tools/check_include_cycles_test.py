#!/usr/bin/env python3
"""tools/check_include_cycles.py on tiny trees written for each case: a cycle is found and printed
with the includes that close it, a folder cycle under engine/ or app/ too, a tree without one
passes, an ambiguous include is refused."""

import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from tree_check import check_refuses_a_missing_folder, run_on_tree  # noqa: E402


def check(files):
    """The script on a fresh folder holding {path: text}: (exit code, output)."""
    return run_on_tree("check_include_cycles.py", files)


class IncludeCycles(unittest.TestCase):
    def expect(self, files, code, *lines):
        """The script on the tree `files` exits with `code` and prints each of `lines`."""
        status, out = check(files)
        self.assertEqual(status, code, out)
        for line in lines:
            self.assertIn(line, out)
        return out

    def test_a_cpp_and_its_header_are_one_unit(self):
        # a.cpp needs b, b.cpp needs a: no header includes another, still a cycle.
        self.expect({
            "src/a.h": "#pragma once\nint a();\n",
            "src/a.cpp": '#include "a.h"\n\n#include "b.h"\nint a() { return b(); }\n',
            "lib/b.h": "#pragma once\nint b();\n",
            "lib/b.cpp": '#include "b.h"\n#include "a.h"\nint b() { return a(); }\n',
        }, 1, "include cycle: lib/b -> src/a -> lib/b", 'src/a.cpp:3: #include "b.h"',
            'lib/b.cpp:2: #include "a.h"')

    def test_headers_in_a_ring_of_three(self):
        self.expect({
            "x.h": '#include "y.h"\n',
            "y.h": '#include "z.h"\n',
            "z.h": '// the ring closes here\n#include "x.h"\n',
        }, 1, "include cycle: x -> y -> z -> x", 'z.h:2: #include "x.h"')

    def test_two_cycles_through_one_unit_are_both_printed(self):
        self.expect({
            "app.h": '#include "lesson.h"\n#include "mouse.h"\n',
            "lesson.h": "#pragma once\n",
            "mouse.h": "#pragma once\n",
            "lesson.cpp": '#include "app.h"\n',
            "mouse.cpp": '#include "app.h"\n',
        }, 1, "include cycle: app -> lesson -> app", "include cycle: app -> mouse -> app")

    def test_a_tree_without_a_cycle_passes(self):
        self.expect({
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
        }, 0, "no cycle among")

    def test_folders_that_include_each_other_are_a_cycle(self):
        # No two files include each other, yet engine/ needs engine/methods/ (step.cpp) and
        # engine/methods/ needs engine/ (resolve.h): the folders are not layers.
        out = self.expect({
            "engine/world.h": "#pragma once\n",
            "engine/step.cpp": '#include "world.h"\n#include "methods.h"\n',
            "engine/methods/methods.h": '#pragma once\n#include "resolve.h"\n',
            "engine/methods/resolve.h": '#pragma once\n\n#include "world.h"\n',
        }, 1)
        self.assertNotIn("include cycle:", out)
        self.assertIn("folder cycle: engine/ -> engine/methods/ -> engine/", out)
        self.assertIn('engine/step.cpp:2: #include "methods.h"', out)
        self.assertIn('engine/methods/resolve.h:3: #include "world.h"', out)
        self.assertIn("1 folder cycle(s)", out)

    def test_a_folder_cycle_through_three_folders_under_app(self):
        self.expect({
            "app/gui/app/app.h": '#pragma once\n#include "csv_export.h"\n',
            "app/gui/explain/csv_export.h": '#pragma once\n#include "table.h"\n',
            "app/analysis/table.h": "#pragma once\n",
            "app/analysis/table.cpp": '#include "table.h"\n#include "app.h"\n',
        }, 1, "folder cycle: app/analysis/ -> app/gui/app/ -> app/gui/explain/ -> app/analysis/",
            'app/analysis/table.cpp:2: #include "app.h"')

    def test_folders_outside_engine_and_app_may_include_each_other(self):
        # Tests and tools are not layers: a test folder may share a fixture both ways.
        self.expect({
            "tests/a/fixture.h": '#pragma once\n#include "helper.h"\n',
            "tests/b/helper.h": "#pragma once\n",
            "tests/b/b_test.cpp": '#include "fixture.h"\n',
        }, 0, "no cycle among")

    def test_the_file_beside_the_including_one_wins(self):
        # As the preprocessor does for "x.h": the including file's folder first, so two util.h
        # in two folders are not ambiguous to a file next to one of them.
        self.expect({
            "a/util.h": "#pragma once\n",
            "a/a.cpp": '#include "util.h"\n',
            "b/util.h": "#pragma once\n",
            "b/b.cpp": '#include "util.h"\n',
        }, 0)

    def test_an_ambiguous_include_is_refused_naming_the_candidates(self):
        self.expect({
            "a/util.h": "#pragma once\n",
            "b/util.h": "#pragma once\n",
            "c/c.cpp": '#include "util.h"\n',
        }, 2, 'c/c.cpp: #include "util.h" could be any of: a/util.h, b/util.h')

    def test_a_path_in_the_include_picks_one_of_two(self):
        # c.h names a/util.h; taking b/util.h instead would make the cycle b/util -> c -> b/util.
        self.expect({
            "a/util.h": "#pragma once\n",
            "b/util.h": '#include "c.h"\n',
            "c/c.h": '#include "a/util.h"\n',
        }, 0)

    def test_bad_usage(self):
        code, out = check({})
        self.assertEqual(code, 0, out)  # an empty tree has no cycle
        check_refuses_a_missing_folder(self, "check_include_cycles.py")


if __name__ == "__main__":
    unittest.main()
