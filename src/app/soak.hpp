// Soak: run a world for a very long time and check, at regular intervals,
// that nothing has gone wrong: no NaN or infinity, no body outside the walls,
// and the energy within the bound the mode promises. Used by `make soak`
// (10^6 steps) and by the tests (10^5 steps).
#pragma once

#include <cstdint>
#include <string>

#include "scene/scene.hpp"
#include "engine/world.hpp"

namespace physics {

struct SoakLimits {
  // The space the bodies must stay in: the inside of the walls. A body has
  // escaped when its centre leaves it. Its box may overlap a wall at the end
  // of a step: the course's one pass can push a body back into a wall it was
  // just taken out of (a later pair moves it), and the next step takes it out
  // again; that depth is reported (`max_wall_depth`), not failed.
  double min_x = 0, min_y = 0, max_x = 0, max_y = 0;
  // Measure the energy bound from the first check instead of the start: for
  // the course solver under gravity, whose contacts settle into a state with
  // some overlap and some kinetic energy it cannot remove; after that the
  // energy must not drift.
  bool settled = false;
  // Total energy (kinetic + potential in `gravity`) may not exceed the
  // starting one by more than this (absolute, in mass·px²/ms²).
  double energy_slack = 0;
  // If set, the energy may not fall either: |E - E0| <= energy_slack (e = 1).
  bool energy_conserved = false;
};

struct SoakResult {
  std::int64_t steps = 0, checks = 0;
  bool ok = true;
  std::string failure;         // the first failed check, empty when ok
  double energy_start = 0, energy_min = 0, energy_max = 0;
  double energy_reference = 0;  // the start, or the first check when `settled`
  double max_wall_depth = 0;     // px, deepest overlap of a body with the walls seen at a check
};

// Kinetic energy plus the potential energy of the finite masses in the
// world's gravity (an acceleration; y grows downwards, so the potential of a
// body at p is -m g·p).
double total_energy(const World& w);

// The limits a scene promises: its walls' inside (or the world rectangle
// without walls); with e = 1 everywhere and no gravity, energy conserved to
// 1e-9 relative; otherwise energy never above the start by more than what the
// position correction may return as potential energy, Σ m·|g|·1 px (the
// largest sink we accept), plus 1e-9 relative. Under gravity with the course
// solver, the bound is taken once the contacts have settled (`settled`).
SoakLimits soak_limits(const SceneSpec& spec, const World& w);

// Steps the world `steps` times, checking after every `every` steps.
// Stops at the first failed check.
SoakResult soak(World& w, std::int64_t steps, std::int64_t every, const SoakLimits& limits);

}  // namespace physics
