// Continuous collision detection (the sheet's closing remark: "si les objets
// vont trop vite, ils passent à travers les murs ... swept collision").
//
// Within one (sub)step every body moves on a straight line at the velocity it
// has after Forces. Ccd::resolve finds, in time order, every moment in
// [0, h] at which two boxes start to touch: the relative motion of the pair is
// cast against their Minkowski difference (the sheet's `mdiff`), and the time
// the origin enters that box is the time of impact (TOI). At each impact the
// pair gets the course's impulse (restitution = min of the pair, fixed bodies
// untouched), and the other impacts of the two bodies are predicted again.
// Nothing ever passes through anything, at any speed.
//
// It does not move the bodies itself: a body whose velocity changes from v to
// v' at time t has its position shifted by t·(v - v'), so that Move's usual
// x += h·v' lands it where the piecewise-linear motion ends. Move and its
// timing stay as they are.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "engine/components.hpp"
#include "engine/events.hpp"
#include "engine/pairs.hpp"

namespace physics {

struct Impact {
  double t;  // ms from the start of the step
  Vector n;  // unit axis that moves c away from b at the impact
};

// Body e's box swept along its line, position + t·velocity, over [t0, t1]
// ms of the substep; with `hair`, grown by a hair more than rounding, so that
// a pair whose two boxes do not meet has no impact whatever time_of_impact
// rounds (CCD's re-prediction), else exactly the path's (auto's plan).
struct SweptBox {
  double x0, x1, y0, y1;
};
inline SweptBox swept_box(const Components& k, EntityId e, double t0, double t1, bool hair) {
  const Vector p = k.position[e], v = k.velocity[e];
  const Vector a = t0 == 0.0 ? p : p + t0 * v, z = p + t1 * v;
  const double w = k.box[e].width, ht = k.box[e].height;
  const double eps =
      hair ? 1e-9 * (1.0 + std::abs(a.x) + std::abs(a.y) + std::abs(z.x) + std::abs(z.y) + w + ht) : 0.0;
  return {std::min(a.x, z.x) - eps, std::max(a.x, z.x) + w + eps, std::min(a.y, z.y) - eps,
          std::max(a.y, z.y) + ht + eps};
}

// Which bodies CCD sweeps, for the auto mode (engine/auto_mode.hpp); the
// spans are indexed by entity id. Without a selection every body is swept
// from the substep's start.
struct CcdSelection {
  // 1: swept from the start. A body hit by a swept one is swept from then
  // on once its remaining motion, |v|·(h - t), exceeds its reach; below
  // that the overlap it can make is left to the pass after Move.
  std::span<std::uint8_t> fast;
  // ms: the time from which the body's straight line (position + t·velocity)
  // is its motion: the stable solver's impact time, 0 for the others.
  std::span<const double> start;
  double thinnest = 0;  // px: the thinnest side of the world's bodies

  // px: half the body's thinnest side plus the world's (an overlap up to that
  // is pushed out on the side it came from; deeper, the body tunnels).
  static double reach(double side, double world_thinnest) { return 0.5 * (side + world_thinnest); }
  double reach(const Components& k, EntityId e) const {
    return reach(static_cast<double>(std::min(k.box[e].width, k.box[e].height)), thinnest);
  }

  // px: how deep the boxes of a and b overlap at time t of the substep
  // (each at position + t·velocity), 0 if they do not.
  static double overlap_at(const Components& k, EntityId a, EntityId b, double t);
  // Whether a and b close, over the `span` ms from time t, by more than the
  // pass after Move can separate: half their two thinnest sides, less their
  // overlap at t if `overlapped` (past that the pass pushes them out on the
  // wrong side: they pass through each other). Two bodies each within its
  // reach may still do so (head on: twice it), and an impact within the
  // substep can give one of them a new velocity.
  static bool closes_through(const Components& k, EntityId a, EntityId b, double t, double span, bool overlapped);
};

struct CcdStats {
  std::int64_t impacts = 0;          // impulses applied at a time of impact
  std::int64_t capped_substeps = 0;  // substeps that hit the impact budget (see Ccd::resolve)
};

class Ccd {
 public:
  // Resolves the impacts of the next h ms between the given bodies (the
  // Collision system's, in registration order), as described above. A
  // substep resolves at most 16·n + 128 impacts within any h/64 of it
  // (a stretch; without gravity, lossless impacts have a larger budget of
  // their own: ImpactBudget in ccd.cpp); past that (an inelastic
  // collapse in a resting stack, a light body squeezed between two heavy
  // ones, which takes ~π·sqrt(M/m) impacts) each body still to meet
  // something stops at its next impact for the rest of the substep, with the
  // velocity it has then (the gravity kick after it taken back), and the
  // others move on: no tunnelling, no energy gained, but time lost for the
  // stopped ones, counted in stats.capped_substeps (the headless summary's
  // `ccd: N substeps over budget`).
  // Each impact is reported to `events` (which keeps it only if enabled).
  // With a selection, only the pairs of a selected body are swept.
  // exact_motion: Move's motion is the exact integrator's (gravity_after_impact).
  void resolve(Components& k, std::span<const EntityId> entities, double h, Vector gravity, bool exact_motion,
               BroadPhase& broadphase, ContactEvents& events, const CcdSelection* selection = nullptr);

  // First time in [t0, t1] at which the boxes of c and b, moving at their
  // current velocities from their positions extrapolated to time 0
  // (`position + t·velocity`), start to touch while approaching; or, if they
  // already overlap at t0, t0 itself when they approach along the shortest
  // way out. Ties between the axes go to x, as in Collision::penetration.
  static std::optional<Impact> time_of_impact(const Components& k, EntityId c, EntityId b, double t0, double t1);

  CcdStats stats;

  // The work a stretch of lossless impacts may take without gravity:
  // elastic_work / n impacts with e = 1 and no friction, between bodies
  // finite or at rest (ImpactBudget in ccd.cpp).
  static constexpr std::int64_t elastic_work = 4'000'000;

 private:
  std::vector<Pair> pairs_;
};

}  // namespace physics
