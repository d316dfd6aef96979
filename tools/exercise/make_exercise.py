#!/usr/bin/env python3
"""The student's tree of the sheet (exercise mode): see README.md, "Working through the sheet".

Every answer to a question of the sheet is marked in the source:

    // Q6 begin
    // Q6 stub: // TODO Q6: ...what the sheet asks...
    // Q6 stub: (void)p1, (void)r1, (void)p2, (void)r2;
    // Q6 stub: return {};
    ...the answer...
    // Q6 end

The exercise tree keeps the markers, and replaces what lies between them by
the stub lines (the text after "// Q<n> stub:", indented as the begin
marker): code that compiles and does nothing. A question kept with --keep
keeps its answer (the stub lines are dropped).

  make_exercise.py --out DIR [--keep 1,2] [--force]   write the tree
  make_exercise.py --check                             parse-level check only

The tree: the course tree (src/course/: game.*, component_defs.*, ...), every
project header it includes and the .cpp beside each of them (so the engine
files it needs), the per-question tests of tests/ and a Makefile (`make test`, and `make run`,
which builds the project's game on the tree's course files). A file
whose content is unchanged is not rewritten (incremental builds). An
existing DIR is not overwritten without --force: it may hold the student's
answers.
"""
import argparse
import os
import re
import shutil
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
QUESTIONS = range(1, 10)

# The course tree (README.md, "Where each question of the sheet is answered").
COURSE = ["src/course/game.cpp", "src/course/game.hpp", "src/course/component_defs.cpp", "src/course/component_defs.hpp",
          "src/course/system_defs.cpp", "src/course/system_defs.hpp", "src/course/ecs.hpp",
          "src/course/systems/draw.cpp", "src/course/systems/draw.hpp", "src/course/systems/move.cpp", "src/course/systems/move.hpp",
          "src/course/systems/forces.cpp", "src/course/systems/forces.hpp",
          "src/course/systems/collision.cpp", "src/course/systems/collision.hpp",
          "src/course/entities/block.cpp", "src/course/entities/block.hpp",
          "src/course/utils/vect.cpp", "src/course/utils/vect.hpp", "src/course/utils/rect.cpp", "src/course/utils/rect.hpp"]
# The per-question tests (suites q<n>_*) and the runner. Their includes pull
# in what else is needed (src/app/headless for q9_scene).
TESTS = ["tests/test_main.cpp", "tests/helpers.hpp", "tests/test_walls.cpp", "tests/test_components.cpp",
         "tests/test_move_forces.cpp", "tests/test_rect.cpp", "tests/test_collision.cpp",
         "tests/test_game.cpp"]
MAKEFILE = "tools/exercise/Makefile.exercise"

BEGIN = re.compile(r"^(\s*)// Q(\d+) begin\s*$")
END = re.compile(r"^\s*// Q(\d+) end\s*$")
STUB = re.compile(r"^\s*// Q(\d+) stub:(?: (.*))?$")
MARK = re.compile(r"//\s*Q\d+\s+(begin|end|stub)\b")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


class MarkerError(Exception):
    pass


def regions(path, lines):
    """The marked regions of a file: (question, begin index, end index, indent, stub lines, answer lines)."""
    out = []
    cur = None
    for i, line in enumerate(lines):
        where = f"{path}:{i + 1}"
        b, e, s = BEGIN.match(line), END.match(line), STUB.match(line)
        if b:
            if cur:
                raise MarkerError(f"{where}: Q{b.group(2)} begins inside Q{cur[0]} (line {cur[1] + 1})")
            cur = [int(b.group(2)), i, b.group(1), [], []]
        elif e:
            if not cur or int(e.group(1)) != cur[0]:
                raise MarkerError(f"{where}: Q{e.group(1)} end without its begin")
            q, start, indent, stub, answer = cur
            if not stub:
                raise MarkerError(f"{path}:{start + 1}: Q{q} region has no '// Q{q} stub:' line")
            if not any(a.strip() and not a.strip().startswith("//") for a in answer):
                raise MarkerError(f"{path}:{start + 1}: Q{q} region has no code to replace")
            out.append((q, start, i, indent, stub, answer))
            cur = None
        elif s:
            if not cur or int(s.group(1)) != cur[0]:
                raise MarkerError(f"{where}: Q{s.group(1)} stub outside its region")
            if any(a.strip() for a in cur[4]):
                raise MarkerError(f"{where}: Q{cur[0]} stub lines must come first in the region")
            cur[3].append(s.group(2) or "")
        elif MARK.search(line):
            raise MarkerError(f"{where}: malformed marker: {line.strip()}")
        elif cur:
            cur[4].append(line)
    if cur:
        raise MarkerError(f"{path}:{cur[1] + 1}: Q{cur[0]} begin without its end")
    return out


def stubbed(path, text, stub_questions):
    """The file with the regions of stub_questions stubbed, the others' stub lines dropped."""
    lines = text.split("\n")
    rs = regions(path, lines)
    out, pos = [], 0
    for q, start, end, indent, stub, answer in rs:
        out += lines[pos:start + 1]
        if q in stub_questions:
            out += [(indent + s).rstrip() for s in stub]
        else:
            out += answer
        out.append(lines[end])
        pos = end + 1
    out += lines[pos:]
    return "\n".join(out), rs


