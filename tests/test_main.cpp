// Test runner: Boost.Test, then a line per suite (the sheet's questions and
// later concerns) and one plain final line "N passed, N failed" that CI reads.
#define BOOST_TEST_DYN_LINK
#include <boost/test/results_collector.hpp>
#include <boost/test/tree/traverse.hpp>
#include <boost/test/tree/visitor.hpp>
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

namespace ut = boost::unit_test;

// Collects the top-level suites, in the order Boost runs them.
struct TopSuites : ut::test_tree_visitor {
  std::vector<const ut::test_suite*> suites;
  int depth = 0;
  bool test_suite_start(const ut::test_suite& s) override {
    if (depth++ == 1) suites.push_back(&s);
    return true;
  }
  void test_suite_finish(const ut::test_suite&) override { --depth; }
};

static bool init_unit_test() {
  ut::framework::master_test_suite().p_name.value = "physics";
  return true;
}

int main(int argc, char* argv[]) {
  const int rc = ut::unit_test_main(&init_unit_test, argc, argv);
  std::cerr.flush();  // Boost's report first, so our lines come last
  const ut::test_suite& master = ut::framework::master_test_suite();
  TopSuites top;
  ut::traverse_test_tree(master, top, true);
  std::sort(top.suites.begin(), top.suites.end(),
            [](const ut::test_suite* a, const ut::test_suite* b) { return a->p_name.get() < b->p_name.get(); });
  for (const ut::test_suite* suite : top.suites) {
    const ut::test_results& r = ut::results_collector.results(suite->p_id);
    // An aborted case (an exception, a failed REQUIRE) is counted among the
    // failed ones too: adding p_test_cases_aborted would count it twice.
    const auto failed = r.p_test_cases_failed;
    if (r.p_test_cases_passed + failed == 0) continue;  // filtered out
    std::cout << "  " << (failed ? "FAIL " : "ok   ") << suite->p_name.get() << ": " << r.p_test_cases_passed
              << " passed" << (failed ? ", " + std::to_string(failed) + " failed" : "") << "\n";
  }
  const ut::test_results& r = ut::results_collector.results(master.p_id);
  std::cout << r.p_test_cases_passed << " passed, " << r.p_test_cases_failed << " failed"
            << std::endl;
  return rc;
}
