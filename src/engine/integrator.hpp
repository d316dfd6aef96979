// The exact integrator (Params::integrator = Integrator::exact).
//
// The sheet steps symplectic Euler: Forces does v += a·h, then Move does
// x += h·v with the new v, so a substep moves a body by v0·h + a·h² where
// constant-force motion (and the exact reference, src/reference/, between
// its events) moves it by v0·h + a·h²/2. The error is a·h²/2 per substep,
// first order over a run: a projectile lands early at every dt.
//
// The course's Forces and Move stay as the sheet has them (they are its
// exercises). This class corrects their result from the engine's side,
// in three calls per substep that Game::step makes through World:
//  1. start, before Forces: the velocities Forces starts from;
//  2. after_forces, before the engine's velocity stages: the kick a·h that
//     Forces gave (measured, not recomputed, so that it is exactly what
//     Forces applied whatever it sums), and the velocity it left;
//  3. shift, after those stages and just before Move: x -= a·h²/2, so that
//     Move's x += h·(v0 + a·h) lands at x + v0·h + a·h²/2.
// The shift goes only to bodies whose velocity the stable solver and CCD left
// as Forces did, bit for bit: those moved freely during the substep, and
// their motion is exact. A body that met a contact has a velocity the solver
// or CCD chose for where Move takes it (the solver's speculative target, a
// resting contact's zero, CCD's time-of-impact shift, which already models
// the gravity kick within the substep), and shifting it would undo that
// choice: a resting block would hover a·h²/2 above the floor. The course's
// Collision pass runs after Move and resolves what it finds, so in the
// course mode every body is shifted; at a contact the body only reaches
// a·h²/2 less deep before the pass pushes it out.
#pragma once

#include <span>
#include <vector>

#include "engine/components.hpp"

namespace physics {

class ExactIntegrator {
 public:
  void start(const Components& k, std::span<const EntityId> bodies);
  void after_forces(const Components& k, std::span<const EntityId> bodies);
  void shift(Components& k, std::span<const EntityId> bodies, double h) const;

 private:
  std::vector<Vector> kick_;      // by entity id: the velocity before Forces, then what Forces added
  std::vector<Vector> v_forces_;  // by entity id: the velocity Forces left
};

}  // namespace physics
