"""What the tests of tools/check_*.py share: a tool run on a tiny tree written for one case, and
the tool's refusal of a folder that does not exist."""

import os
import subprocess
import sys
import tempfile

TOOLS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools")


def run_on_tree(script, files):
    """Writes {path: text} into a fresh folder and runs tools/`script` on it: (exit, output)."""
    with tempfile.TemporaryDirectory() as root:
        for path, text in files.items():
            os.makedirs(os.path.join(root, os.path.dirname(path)), exist_ok=True)
            with open(os.path.join(root, path), "w", encoding="utf-8") as f:
                f.write(text)
        run = subprocess.run([sys.executable, os.path.join(TOOLS, script), root],
                             capture_output=True, text=True, timeout=60)
        return run.returncode, run.stdout + run.stderr


def check_refuses_a_missing_folder(test, script):
    """tools/`script` on a folder that does not exist: exit 2, "not a folder"."""
    run = subprocess.run([sys.executable, os.path.join(TOOLS, script), "/nonexistent/folder"],
                         capture_output=True, text=True, timeout=60)
    test.assertEqual(run.returncode, 2)
    test.assertIn("not a folder", run.stderr)
