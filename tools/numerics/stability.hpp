// The stiff and extreme cases of `make stability`, each with its pass
// criterion. The same functions back tests/test_stability.cpp.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "numerics/scenes.hpp"

namespace physics::numerics {

struct Outcome {
  bool pass = false;
  std::string figure;  // the measured number(s) the criterion is judged on
};

struct StabilityCase {
  std::string name;
  std::string criterion;
  bool slow = false;  // long: under the Boost label "slow"
  std::function<Outcome(const Mode&)> run;
};

std::vector<StabilityCase> stability_cases();

// The matrix cells expected to fail (case name, mode name): the modes not
// meant to handle the case. Everything else is expected to pass; the tests
// check both ways, so a change that fixes or breaks a cell shows.
bool expected_to_fail(const std::string& case_name, const std::string& mode_name);

// Why shock propagation: the deepest sink of a heavy block on a light one on
// the floor over 10 s, stable solver with and without it, by iteration count
// and mass ratio (a markdown table).
std::string shock_ablation();

}  // namespace physics::numerics
