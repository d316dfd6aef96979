// Test runner: Boost.Test, then one plain line "N passed, N failed" that CI reads.
#define BOOST_TEST_DYN_LINK
#include <boost/test/results_collector.hpp>
#include <boost/test/unit_test.hpp>

#include <iostream>

namespace ut = boost::unit_test;

static bool init_unit_test() {
  ut::framework::master_test_suite().p_name.value = "physics";
  return true;
}

int main(int argc, char* argv[]) {
  const int rc = ut::unit_test_main(&init_unit_test, argc, argv);
  std::cerr.flush();  // Boost's report first, so our line is the last one
  const ut::test_results& r = ut::results_collector.results(ut::framework::master_test_suite().p_id);
  std::cout << r.p_test_cases_passed << " passed, "
            << r.p_test_cases_failed + r.p_test_cases_aborted << " failed" << std::endl;
  return rc;
}