def closure():
    """The course tree and the tests, plus every project header they include and the .cpp beside it."""
    files, todo = [], list(COURSE) + list(TESTS)
    while todo:
        f = todo.pop(0)
        if f in files:
            continue
        if not os.path.isfile(os.path.join(ROOT, f)):
            raise MarkerError(f"{f}: missing")
        files.append(f)
        text = open(os.path.join(ROOT, f), encoding="utf-8").read()
        for inc in INCLUDE.findall(text):
            for base in (os.path.dirname(f), "src", "include"):
                cand = os.path.normpath(os.path.join(base, inc))
                if os.path.isfile(os.path.join(ROOT, cand)):
                    todo.append(cand)
                    if cand.endswith(".hpp"):
                        cpp = cand[:-4] + ".cpp"
                        if os.path.isfile(os.path.join(ROOT, cpp)):
                            todo.append(cpp)
                    break
            else:
                raise MarkerError(f"{f}: cannot find the included \"{inc}\"")
    return sorted(files)


def write_if_changed(path, text):
    if os.path.isfile(path) and open(path, encoding="utf-8").read() == text:
        return False
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    return True


def check(files):
    """Parse-level check: every question has a valid region, each stub replaces its answer, a suite tests it."""
    problems, found = [], {q: [] for q in QUESTIONS}
    for f in files:
        text = open(os.path.join(ROOT, f), encoding="utf-8").read()
        try:
            out, rs = stubbed(f, text, set(QUESTIONS))
            kept, _ = stubbed(f, text, set())
        except MarkerError as e:
            problems.append(str(e))
            continue
        if rs and f not in COURSE:
            problems.append(f"{f}: marked, but not in the course tree")
        for q, start, end, indent, stub, answer in rs:
            found.setdefault(q, []).append(f"{f}:{start + 1}")
        # Without stubs, the tree is the source minus the stub comments: the code is the same.
        strip = lambda t: [l for l in t.split("\n") if not STUB.match(l)]
        if strip(text) != kept.split("\n"):
            problems.append(f"{f}: the tree with every answer kept differs from the source")
        if rs and out == text:
            problems.append(f"{f}: stubbing changes nothing")
    suites = set()
    for f in TESTS:
        suites |= set(re.findall(r"BOOST_AUTO_TEST_SUITE\((q\d+)_\w+\)", open(os.path.join(ROOT, f)).read()))
    for q in QUESTIONS:
        if not found.get(q):
            problems.append(f"Q{q}: no marked region")
        if f"q{q}" not in suites:
            problems.append(f"Q{q}: no test suite q{q}_* in {', '.join(TESTS)}")
    for q in sorted(found):
        if q not in QUESTIONS:
            problems.append(f"Q{q}: the sheet has no such question ({', '.join(found[q])})")
    return problems, found


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", help="directory of the exercise tree")
    ap.add_argument("--keep", default="", help="questions whose answers are kept, e.g. 1,2,3")
    ap.add_argument("--force", action="store_true", help="overwrite an existing tree (the student's edits are lost)")
    ap.add_argument("--check", action="store_true", help="parse-level check of the markers, nothing written")
    a = ap.parse_args()
    try:
        files = closure()
    except MarkerError as e:
        sys.exit(f"exercise: {e}")
    problems, found = check(files)
    if problems:
        sys.exit("exercise: marker problems:\n  " + "\n  ".join(problems))
    if a.check:
        print(f"exercise markers: ok ({len(files)} files; " +
              ", ".join(f"Q{q} x{len(found[q])}" for q in QUESTIONS) + ")")
        return
    if not a.out:
        ap.error("--out DIR or --check")
    keep = {int(q) for q in a.keep.replace(",", " ").split()}
    stub_q = set(QUESTIONS) - keep
    out = os.path.abspath(a.out)
    stamp = os.path.join(out, ".exercise")
    if os.path.exists(out) and not a.force:
        if not os.path.exists(stamp):
            sys.exit(f"exercise: {a.out} exists and was not made by this script")
        sys.exit(f"exercise: {a.out} exists and may hold your answers: not overwritten "
                 f"(remove it, or pass --force / make exercise FORCE=1)")
    changed = 0
    for f in files:
        text = open(os.path.join(ROOT, f), encoding="utf-8").read()
        text, _ = stubbed(f, text, stub_q)
        changed += write_if_changed(os.path.join(out, f), text)
    # `make run` in the tree builds the game in the project it came from.
    makefile = open(os.path.join(ROOT, MAKEFILE), encoding="utf-8").read().replace("@PROJECT@", ROOT)
    changed += write_if_changed(os.path.join(out, "Makefile"), makefile)
    # Files of an earlier generation that are no longer part of the tree.
    wanted = {os.path.join(out, f) for f in files} | {os.path.join(out, "Makefile"), stamp}
    for d in ("src", "tests"):
        for dirpath, _, names in os.walk(os.path.join(out, d)):
            for n in names:
                p = os.path.join(dirpath, n)
                if p not in wanted:
                    os.remove(p)
    write_if_changed(stamp, "stubbed: " + " ".join(f"Q{q}" for q in sorted(stub_q)) + "\n")
    print(f"exercise: {a.out}: {len(files)} files ({changed} written), "
          f"stubbed {', '.join(f'Q{q}' for q in sorted(stub_q)) or 'nothing'}")


if __name__ == "__main__":
    main()
