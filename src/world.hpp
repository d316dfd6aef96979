// A world: the component arrays, the systems a scene declared, and the
// parameters of the step. It replaces the OCaml code's global tables, so that
// tests and the testbed can hold several worlds at once.
#pragma once

#include <array>
#include <cstdint>

#include "component_defs.hpp"
#include "system_defs.hpp"
#include "systems/ccd.hpp"
#include "systems/contact_solver.hpp"

namespace physics {

inline constexpr double course_dt = 1000.0 / 60.0;  // ms, the sheet's dt

// How Collision resolves contacts. `course` is the sheet's one pass over the
// pairs and stays the default; `stable` is the iterated contact solver for
// resting contact and stacks (see the numerics options in the README).
enum class Solver : std::uint8_t { course, stable };

struct Params {
  double dt = course_dt;    // ms per frame
  int substeps = 1;         // Forces/Move/Collision run this many times with dt/substeps
  Vector gravity{};         // px/ms², applied by Forces to finite masses
  bool ccd = false;         // swept collision (time of impact), no tunnelling
  Solver solver = Solver::course;
  int iterations = 8;       // velocity iterations of the stable solver
};

// Throws std::invalid_argument naming the bad parameter.
void validate(const Params& p);

// Wall-clock time spent in each physics system since the world was made.
struct SystemTimes {
  std::array<std::int64_t, 4> ns{};  // indexed by SystemId
  std::int64_t steps = 0;
  double ms_per_step(SystemId s) const;
  double total_ms_per_step() const;
};

struct World {
  Components components;
  Systems systems;
  Params params;
  SystemTimes times;
  std::int64_t frame = 0;
  // State of the numerics options (Params::ccd, Params::solver): impact
  // counters and the stable solver's warm-start impulses. Unused in the
  // course mode.
  Ccd ccd;
  ContactSolver contact_solver;

  explicit World(SystemSet set = {}, Params p = {});

  // One frame of physics, in the sheet's order: Forces, Move, Collision.
  // (Draw is the front end's business.) With ccd or the stable solver, each
  // substep runs Forces, [stable: solve velocities], [ccd: impacts], Move,
  // then stable: project positions / course: the sheet's Collision pass; the
  // time of all but Forces and Move counts as Collision's.
  void step();

  // Diagnostics over finite masses (fixed bodies carry no kinetic energy and
  // an infinite momentum that means nothing).
  double kinetic_energy() const;
  Vector momentum() const;
  std::size_t finite_bodies() const;

 private:
  void step_numerics(double h);
};

}  // namespace physics
