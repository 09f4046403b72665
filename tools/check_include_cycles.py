#!/usr/bin/env python3
"""Fails (exit 1) when the project's own source files, or its folders, include each other in a circle.

    tools/check_include_cycles.py [ROOT]        # ROOT: the repository (default: this script's)

A unit is a source file together with its header: app_state.h and app_state.cpp in one folder are
one unit, so "a.cpp includes b.h and b.cpp includes a.h" is a cycle (a needs b needs a), as is a
header that includes itself through others. Only `#include "x.h"` lines are read (comments are
skipped; `#if` is not evaluated). The build puts whole folders on the include path and includes
headers by their bare name, so an include is resolved as the compiler would find it among the
project's files: first next to the including file, then by the one file anywhere in the tree with
that path ending. Two candidates are an error (exit 2: the build's include order would decide,
and so would a renamed folder), and so is an unreadable file. A name that is no project file
(a system or generated header) is not the project's and is skipped.

Folders are layers: under engine/ and app/ (LAYERED_ROOTS), no folder may include a file of a
folder that includes it back, directly or through others. A file's folder is the one it sits in
(engine/ and engine/methods/ are two folders), so engine/step.cpp including methods/methods.h and
methods/resolve.h including world.h is a folder cycle engine -> engine/methods -> engine, although
no two files include each other.

Prints each cycle as the chain of includes that closes it, one line per link with file and line;
a folder cycle as its folders and, per link, one include that makes it.
Exit codes: 0 no cycle, 1 a cycle (of files or of folders), 2 an ambiguous include or bad usage.
"""

import os
import re
import sys
from collections import deque

SOURCE_SUFFIXES = (".h", ".hpp", ".hh", ".inl", ".c", ".cc", ".cpp", ".cxx")
# Folders that hold no source of the project's own: version control, build trees, packages.
SKIPPED_FOLDER = re.compile(r"^(\.git|build.*|node_modules|__pycache__)$")
INCLUDE = re.compile(r'^[ \t]*#[ \t]*include[ \t]*"([^"]+)"', re.MULTILINE)
COMMENT = re.compile(r"//[^\n]*|/\*.*?\*/", re.DOTALL)
# The trees whose folders must be layers (a folder never includes one that includes it back).
LAYERED_ROOTS = ("engine", "app")


class Ambiguous(Exception):
    pass


def source_files(root):
    """Every source file under root, as paths relative to it with '/' separators, sorted."""
    found = []
    for folder, subfolders, names in os.walk(root):
        subfolders[:] = sorted(d for d in subfolders if not SKIPPED_FOLDER.match(d))
        for name in names:
            if name.endswith(SOURCE_SUFFIXES):
                found.append(os.path.relpath(os.path.join(folder, name), root).replace(os.sep, "/"))
    return sorted(found)


def unit_of(path):
    """'app/gui/state/app_state.cpp' -> 'app/gui/state/app_state': a file and its header."""
    return os.path.splitext(path)[0]


def includes_of(root, path):
    """(line number, included name) of each quoted #include of the file, comments left out."""
    with open(os.path.join(root, path), encoding="utf-8", errors="replace") as f:
        text = f.read()
    # Blank the comments but keep their newlines, so line numbers stay true.
    text = COMMENT.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)
    return [(text.count("\n", 0, m.start()) + 1, m.group(1)) for m in INCLUDE.finditer(text)]


def resolve(including, name, files, by_basename):
    """The project file an include names, or None when it is not the project's."""
    beside = os.path.normpath(os.path.join(os.path.dirname(including), name)).replace(os.sep, "/")
    if beside in files:
        return beside
    candidates = [p for p in by_basename.get(os.path.basename(name), [])
                  if p == name or p.endswith("/" + name)]
    if len(candidates) > 1:
        raise Ambiguous(f'{including}: #include "{name}" could be any of: ' + ", ".join(candidates)
                        + " (include it by a path that names one, or rename one)")
    return candidates[0] if candidates else None


def include_graph(root):
    """unit -> {included unit: (including file, line, included name)}: the first such include."""
    files = source_files(root)
    file_set = set(files)
    by_basename = {}
    for path in files:
        by_basename.setdefault(os.path.basename(path), []).append(path)
    graph = {unit_of(p): {} for p in files}
    for path in files:
        for line, name in includes_of(root, path):
            target = resolve(path, name, file_set, by_basename)
            if target is None or unit_of(target) == unit_of(path):
                continue
            graph[unit_of(path)].setdefault(unit_of(target), (path, line, name))
    return graph


