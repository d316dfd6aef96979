// The scenarios and measures of `make report`: each scenario is run by the
// engine under a setting and by the exact reference (src/reference/), and the
// difference is measured. Also used by tests/test_numerics.cpp.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "numerics/scenes.hpp"
#include "reference/event_sim.hpp"

namespace physics::numerics {

struct Scenario {
  std::string name;
  double t_end;             // ms simulated
  Vector gravity;
  bool walled;              // tunnelling = leaving the walls; otherwise = order inversions along x
  int tracked = -1;         // entity whose first impact is timed (-1: any finite body)
  std::function<void(World&)> build;  // bodies with their initial velocities
};

std::vector<Scenario> report_scenarios();

// A setting of the sweep: a mode and the family (curve) it belongs to.
struct Setting {
  std::string family;
  Mode mode;
  std::string label;  // e.g. "dt=1000/120", "K=4", "it=8"
};
std::vector<Setting> report_settings();

struct Errors {
  double pos_rms = 0;        // px, over the finite bodies and the sample times
  double first_impact = 0;   // ms, engine's first impact (end of its frame) - reference's; NaN if none
  double energy = 0;         // max |E - E_ref| / E_scale over the samples (E = kinetic + potential)
  double momentum = 0;       // max |P - P_ref| / Σ m|v0| over the samples
  double max_penetration = 0;  // px, deepest overlap over all frames
  int tunnelled = 0;
  std::int64_t capped = 0;   // CCD substeps that ran out of budget
};

// Runs the scenario under the setting and measures its errors against the reference.
Errors measure(const Scenario& s, const Mode& m);

// The reference's bodies for a world (same order as the entity ids).
std::vector<reference::Body> reference_bodies(const World& w);

}  // namespace physics::numerics
