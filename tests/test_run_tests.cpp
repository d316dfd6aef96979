// The runner of `make test` (tools/run_tests.py), on a fake test binary: a
// shell script that lists three suites and answers each filter as the real
// binary (tests/test_main.cpp) would. The sums must be right, a failed test
// and a crash must fail the run, exclusions must reach every process, and any
// other argument must run the binary once, as given.
#include <sys/stat.h>
#include <sys/wait.h>

#include <string>

#include "cli_helpers.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_run_tests {

namespace {

using namespace physics::test;

// `a` has a failing case, `b` crashes unless excluded with "!b", `c` passes;
// the slow cases (label "slow") are in `c`.
const char* fake = R"(#!/bin/sh
echo "$*" >> "$(dirname "$0")/calls"
case "$*" in
  --list_content) printf 'a*\n    one*\nb*\nc*\n0 passed, 0 failed\n' ;;
  "--run_test=@slow"*) echo "Running 1 test case..."; echo "  ok   c: 1 passed"; echo "1 passed, 0 failed" ;;
  "--run_test=b "*"--run_test=!b"*) echo "Test setup error: no test cases matching filter or all test cases were disabled"
                     echo "0 passed, 0 failed"; exit 200 ;;
  "--run_test=a "*) echo "Running 1 test case..."; echo "t.cpp(3): error: boom"; echo "  FAIL a: 0 passed, 1 failed"
                    echo "0 passed, 1 failed"; exit 201 ;;
  "--run_test=b "*) echo "Running 2 test cases..."; echo "half a line"; exit 139 ;;
  "--run_test=c "*) echo "Running 2 test cases..."; echo "*** No errors detected"; echo "  ok   c: 2 passed"; echo "2 passed, 0 failed" ;;
  *) echo "Running 5 test cases..."; echo "as given: $*"; echo "5 passed, 0 failed" ;;
esac
)";

struct Run {
  int code;
  std::string out, calls;
};

Run run_tests(const TempDir& dir, const std::string& args) {
  const std::string bin = dir.file("tests", fake);
  ::chmod(bin.c_str(), 0755);
  const std::string script = (repo_root() / "tools" / "run_tests.py").string();
  const std::string cmd = "python3 " + quote(script) + " " + quote(bin) + " " + args + " >" + quote(dir.file("out")) + " 2>&1";
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read(dir.file("out")), read(dir.file("calls"))};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(test_runner)

BOOST_AUTO_TEST_CASE(sums_the_suites_and_fails_on_a_failed_test_or_a_crash) {
  const TempDir dir;
  const Run r = run_tests(dir, "2");
  BOOST_TEST(r.code == 1);
  // 1 slow + 2 in c; a's failure and b's crash.
  BOOST_TEST(has(r.out, "\n3 passed, 2 failed\n"), r.out);
  BOOST_TEST(r.out.ends_with("3 passed, 2 failed\n"), r.out);
  BOOST_TEST(has(r.out, "  ok   c: 3 passed\n"), r.out);
  BOOST_TEST(has(r.out, "  FAIL a: 0 passed, 1 failed\n"), r.out);
  BOOST_TEST(has(r.out, "t.cpp(3): error: boom"), r.out);
  BOOST_TEST(has(r.out, "run_tests: b: ended without its final line (exit 139): counted as 1 failed"), r.out);
  BOOST_TEST(!has(r.out, "Running"), r.out);
  BOOST_TEST(!has(r.out, "No errors"), r.out);
  // Each suite in a process of its own, the slow cases apart.
  BOOST_TEST(has(r.calls, "--run_test=@slow\n"), r.calls);
  BOOST_TEST(has(r.calls, "--run_test=a --run_test=!@slow\n"), r.calls);
  BOOST_TEST(has(r.calls, "--run_test=c --run_test=!@slow\n"), r.calls);
}

BOOST_AUTO_TEST_CASE(exclusions_reach_every_process) {
  const TempDir dir;
  const Run r = run_tests(dir, "1 -- '--run_test=!b'");
  // b excluded: its process matches nothing, which is no failure; a still fails.
  BOOST_TEST(r.code == 1);
  BOOST_TEST(r.out.ends_with("\n3 passed, 1 failed\n"), r.out);
  BOOST_TEST(!has(r.out, "no test cases matching"), r.out);
  BOOST_TEST(has(r.calls, "--run_test=b --run_test=!@slow --run_test=!b\n"), r.calls);
}

BOOST_AUTO_TEST_CASE(other_arguments_run_the_binary_once_as_given) {
  const TempDir dir;
  const Run r = run_tests(dir, "-- --run_test=c/x --log_level=all");
  BOOST_TEST(r.code == 0);
  BOOST_TEST(r.calls == "--run_test=c/x --log_level=all\n");
  BOOST_TEST(has(r.out, "as given: --run_test=c/x --log_level=all"), r.out);
  BOOST_TEST(r.out.ends_with("5 passed, 0 failed\n"), r.out);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_run_tests
