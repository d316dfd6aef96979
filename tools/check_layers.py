#!/usr/bin/env python3
"""The include layering of src/ (`make layers`, run by `make test`).

Folders under src/ depend one way; a file may include (#include "...") only
files of its own level or lower:

  0  utils/*                                     Vector, Rect: the course's
  1  ecs.hpp, component_defs.*                   components
  2  engine/*, systems/*, system_defs.*,         the engine and the course's
     reference/*                                 systems (one layer)
  3  entities/*
  4  game.*
  5  app/*, games/*                              scenes, command line, window; the games'
                                                 rules (src/games), which the testbed runs

Also fails on any include cycle between files (A includes B ... includes A).
A file of src/ outside this table is an error too: give it a level here.
Includes with <...> and includes that resolve to no file of src/ are ignored.

Usage: tools/check_layers.py [SRC_DIR]    (default: the src/ beside tools/)
Exit status 0 when clean, 1 with one line per problem on stderr.
"""

import os
import re
import sys

# (level, name, predicate on the path relative to src/, with '/' separators)
LEVELS = [
    (0, "utils", lambda p: p.startswith("course/utils/")),
    (1, "components", lambda p: p in ("course/ecs.hpp",) or re.fullmatch(r"course/component_defs\.[ch]pp", p) is not None),
    (2, "engine/systems", lambda p: p.split("/")[0] in ("engine", "reference") or p.startswith("course/systems/")
        or re.fullmatch(r"course/system_defs\.[ch]pp", p) is not None),
    (2.5, "api", lambda p: p.startswith("api/")),
    (3, "entities", lambda p: p.startswith("course/entities/")),
    (4, "game", lambda p: re.fullmatch(r"course/game\.[ch]pp", p) is not None),
    (5, "app", lambda p: p.split("/")[0] in ("app", "games", "scene", "input")),
]

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
SOURCE_EXT = (".hpp", ".cpp", ".h", ".cc", ".hh", ".ipp", ".tpp")


def level_of(rel):
    for level, name, matches in LEVELS:
        if matches(rel):
            return level, name
    return None


def main(argv):
    src = os.path.abspath(argv[1] if len(argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "src"))
    if not os.path.isdir(src):
        print(f"layers: no directory {src}", file=sys.stderr)
        return 2
    shown = os.path.relpath(src) if len(argv) <= 1 else argv[1].rstrip("/")

    files = []
    for root, _, names in os.walk(src):
        files += [os.path.relpath(os.path.join(root, n), src).replace(os.sep, "/")
                  for n in names if n.endswith(SOURCE_EXT)]
    files.sort()

    problems = []
    graph = {f: [] for f in files}  # file -> [(included file, line number)]
    for f in files:
        with open(os.path.join(src, f), encoding="utf-8", errors="replace") as text:
            for number, line in enumerate(text, 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                # As the compiler looks: beside the including file first, then src/ (-Isrc).
                for candidate in (os.path.join(os.path.dirname(f), m.group(1)), m.group(1)):
                    target = os.path.normpath(candidate).replace(os.sep, "/")
                    if target in graph:
                        graph[f].append((target, number, m.group(1)))
                        break

    for f in files:
        mine = level_of(f)
        if mine is None:
            problems.append(f"{shown}/{f}: has no level in tools/check_layers.py (LEVELS)")
            continue
        for target, number, written in graph[f]:
            theirs = level_of(target)
            if theirs is not None and theirs[0] > mine[0]:
                problems.append(f'{shown}/{f}:{number}: #include "{written}" goes the wrong way: '
                                f"{f} is level {mine[0]} ({mine[1]}), {target} is level {theirs[0]} ({theirs[1]}); "
                                f"a file may include only its own level or lower")

    # Include cycles: depth-first search, each cycle reported once, from the first file found on it.
    WHITE, GREY, BLACK = 0, 1, 2
    colour = dict.fromkeys(files, WHITE)
    seen_cycles = set()

    def visit(start):
        stack = [(start, iter(graph[start]))]
        path = [start]
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
                key = frozenset(cycle)
                if key not in seen_cycles:
                    seen_cycles.add(key)
                    problems.append(f"{shown}/{cycle[0]}: include cycle: " + " -> ".join(cycle + [target]))
            elif colour[target] == WHITE:
                colour[target] = GREY
                path.append(target)
                stack.append((target, iter(graph[target])))

    for f in files:
        if colour[f] == WHITE:
            visit(f)

    if problems:
        for p in problems:
            print(f"layers: {p}", file=sys.stderr)
        print(f"layers: {len(problems)} problem(s) in {shown}", file=sys.stderr)
        return 1
    edges = sum(len(v) for v in graph.values())
    print(f"layers: {len(files)} files, {edges} includes: none goes the wrong way, no cycle")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
