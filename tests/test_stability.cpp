// The stiff and extreme cases of `make stability` (tools/numerics/stability.cpp),
// each mode against its criterion. A cell is expected to pass unless
// expected_to_fail() names it (the modes not meant to handle that case); both
// directions are checked, so a change that breaks or fixes a cell shows here.
// The long cases carry the label "slow": `make test TEST_ARGS='--run_test=!@slow'`
// skips them (the sanitizer build does).
#include <boost/test/data/monomorphic.hpp>
#include <boost/test/data/test_case.hpp>

#include "helpers.hpp"
#include "numerics/stability.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_stability {

using namespace physics::numerics;
namespace bdata = boost::unit_test::data;

namespace {

const std::vector<StabilityCase>& cases() {
  static const std::vector<StabilityCase> all = stability_cases();
  return all;
}

std::vector<int> indices(bool slow) {
  std::vector<int> out;
  for (std::size_t i = 0; i < cases().size(); ++i)
    if (cases()[i].slow == slow) out.push_back(static_cast<int>(i));
  return out;
}

void check(int index) {
  const StabilityCase& c = cases()[static_cast<std::size_t>(index)];
  for (Mode m : stability_modes()) {
    m.stop_when_lost = true;  // the same pass or fail, without running out a decided failure
    const Outcome o = c.run(m);
    const bool expected = !expected_to_fail(c.name, m.name);
    BOOST_TEST_INFO(c.name << " [" << m.name << "]: " << c.criterion << "; measured " << o.figure);
    BOOST_TEST(o.pass == expected);
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(stability_matrix)

BOOST_DATA_TEST_CASE(case_meets_its_criterion_in_the_modes_meant_for_it, bdata::make(indices(false)), index) {
  check(index);
}

BOOST_TEST_DECORATOR(*boost::unit_test::label("slow"))
BOOST_DATA_TEST_CASE(long_case_meets_its_criterion_in_the_modes_meant_for_it, bdata::make(indices(true)), index) {
  check(index);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_stability
