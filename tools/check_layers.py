#!/usr/bin/env python3
"""The include layering of src/ and include/ (`make layers`, run by `make test`).

Every folder is a level of its own (LEVELS, lowest first). A file may include
(#include "...") only files of its own folder or of a lower level, and a
folder listed in ONLY only the folders named there. Fails on:
  - an include that goes the wrong way (to a higher level, or outside ONLY);
  - a folder cycle: folders that include each other, even through others;
  - a file cycle (A includes B ... includes A), even within one folder;
  - a file of src/ or include/ in no level (give its folder one here);
  - an entry of KNOWN that is no longer true (the violation is gone: remove
    the entry, so that the table stays true).
A violation listed in KNOWN is printed on every run ("known: ...") and does
not fail the check; neither do the folder cycles it closes, which are
printed with it. A new violation fails it.

Includes with <...> and includes that resolve to no file are ignored. An
include resolves as the compiler looks: beside the including file, then in
src/ (-Isrc), then in include/ (-Iinclude).

Usage: tools/check_layers.py [SRC_DIR] [--known FILE]
  SRC_DIR   default: the src/ beside tools/; include/ beside it is checked too
  --known   the known violations from FILE instead of KNOWN, one a line:
            "FROM -> TO: why" (paths as printed, '#' starts a comment)
Exit status 0 when clean, 1 with one line per problem on stderr, 2 on bad usage.
"""

import os
import re
import sys

# Folders, lowest level first; a file's folder is its directory, relative to
# the tree's root (src/ and include/ side by side). To add a folder, add a
# line at the level where it belongs: everything it includes must be below.
LEVELS = [
    ("include/physics", "the public API: standard headers only"),
    ("src/course/utils", "Vector, Rect: the course's value types"),
    ("src/engine", "the engine: ECS, component storage, broad phase, contact law, solvers, queries"),
    ("src/course/systems", "the course's systems: Draw, Forces, Move, Collision"),
    ("src/course/entities", "the course's entities: Block"),
    ("src/course", "the course's root files: game, component_defs, system_defs, ecs"),
    ("src/api", "the public API's implementation"),
    ("src/reference", "the exact event-driven reference"),
    ("src/scene", "scene spec, JSON, built-in scenes, save"),
    ("src/input", "key codes"),
    ("src/games", "the games' rules: interface, each game, registry"),
    ("src/app", "command line, testbed, window, styles, headless, input logs, main"),
]

# Folders that may include fewer folders than their level allows: only their
# own and these (issue 21: a game uses the engine's World, later the public
# API, the scene module and the keys).
ONLY = {
    "src/games": {"include/physics", "src/scene", "src/input"},
}

# The violations that remain, each with what would remove it. Every run
# prints them; the check fails when one is no longer true, so remove it then.
KNOWN = [
]

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
SOURCE_EXT = (".hpp", ".cpp", ".h", ".cc", ".hh", ".ipp", ".tpp")
LEVEL = {folder: rank for rank, (folder, _) in enumerate(LEVELS)}


def short(folder):
    """A folder as messages name it: src/engine -> engine, include/physics stays."""
    return folder[4:] if folder.startswith("src/") else folder


def scan(root):
    """Files of src/ and include/ under root, named relative to it, with '/' separators."""
    files = []
    for top in ("src", "include"):
        for base, _, names in os.walk(os.path.join(root, top)):
            files += [os.path.relpath(os.path.join(base, n), root).replace(os.sep, "/")
                      for n in names if n.endswith(SOURCE_EXT)]
    return sorted(files)


