#!/usr/bin/env python3
"""The outside hostile-input suite of issue 28: written from the issue's classes and the public
contract (README, docs/cli.md, docs/scene-format.md, docs/lesson-format.md, the programs' --help),
not from the project's own tests.

    tests/robustness/hostile_outside.py BUILD_DIR CLASS

CLASS is one of: lessons, settings, writes, memory, energy, echoes (the cases are in
hostile_CLASS.py).
Every case runs its program under
`timeout` (a hang fails the case) with an address-space limit (ulimit -v: a blow-up fails the
case, not the machine) and no core files, and checks what the contract promises: the exit code,
an error that names its place, no crash signal, no raw control bytes on stderr (or stdout where
the program echoes outside text), no NaN in results, and files that were there intact byte for
byte. The window's settings cases need an X server: run the class under xvfb-run.
The last line printed is `CLASS: N cases, F failed`; the exit code is 1 when a case failed.
"""
import json
import os
import re
import resource
import shutil
import signal
import stat
import subprocess
import sys
import tempfile

HANG = 124  # timeout(1)'s exit code when it had to stop the program
NOBODY = 65534


class Result:
    def __init__(self, code, out, err, maxrss_kb):
        self.code, self.out, self.err, self.maxrss_kb = code, out, err, maxrss_kb

    def text(self):
        return "exit %s\n--- stdout ---\n%s\n--- stderr ---\n%s" % (
            self.code, self.out[:1500].decode("utf-8", "replace"),
            self.err[:1500].decode("utf-8", "replace"))


def run(args, cwd, timeout=30, mem_mb=1536, env=None, stdin_path=None, fsize=None,
        as_nobody=False):
    """Runs args under timeout(1) with the limits; returns its exit code (negative: a signal),
    stdout, stderr (the first 64 MB of each) and the largest resident set of the process tree."""

    def limits():
        resource.setrlimit(resource.RLIMIT_AS, (mem_mb << 20, mem_mb << 20))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        if fsize is not None:  # a "full disk" for regular files: writes beyond fsize fail
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
            resource.setrlimit(resource.RLIMIT_FSIZE, (fsize, fsize))
        if as_nobody:
            os.setgroups([])
            os.setgid(NOBODY)
            os.setuid(NOBODY)

    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        stdin = open(stdin_path, "rb") if stdin_path else subprocess.DEVNULL
        proc = subprocess.Popen(["timeout", "-k", "5", str(timeout)] + [str(a) for a in args],
                                cwd=cwd, env=env, stdin=stdin, stdout=out, stderr=err,
                                preexec_fn=limits)
        _, status, usage = os.wait4(proc.pid, 0)
        proc.returncode = os.waitstatus_to_exitcode(status)
        if stdin_path:
            stdin.close()
        out.seek(0)
        err.seek(0)
        code = proc.returncode
        if code >= 128 and code != HANG:  # timeout re-reports a signal as 128 + N
            code = -(code - 128)
        return Result(code, out.read(64 << 20), err.read(64 << 20), usage.ru_maxrss)


RAW_CONTROL = re.compile(rb"[\x00-\x08\x0b-\x1f\x7f]|\xc2[\x80-\x9f]")
NAN = re.compile(rb"(?i)(?<![a-z_])-?(nan|inf|infinity)(?![a-z_])")


