#!/usr/bin/env python3
"""Checks that the documentation points at things that exist.

  tools/check_links.py [FILE.md ...]     default: README.md and docs/*.md

For each Markdown file:
  - every relative link or image, [text](target) and ![alt](target), names an
    existing file or folder (relative to the file), and its #anchor, if any,
    is a heading of the target (GitHub's rule: lower case, punctuation
    dropped, spaces to hyphens; a repeated heading gets -1, -2, ...);
  - every repository path quoted in code, such as `src/course/game.cpp`,
    `src/engine/pairs.*` or `src/app/cli.{hpp,cpp}`, exists (globs and braces
    expanded), so a file that moved is caught in the docs that name it.
Links to web pages (http:, https:, mailto:) are not followed. Fenced code
blocks are skipped: they hold commands and programs, not references.

Prints one line per problem (FILE:LINE: ...) and exits 1 if there is any, 0
otherwise.
"""
import glob
import os
import re
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
# Top folders whose paths, quoted in code, must exist.
TRACKED = ("src", "include", "tests", "tools", "bench", "scenes", "replays", "report", "examples", "fuzz", "docs")
LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(([^()\s]+)(?:\s+\"[^\"]*\")?\)")
CODE = re.compile(r"(`+)(.+?)\1")
PATH = re.compile(r"(?:^|(?<=[\s(]))((?:" + "|".join(TRACKED) + r")/[A-Za-z0-9_.*{},/-]*)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")


def slug(heading):
    """GitHub's anchor for a heading."""
    text = re.sub(r"`([^`]*)`", r"\1", heading)
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)  # a link keeps its text
    text = text.strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def prose_lines(path):
    """(line number, text) of the lines outside fenced code blocks."""
    fenced = False
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            if line.lstrip().startswith(("```", "~~~")):
                fenced = not fenced
                continue
            if not fenced and not line.startswith("    "):
                yield n, line.rstrip("\n")


_anchors = {}


def anchors(path):
    if path not in _anchors:
        seen = {}
        for _, line in prose_lines(path):
            m = HEADING.match(line)
            if not m:
                continue
            s = slug(m.group(2))
            k = seen.get(s, 0)
            seen[s] = k + 1
            seen.setdefault(s if k == 0 else f"{s}-{k}", 1)
        _anchors[path] = set(seen)
    return _anchors[path]


def check_link(md, n, target):
    if re.match(r"[a-z]+:", target):
        return None
    file_part, _, anchor = target.partition("#")
    dest = os.path.normpath(os.path.join(os.path.dirname(md), file_part)) if file_part else md
    if not os.path.exists(dest):
        return f"{n}: link to {target}: no such file"
    if anchor and dest.endswith(".md") and anchor not in anchors(dest):
        return f"{n}: link to {target}: no heading #{anchor} in {os.path.relpath(dest, ROOT)}"
    return None


def expand(path):
    """The paths a quoted path names: {a,b} alternatives, then glob patterns."""
    m = re.search(r"\{([^{}]*)\}", path)
    if m:
        return [p for alt in m.group(1).split(",") for p in expand(path[:m.start()] + alt + path[m.end():])]
    return [path]


def check_path(n, path):
    path = path.rstrip(".,;:)")
    for p in expand(path):
        full = os.path.join(ROOT, p)
        if not (glob.glob(full) if any(c in p for c in "*?[") else os.path.exists(full)):
            return f"{n}: `{path}`: no such file in the repository"
    return None


def check(md):
    problems = []
    for n, line in prose_lines(md):
        for code in CODE.finditer(line):
            for p in PATH.finditer(code.group(2)):
                problems.append(check_path(n, p.group(1)))
        for link in LINK.finditer(CODE.sub("", line)):
            problems.append(check_link(md, n, link.group(1)))
    return [f"{os.path.relpath(md, ROOT)}:{p}" for p in problems if p]


def hello_snippet():
    """The README's first C++ block must be examples/hello.cpp (from its first #include): the example built and
    run by `make examples` is the one the reader copies."""
    readme = open(os.path.join(ROOT, "README.md"), encoding="utf-8").read()
    block = re.search(r"```cpp\n(.*?)```", readme, re.S)
    hello = open(os.path.join(ROOT, "examples", "hello.cpp"), encoding="utf-8").read()
    if not block or block.group(1) != hello[hello.find("#include"):]:
        return ["README.md: its first ```cpp block is not examples/hello.cpp (from its first #include)"]
    return []


def main(argv):
    files = argv or [os.path.join(ROOT, "README.md")] + sorted(glob.glob(os.path.join(ROOT, "docs", "*.md")))
    problems = [p for md in files for p in check(os.path.abspath(md))]
    if not argv:
        problems += hello_snippet()
    for p in problems:
        print(p)
    if problems:
        print(f"check_links: {len(problems)} problem(s) in {len(files)} file(s)", file=sys.stderr)
        return 1
    print(f"check_links: {len(files)} file(s), every link and quoted path exists")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