def includes(root, files):
    """file -> [(included file, line number, as written)]."""
    known = set(files)
    graph = {f: [] for f in files}
    for f in files:
        with open(os.path.join(root, f), encoding="utf-8", errors="replace") as text:
            for number, line in enumerate(text, 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                for base in (os.path.dirname(f), "src", "include"):
                    target = os.path.normpath(os.path.join(base, m.group(1))).replace(os.sep, "/")
                    if target in known:
                        graph[f].append((target, number, m.group(1)))
                        break
    return graph


def folder(f):
    return os.path.dirname(f)


def wrong_way(f, target):
    """Why the include f -> target goes the wrong way, or None."""
    a, b = folder(f), folder(target)
    if a == b or a not in LEVEL or b not in LEVEL:
        return None
    if a in ONLY and b not in ONLY[a]:
        return f"{short(a)} may include only {', '.join(sorted(short(x) for x in ONLY[a]))}"
    if LEVEL[b] > LEVEL[a]:
        return (f"{short(a)} is level {LEVEL[a]}, {short(b)} is level {LEVEL[b]}; "
                f"a folder may include only its own level or lower")
    return None


def read_known(path):
    """[(from, to, why)] from a file of lines "FROM -> TO: why"."""
    entries = []
    with open(path, encoding="utf-8") as text:
        for line in text:
            line = line.split("#", 1)[0].strip()
            m = re.fullmatch(r"(\S+)\s*->\s*([^\s:]+)\s*:?\s*(.*)", line)
            if m:
                entries.append(m.groups())
    return entries


def cycles_of_files(graph):
    """Each include cycle once, as a list of files from the first found on it."""
    WHITE, GREY, BLACK = 0, 1, 2
    colour = dict.fromkeys(graph, WHITE)
    seen, found = set(), []
    for start in graph:
        if colour[start] != WHITE:
            continue
        stack, path = [(start, iter(graph[start]))], [start]
        colour[start] = GREY
        while stack:
            node, edges = stack[-1]
            step = next(edges, None)
            if step is None:
                colour[node] = BLACK
                stack.pop()
                path.pop()
                continue
            target = step[0]
            if colour[target] == GREY:
                cycle = path[path.index(target):]
                if frozenset(cycle) not in seen:
                    seen.add(frozenset(cycle))
                    found.append(cycle + [target])
            elif colour[target] == WHITE:
                colour[target] = GREY
                path.append(target)
                stack.append((target, iter(graph[target])))
    return found


def folder_cycles(edges):
    """The folder cycles of edges {(folder a, folder b): example}: one cycle per
    group of folders that reach each other, as a list of folders a -> ... -> a."""
    nexts = {}
    for a, b in sorted(edges):
        nexts.setdefault(a, []).append(b)

    def reach(start):
        seen, todo = {start}, [start]
        while todo:
            for b in nexts.get(todo.pop(), []):
                if b not in seen:
                    seen.add(b)
                    todo.append(b)
        return seen

    reaches = {a: reach(a) for a in nexts}
    done, found = set(), []
    for a in sorted(nexts):
        group = {b for b in reaches[a] if b != a and a in reaches.get(b, ())}
        if not group or a in done:
            continue
        done |= group | {a}
        found.append(shortest_cycle(a, nexts))
    return found


def shortest_cycle(a, nexts):
    """A shortest path a -> ... -> a (breadth first; a is on a cycle)."""
    parent, todo = {a: None}, [a]
    for node in todo:  # todo grows as the search goes
        for b in nexts.get(node, []):
            if b == a:
                path = [node]
                while parent[path[-1]] is not None:
                    path.append(parent[path[-1]])
                return path[::-1] + [a]
            if b not in parent:
                parent[b] = node
                todo.append(b)
    return [a]


def describe_cycle(cycle, edges):
    steps = " -> ".join(short(x) for x in cycle)
    why = "; ".join(edges[(a, b)] for a, b in zip(cycle, cycle[1:]))
    return f"folder cycle: {steps} ({why})"


def check(root, shown, known):
    files = scan(root)
    graph = includes(root, files)
    problems, notes = [], []
    for f in files:
        if folder(f) not in LEVEL:
            problems.append(f"{shown(f)}: has no level: its folder {folder(f)}/ is not in LEVELS "
                            f"(tools/check_layers.py)")

    known_edges = {(a, b): why for a, b, why in known}
    used = set()
    edges_all, edges_rest = {}, {}  # (folder, folder) -> "file:line includes file", without the known ones
    for f in files:
        for target, number, written in graph[f]:
            a, b = folder(f), folder(target)
            if a != b:
                example = f"{f}:{number} includes {target}"
                edges_all.setdefault((a, b), example)
                if (f, target) not in known_edges:
                    edges_rest.setdefault((a, b), example)
            why = wrong_way(f, target)
            if why is None:
                continue
            if (f, target) in known_edges:
                used.add((f, target))
                notes.append(f"known: {f} -> {target} ({why}): {known_edges[(f, target)]}")
            else:
                problems.append(f'{shown(f)}:{number}: #include "{written}" goes the wrong way: {why}')

    for a, b in known_edges:
        if (a, b) not in used:
            problems.append(f"known violation {a} -> {b} is no longer found: remove it from KNOWN "
                            f"(tools/check_layers.py), so that the list stays true")

    rest = folder_cycles(edges_rest)
    for cycle in rest:
        problems.append(describe_cycle(cycle, edges_rest))
    rest_sets = [set(c) for c in rest]
    for cycle in folder_cycles(edges_all):
        if not any(set(cycle) <= s for s in rest_sets):
            notes.append("known " + describe_cycle(cycle, edges_all) + ": closed by the known includes above")

    for cycle in cycles_of_files(graph):
        problems.append(f"{shown(cycle[0])}: include cycle: " + " -> ".join(cycle))
    return files, graph, problems, notes


def main(argv):
    args, known_file = [], None
    it = iter(argv[1:])
    for a in it:
        if a == "--known":
            known_file = next(it, None)
            if known_file is None:
                print("layers: --known needs a file", file=sys.stderr)
                return 2
        else:
            args.append(a)
    src = os.path.abspath(args[0] if args else os.path.join(os.path.dirname(__file__), "..", "src"))
    if not os.path.isdir(src):
        print(f"layers: no directory {src}", file=sys.stderr)
        return 2
    root = os.path.dirname(src)
    base = os.path.relpath(root) if not args else os.path.dirname(args[0].rstrip("/")) or "."

    def shown(f):
        return f if base == "." else os.path.join(base, f)

    known = KNOWN
    if known_file is not None:
        try:
            known = read_known(known_file)
        except OSError as e:
            print(f"layers: --known {known_file}: {e.strerror}", file=sys.stderr)
            return 2
    files, graph, problems, notes = check(root, shown, known)
    for n in notes:
        print(f"layers: {n}")
    if problems:
        for p in problems:
            print(f"layers: {p}", file=sys.stderr)
        print(f"layers: {len(problems)} problem(s) in {base}", file=sys.stderr)
        return 1
    edges = sum(len(v) for v in graph.values())
    but = f" but the {len(known)} known above" if known else ""
    print(f"layers: {len(files)} files, {edges} includes, {len(LEVELS)} levels: none goes the wrong way{but}, "
          f"no cycle{' but theirs' if known else ''}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
