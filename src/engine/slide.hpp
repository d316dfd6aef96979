// Friction's motion within a substep, for the stable solver
// (Params::solver stable, and auto when it takes the solver).
//
// The solver applies friction to the velocity before Move, and Move carries a
// body by h·v at the velocity it leaves: a block sliding to rest under
// friction then moves, each substep, by the velocity it has at the substep's
// end, and stops v0·h/2 short of v0²/(2 mu g) (90.3 px for 94.9 at v0 =
// 0.56 px/ms, mu 0.93, g 0.00176, dt = 1000/60: 4.9 %). The course's pass,
// which applies friction after Move, overshoots by as much. Between its
// substep's start and end the slide's deceleration is constant, so the exact
// motion along the surface is the trapezoid, h·(v_start + v_end)/2: this
// shifts such a body along the surface by -h/2·(v_end - v_start), where
// v_start is its velocity before Forces and v_end the one the velocity
// stages left. Its three calls per substep (World):
//  1. start, before Forces: the velocities Forces starts from;
//  2. after_solver, after the solver's velocities: the sliders and their
//     velocity along the surface;
//  3. shift, after CCD and just before Move.
// A slider is a finite body whose solver contacts this substep all rest
// (no impact: an impact's friction is an impulse at its instant), all have
// normals on one axis (the surface's; a contact across the other axis holds
// the body there, and the shift would move it into what it touches), and
// carry a tangential impulse. A slider whose velocity along the surface CCD
// changed afterwards is left as it is. A body held by static friction (v_start
// and v_end both 0, even under a sideways force) does not move; a force-driven
// slide is exact too (the trapezoid is exact for a constant force). The normal
// direction is the solver's (a resting contact's target), never shifted.
#pragma once

#include <span>
#include <vector>

#include "engine/components.hpp"
#include "engine/contact_solver.hpp"

namespace physics {

class SlideIntegrator {
 public:
  // `needed`: whether anything reads the velocities before Forces this
  // substep (some body has friction, or CCD may run); when not, they are not
  // copied (a frictionless rain of 100 000: 1.6 MB a step) and
  // before_forces() is empty.
  void start(const Components& k, bool needed);
  void after_solver(const Components& k, std::span<const ContactConstraint> contacts,
                    std::span<const FrictionRow> rows);
  void shift(Components& k, double h);
  // By entity id, the velocities before this substep's Forces (start()).
  std::span<const Vector> before_forces() const { return v_start_; }

 private:
  std::vector<Vector> v_start_;        // by entity id: the velocity before Forces
  std::vector<Vector> v_end_;          // by entity id: a slider's velocity after the solver
  // By entity id, over its contacts: 1 x-normal, 2 y-normal, 4 an impact or a
  // finite support, 8 friction, 32 a fixed body (after_solver()); shift()
  // reads a slider's axis there ((t & 3) == 2: y-normal contacts, a floor or
  // a ceiling, so along x).
  std::vector<std::uint8_t> touched_;
  std::vector<EntityId> sliders_;
};

}  // namespace physics
