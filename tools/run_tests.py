#!/usr/bin/env python3
"""Runs the test binary on every core: `make test` calls it.

Usage: tools/run_tests.py BINARY [JOBS] [-- BOOST_ARGS...]

The binary runs once per top-level suite, JOBS processes at a time (the
machine's cores by default), and the long cases (label "slow") in one
process of their own, started first: they are a third of the time. What each
process printed comes out whole, in the order of the suites, then one line
per suite and the final line "N passed, N failed" (tests/test_main.cpp's
format, summed). The exit code is non-zero if a test failed or a process
ended without its final line (a crash: its output says where).

BOOST_ARGS made only of exclusions (`--run_test=!...`, as `make test
SANITIZE=1` passes) apply to every process. Any other argument (a suite to
run, a log level) runs the binary once, as it is, with those arguments: one
process, Boost's own order.
"""
import os
import re
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

SUITE_LINE = re.compile(r"^  (ok   |FAIL )(\S+): (\d+) passed(?:, (\d+) failed)?$")
FINAL_LINE = re.compile(r"^(\d+) passed, (\d+) failed$")
NO_MATCH = "no test cases matching filter"
# Boost's own lines around each process's cases, said once for all at the end.
BOOST_NOISE = re.compile(r"^(Running \d+ test cases?\.\.\.|\*\*\* No errors detected)$")


def run(binary, args):
    env = dict(os.environ, BOOST_TEST_COLOR_OUTPUT="no")
    proc = subprocess.run([binary, *args], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env,
                          text=True, errors="replace")
    return proc.returncode, proc.stdout


def top_suites(binary):
    rc, out = run(binary, ["--list_content"])
    if rc != 0:
        sys.exit(f"run_tests: {binary} --list_content failed (exit {rc}):\n{out}")
    return [line.rstrip("*") for line in out.splitlines()
            if line and not line.startswith(" ") and not FINAL_LINE.match(line)]


def summarise(label, rc, out, suites):
    """Prints a process's output but its summary lines, adds its suite lines to `suites`, and returns
    its final line's (passed, failed) (a case outside any suite has no suite line), or None if the
    process broke: no final line (a crash), or a non-zero exit with no failed test."""
    lines = out.splitlines()
    final = FINAL_LINE.match(lines[-1]) if lines else None
    for line in lines[:-1] if final else lines:
        m = SUITE_LINE.match(line)
        if m:
            passed, failed = suites.get(m[2], (0, 0))
            suites[m[2]] = (passed + int(m[3]), failed + int(m[4] or 0))
        elif line.strip() and NO_MATCH not in line and not BOOST_NOISE.match(line):
            print(line)
    if not final:
        print(f"run_tests: {label}: ended without its final line (exit {rc}): counted as 1 failed")
        return None
    if rc != 0 and int(final[2]) == 0 and NO_MATCH not in out:
        print(f"run_tests: {label}: exit {rc} with no failed test: counted as 1 failed")
        return None
    return int(final[1]), int(final[2])


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__.strip())
    binary, rest = argv[1], argv[2:]
    boost_args = rest[rest.index("--") + 1:] if "--" in rest else []
    jobs = os.cpu_count() or 1
    if rest and rest[0] != "--":
        if not rest[0].isdigit() or int(rest[0]) < 1:
            sys.exit(f"run_tests: JOBS must be a positive integer, not {rest[0]!r}")
        jobs = int(rest[0])
    if any(not a.startswith("--run_test=!") for a in boost_args):
        rc, out = run(binary, boost_args)
        sys.stdout.write(out)
        return rc
    runs = [("the slow cases", ["--run_test=@slow"])]
    runs += [(suite, [f"--run_test={suite}", "--run_test=!@slow"]) for suite in top_suites(binary)]
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        results = list(pool.map(lambda r: run(binary, r[1] + boost_args), runs))
    suites, passed, failed = {}, 0, 0
    for (label, _), (rc, out) in zip(runs, results):
        counted = summarise(label, rc, out, suites) or (0, 1)  # a broken process: 1 failed
        passed, failed = passed + counted[0], failed + counted[1]
    for suite, (p, f) in sorted(suites.items()):
        print(f"  {'FAIL ' if f else 'ok   '}{suite}: {p} passed" + (f", {f} failed" if f else ""))
    print(f"{passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
