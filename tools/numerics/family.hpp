// The generated stiff-case family of `make stability` (issue 23): scenes
// drawn from parameter ranges, not a fixed list, each checked against an
// invariant from physics (1-D order kept, none outside the walls, overlap
// below 1 px, energy never grows and is kept for e = 1 without friction,
// momentum kept without walls and gravity, closed forms for free flight,
// slides, exact fits and reflections, sensor crossings, a reload that
// continues bit for bit). A draw is reproducible from (family, seed):
// `build/stability --family NAME --seed S` replays it. The matrix's
// criteria helpers (numerics/stability.hpp, criteria) judge it, in the
// matrix's modes. tests/test_family.cpp runs the seeds 1..test_draws.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "numerics/stability.hpp"

namespace physics::numerics {

// One scene drawn from a family's ranges.
struct Draw {
  std::string params;                       // the values drawn, as text
  std::function<Outcome(const Mode&)> run;  // the scene in a mode, judged by the family's invariant
};

struct Family {
  std::string name;       // a word or two with dashes: what --family takes
  std::string ranges;     // what is drawn, from what ranges
  std::string invariant;  // what every draw is checked against
  std::function<Draw(std::uint64_t seed)> draw;
};

const std::vector<Family>& families();
const Family* find_family(std::string_view name);  // nullptr if none is so named

// Seeds 1..family_draws per family in `make stability`; 1..test_draws in `make test`.
inline constexpr int family_draws = 50;
inline constexpr int test_draws = 5;

// The draws of the test subset (seed <= test_draws) that fail today in a
// mode; tests/test_family.cpp checks both ways (a listed draw that passes
// and an unlisted one that fails both show). `build/stability
// --family-expected` prints today's list in this form.
bool family_expected_to_fail(const std::string& family, std::uint64_t seed, const std::string& mode);
// That list: "family/seed" and the names of the modes it fails in, separated by spaces.
using FailingDraw = std::pair<std::string_view, std::string_view>;
const std::vector<FailingDraw>& failing_today();

}  // namespace physics::numerics