def folder_of(unit):
    """'app/gui/ui/help' -> 'app/gui/ui'; a unit at the root is in '.'."""
    return os.path.dirname(unit) or "."


def layered(folder):
    return any(folder == root or folder.startswith(root + "/") for root in LAYERED_ROOTS)


def folder_graph(graph):
    """folder -> {included folder: (including file, line, included name)}, among LAYERED_ROOTS'
    folders: the first include (in path order) that makes each arrow."""
    folders = {}
    for unit in sorted(graph):
        source = folder_of(unit)
        if not layered(source):
            continue
        arrows = folders.setdefault(source, {})
        for target_unit in sorted(graph[unit]):
            target = folder_of(target_unit)
            if target == source or not layered(target):
                continue
            include = graph[unit][target_unit]
            if target not in arrows or include < arrows[target]:
                arrows[target] = include
    for arrows in list(folders.values()):
        for target in arrows:
            folders.setdefault(target, {})
    return folders


def strongly_connected(graph):
    """Tarjan's components of more than one unit (iterative: no recursion limit)."""
    index, low, on_stack, stack, components = {}, {}, set(), [], []
    counter = 0
    for start in sorted(graph):
        if start in index:
            continue
        work = [(start, iter(sorted(graph[start])))]
        index[start] = low[start] = counter
        counter += 1
        stack.append(start)
        on_stack.add(start)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = counter
                    counter += 1
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph[child]))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                parent = work[-1][0]
                low[parent] = min(low[parent], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                if len(component) > 1:
                    components.append(sorted(component))
    return sorted(components)


def shortest_cycle_through(graph, start, members):
    """The shortest chain of units start -> ... -> start inside one component (breadth first)."""
    came_from = {start: None}
    queue = deque([start])
    while queue:
        node = queue.popleft()
        for child in sorted(graph[node]):
            if child not in members:
                continue
            if child == start:
                chain = [node]
                while came_from[chain[-1]] is not None:
                    chain.append(came_from[chain[-1]])
                return list(reversed(chain)) + [start]
            if child not in came_from:
                came_from[child] = node
                queue.append(child)
    return None


def cycles(graph):
    """One shortest cycle through each unit of each component, each cycle listed once."""
    found, seen = [], set()
    for component in strongly_connected(graph):
        members = set(component)
        for unit in component:
            chain = shortest_cycle_through(graph, unit, members)
            rotation = min(range(len(chain) - 1), key=lambda i: chain[i])
            key = tuple(chain[rotation:-1] + chain[:rotation])
            if key not in seen:
                seen.add(key)
                found.append(list(key) + [key[0]])
    return found


def main(argv):
    if len(argv) > 2 or (len(argv) == 2 and argv[1].startswith("-")):
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    root = argv[1] if len(argv) == 2 else os.path.join(os.path.dirname(__file__), "..")
    if not os.path.isdir(root):
        print(f"check_include_cycles: {root}: not a folder", file=sys.stderr)
        return 2
    try:
        graph = include_graph(root)
    except (Ambiguous, OSError) as error:
        print(f"check_include_cycles: {error}", file=sys.stderr)
        return 2
    found = cycles(graph)
    for chain in found:
        print(f"include cycle: {' -> '.join(chain)}")
        for unit, next_unit in zip(chain, chain[1:]):
            path, line, name = graph[unit][next_unit]
            print(f'  {path}:{line}: #include "{name}"')
    folders = folder_graph(graph)
    found_folders = cycles(folders)
    for chain in found_folders:
        print(f"folder cycle: {' -> '.join(f + '/' for f in chain)}")
        for folder, next_folder in zip(chain, chain[1:]):
            path, line, name = folders[folder][next_folder]
            print(f'  {path}:{line}: #include "{name}"')
    if found:
        print(f"check_include_cycles: {len(found)} cycle(s) among the project's own files "
              "(a file and its header count as one): break each by moving what both need below "
              "both, or by passing in what one side needs", file=sys.stderr)
    if found_folders:
        print(f"check_include_cycles: {len(found_folders)} folder cycle(s) under "
              f"{', '.join(r + '/' for r in LAYERED_ROOTS)} (folders are layers: a folder never "
              "includes one that includes it back): move the file that runs back up into the "
              "folder below, or what both need below both", file=sys.stderr)
    if found or found_folders:
        return 1
    print(f"check_include_cycles: no cycle among {len(graph)} units nor among "
          f"{len(folders)} folders")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