class Suite:
    def __init__(self, build, name):
        self.build = os.path.abspath(build)
        self.cli = os.path.join(self.build, "app/cli/sandbox-cli")
        self.offscreen = os.path.join(self.build, "app/gui/sandbox-offscreen")
        self.window = os.path.join(self.build, "app/gui/sandbox")
        self.source = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
        self.name = name
        self.cases = 0
        self.failures = []
        self.root = tempfile.mkdtemp(prefix="hostile_%s_" % name)
        os.chmod(self.root, 0o755)

    def folder(self, case):
        path = os.path.join(self.root, re.sub(r"[^A-Za-z0-9_.-]", "_", case))
        os.makedirs(path, exist_ok=True)
        return path

    def check(self, case, problems, result=None):
        """Counts one case; problems: the list of what did not hold."""
        self.cases += 1
        if problems:
            detail = "\n  ".join(problems)
            if result is not None:
                detail += "\n" + result.text()
            self.failures.append("%s: %s" % (case, detail))
            print("FAIL %s: %s" % (case, detail), flush=True)
        else:
            print("ok   %s" % case, flush=True)

    def common(self, result, echo_stdout=False):
        """What holds for every run, good input or bad: no signal, no hang, no raw control bytes
        in what the program prints about outside text."""
        problems = []
        if result.code == HANG:
            problems.append("hung (stopped by timeout)")
        elif result.code < 0:
            problems.append("killed by signal %d" % -result.code)
        if RAW_CONTROL.search(result.err):
            problems.append("raw control bytes on stderr: %r" %
                            RAW_CONTROL.search(result.err).group(0))
        if echo_stdout and RAW_CONTROL.search(result.out):
            problems.append("raw control bytes on stdout: %r" %
                            RAW_CONTROL.search(result.out).group(0))
        return problems

    def refused(self, result, places, code=None, echo_stdout=False, max_err=64 << 10):
        """Bad input: a non-zero exit (code, when given), every place in places on stderr."""
        problems = self.common(result, echo_stdout)
        if result.code == 0:
            problems.append("exit 0 on bad input")
        elif code is not None and result.code != code and result.code > 0:
            problems.append("exit %d, expected %d" % (result.code, code))
        for place in places:
            if isinstance(place, re.Pattern):
                if not place.search(result.err.decode("utf-8", "replace")):
                    problems.append("stderr does not match %r" % place.pattern)
            elif place.encode() not in result.err:
                problems.append("stderr does not name %r" % place)
        if len(result.err) > max_err:
            problems.append("stderr is %d bytes (an echo not cut)" % len(result.err))
        return problems

    def accepted(self, result, echo_stdout=False):
        problems = self.common(result, echo_stdout)
        if result.code != 0:
            problems.append("exit %d on good input" % result.code)
        if NAN.search(result.out):
            problems.append("NaN or inf in stdout: %r" % NAN.search(result.out).group(0))
        return problems

    def finish(self):
        print("%s: %d cases, %d failed" % (self.name, self.cases, len(self.failures)))
        if not self.failures:
            shutil.rmtree(self.root, ignore_errors=True)
        else:
            print("files kept in " + self.root)
        return 1 if self.failures else 0


def write(path, data):
    with open(path, "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def read(path):
    with open(path, "rb") as f:
        return f.read()


def snapshot(folder):
    """Every entry under folder (not following links) with its kind and, for files, bytes."""
    entries = {}
    for base, dirs, files in os.walk(folder):
        for name in dirs + files:
            path = os.path.join(base, name)
            st = os.lstat(path)
            if stat.S_ISREG(st.st_mode):
                entries[path] = ("file", read(path))
            elif stat.S_ISLNK(st.st_mode):
                entries[path] = ("link", os.readlink(path))
            else:
                entries[path] = (stat.S_IFMT(st.st_mode), b"")
    return entries


def changed(before, after):
    return sorted(p for p in set(before) | set(after) if before.get(p) != after.get(p))


if __name__ == "__main__":
    import importlib

    CLASSES = ("lessons", "settings", "writes", "memory", "energy", "echoes")
    if len(sys.argv) != 3 or sys.argv[2] not in CLASSES:
        sys.exit("usage: hostile_outside.py BUILD_DIR CLASS (one of %s)" % ", ".join(CLASSES))
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    suite = Suite(sys.argv[1], sys.argv[2])
    importlib.import_module("hostile_" + sys.argv[2]).run_cases(suite)
    sys.exit(suite.finish())
