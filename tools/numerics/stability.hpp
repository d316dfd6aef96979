// The stiff and extreme cases of `make stability`, each with its pass
// criterion. The same functions back tests/test_stability.cpp.
#pragma once

#include <cstdio>
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

// The criteria's measures, shared by the matrix's cases and the generated
// family (numerics/family.hpp).
namespace criteria {

inline constexpr double max_sink = 1.0;           // px: the deepest overlap allowed
inline constexpr double energy_tolerance = 1e-9;  // relative: rounding, not growth
inline constexpr double momentum_tolerance = 1e-12;

// printf's format of numbers, each passed as a double (so %g, %f, %e, %.0f
// for integers), as a string of at most 255 characters.
template <class... Numbers>
std::string fmt(const char* f, Numbers... a) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, static_cast<double>(a)...);
  return buf;
}
// Bodies outside the space the course's walls enclose (shifted by o).
int outside_walls(const World& w, Vector o = {});
// Kinetic energy plus the potential of falling 600 px: what growth is measured against.
double energy_in_play(const World& w);
// Σ m|v|, what momentum drift is measured against; drift(a, b, scale) = |a - b|_1 / scale.
double momentum_scale(const World& w);
double drift(Vector a, Vector b, double scale);
std::string out_text(int n);  // ", N out", or nothing
// The verdict, failed when CCD ran out of its budget in more than 1 % of the substeps (time lost).
Outcome finish(bool pass, std::string figure, const World& w);
Outcome nan_outcome();

// What a run of `frames` frames tracks for every criterion.
struct Track {
  bool finite = true;
  double max_overlap = 0;   // px, deepest over the run (sampled each `every` frames)
  double energy_growth = 0; // max (E - E0) / energy in play, step energy
  double momentum_drift = 0;
  int outside = 0;          // max count of bodies outside the walls
};
// Whether a test's run can stop (Mode::stop_when_lost): its cell has failed.
bool lost(const Mode& m, const World& w, int frames);
// Runs `frames` frames of w; `each`, if given, looks at the world after every frame.
Track run(const Mode& m, World& w, int frames, bool with_walls, Vector wall_offset = {}, int every = 1,
          const std::function<void(const World&)>& each = {});

}  // namespace criteria

// The matrix cells expected to fail (case name, mode name): the modes not
// meant to handle the case. Everything else is expected to pass; the tests
// check both ways, so a change that fixes or breaks a cell shows.
bool expected_to_fail(const std::string& case_name, const std::string& mode_name);

// Why shock propagation: the deepest sink of a heavy block on a light one on
// the floor over 10 s, stable solver with and without it, by iteration count
// and mass ratio (a markdown table).
std::string shock_ablation();

}  // namespace physics::numerics
