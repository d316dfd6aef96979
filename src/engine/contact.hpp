// The one contact type and the one contact law of the engine: every solver
// (the course's Collision pass, CCD, the stable solver) and the exact
// reference exchange normal impulses through apply_normal_impulse, with one
// inverse-mass convention (inverse_mass: 0 for a fixed body).
#pragma once

#include <array>
#include <cmath>
#include <utility>

#include "engine/components.hpp"

namespace physics {

// A contact between the bodies c and b, as found by a solver.
struct Contact {
  EntityId c, b;
  Vector penetration;  // moves c out of b (the shortest of the four vectors of the sheet's figure 2)
  Vector normal;       // unit, along penetration
  bool approaching;    // whether an impulse was applied (v·n < 0)
  double jn = 0.0;     // normal impulse applied (0 if not approaching)
  double jt = 0.0;     // tangential (friction) impulse applied, along tangent(normal)
};

// w = 1/M, and 0 for an infinite mass (a wall is not moved by any impulse).
inline double inverse_mass(double m) { return std::isfinite(m) ? 1.0 / m : 0.0; }

// The impulse j along the unit normal n (pointing from b to c): the sheet's
// v_c += n·j/M_c and v_b -= n·j/M_b, written with inverse masses.
inline void apply_normal_impulse(Vector& vc, Vector& vb, Vector n, double j, double wc, double wb) {
  vc = vc + (wc * j) * n;
  vb = vb - (wb * j) * n;
}

// The same along one axis: vc and vb are the bodies' velocity components
// along the normal's axis, `sign` the normal's (±1) along it. The values are
// apply_normal_impulse's for an axis normal, whose zero component only added
// ±0 to the other one (the stable solver's rows, ContactSolver::iterate).
inline void apply_axis_impulse(double& vc, double& vb, double sign, double j, double wc, double wb) {
  vc = vc + (wc * j) * sign;
  vb = vb - (wb * j) * sign;
}

// The same law given the change dv of the normal relative velocity instead
// of the impulse: j = dv / (w_c + w_b), applied as dv·w_c/(w_c + w_b) and
// dv·w_b/(w_c + w_b), which is exact when one body is fixed (ratio 1: a wall
// reverses the normal velocity bit for bit) or the masses are equal (1/2).
inline void change_normal_velocity(Vector& vc, Vector& vb, Vector n, double dv, double wc, double wb) {
  apply_normal_impulse(vc, vb, n, dv, wc / (wc + wb), wb / (wc + wb));
}

// The gravity in an impact's normal velocity, by how Move takes the body on.
// Forces gives the whole substep's kick a·h at its start; an impact at t
// (0 <= t <= h) reverses the normal velocity v_n, the position staying
// continuous at t (x + t·v), and Move then goes x += h·v. Of that kick, the
// part before t is reflected and the part after is not, which keeps the
// energy the time stepping keeps in free flight only with the right
// amount, a_n = a·n the pair's relative acceleration along the normal
// (g against a fixed body, 0 between two free ones):
//  - the course's symplectic Euler keeps ½v² - a·x + ½h a·v: the normal
//    velocity after the impact is -e·v_n + e·a_n·(h - 2t);
//  - the exact integrator (engine/integrator.hpp), which leaves a body that
//    met a contact unshifted, keeps ½v² - a·x to ½(a·h)²: -e·v_n + 2e·a_n·(h - t)
//    (at e = 1 the (1+e)·a_n·(h - t) this engine used for both).
// At t = 0 both let a body resting on the floor rest (it leaves at 0, no hop
// of g·h), and for e < 1 the energy only falls. The exact integrator's
// amount under symplectic Euler made every e = 1 bounce on the floor lose
// m·g·h·|v_n|: a ball dropped 460 px came back 15 px lower each bounce.
inline double gravity_after_impact(double e, double a_n, double h, double t, bool exact_motion) {
  return exact_motion ? 2.0 * e * a_n * (h - t) : e * a_n * (h - 2.0 * t);
}

// ---- Separation along the four axes ----

// The four normals of a box contact, in the tie order of the sheet's
// penetration vectors: 0: -x, 1: +x, 2: -y, 3: +y (the normal that moves c
// away from b).
inline constexpr Vector axis_normal[4] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};

// The gaps between the boxes of c and b along the four axes (negative:
// overlapping by that much along it).
inline std::array<double, 4> axis_gaps(Vector pc, Rect rc, Vector pb, Rect rb) {
  // The sums of Rect::mdiff, written out (the stable solver calls this per contact).
  const double sx = pb.x - pc.x - rc.width, sy = pb.y - pc.y - rc.height;
  return {sx, -(sx + (rb.width + rc.width)), sy, -(sy + (rb.height + rc.height))};
}
inline std::array<double, 4> axis_gaps(const Components& k, EntityId c, EntityId b) {
  return axis_gaps(k.position[c], k.box[c], k.position[b], k.box[b]);
}

// The separating axis with the largest gap; for overlapping boxes that is the
// shortest way out, with Collision::penetration's tie order (-x, +x, -y, +y).
inline std::pair<int, double> best_axis(const Components& k, EntityId c, EntityId b) {
  const std::array<double, 4> gaps = axis_gaps(k, c, b);
  int best = 0;
  for (int a = 1; a < 4; ++a)
    if (gaps[a] > gaps[best]) best = a;
  return {best, gaps[best]};
}

// The normal of a contact for a solver that keeps resting contacts (the
// stable solver's), and the gap along it; `separation` is best_axis's gap
// (the boxes' distance, what decides whether they are in contact at all).
// The shortest way out alone makes ghost collisions: a box resting on a
// floor of touching boxes sits `slop` deep in it, so the next floor box is
// nearer along x than along y, and a horizontal normal stops the box at the
// seam (in a slot that fits exactly, a vertical one stops a falling box on a
// wall box's top). Touching floors are exact only to rounding and the
// resting slop, so a gap within ±touch of 0 counts as touching: if the boxes
// touch along one axis only, they slide along that face, which is the
// normal (the other axis is either overlapping deeper, where best_axis says
// the same, or separated, and the box passes over the seam). If they touch
// along both (corner to corner: `corner`), the normal is the axis of the face
// contacts the two bodies have with others (`faces`, touching_face's bits:
// the floor box a box rests on, the wall it slides down), else the axis they
// move less along (a slide along x over a seam: y; a fall down a slot: x).
// Otherwise best_axis's, with its tie order.
struct ContactAxis {
  int axis;           // as best_axis's
  double gap;         // along axis (negative: overlap)
  double separation;  // best_axis's gap
  int separating;     // best_axis's axis
  bool corner;        // touching along both axes
};
// From the pair's gaps (axis_gaps) and relative velocity v_c - v_b.
inline ContactAxis contact_axis(const std::array<double, 4>& gaps, Vector v, double touch, int faces = 0) {
  const int ax = gaps[1] > gaps[0] ? 1 : 0, ay = gaps[3] > gaps[2] ? 3 : 2;
  const int best = gaps[ay] > gaps[ax] ? ay : ax;
  const bool tx = std::abs(gaps[ax]) <= touch, ty = std::abs(gaps[ay]) <= touch;
  int axis = best;
  if (tx != ty) {
    axis = tx ? ax : ay;
  } else if (tx && (faces == 1 || faces == 2)) {
    axis = faces == 1 ? ax : ay;
  } else if (tx) {
    if (std::abs(v.x) != std::abs(v.y)) axis = std::abs(v.x) < std::abs(v.y) ? ax : ay;
  }
  return {axis, gaps[axis], gaps[best], best, tx && ty};
}
inline ContactAxis contact_axis(const Components& k, EntityId c, EntityId b, double touch, int faces = 0) {
  return contact_axis(axis_gaps(k, c, b), k.velocity[c] - k.velocity[b], touch, faces);
}

// 1 if the boxes touch along x face to face (within ±touch along x,
// overlapping by more than touch along y), 2 the same along y, 0 otherwise:
// what contact_axis's `faces` collects over a body's pairs, from `a`, the
// pair's contact_axis without faces.
inline int touching_face(const ContactAxis& a, double touch) {
  if (a.corner || std::abs(a.gap) > touch || a.axis != a.separating) return 0;  // (else separated along the other)
  return a.axis < 2 ? 1 : 2;
}

// ---- Friction (beyond the sheet; docs/game-physics.md) ----

// A pair's coefficient: sqrt(mu_a mu_b), Box2D's mixing rule (so a
// frictionless body, mu = 0, slides on anything).
inline double pair_friction(double mu_a, double mu_b) { return std::sqrt(mu_a * mu_b); }
// The same for the bodies c and b: 0 without a square root when either has
// none (every pair of the sheet's scenes, on the solvers' hot paths).
inline double pair_friction(const Components& k, EntityId c, EntityId b) {
  return k.friction[c] > 0.0 && k.friction[b] > 0.0 ? pair_friction(k.friction[c], k.friction[b]) : 0.0;
}

// The unit tangent of a contact: the normal turned a quarter turn. Friction
// impulses are signed along it.
inline Vector tangent(Vector n) { return {-n.y, n.x}; }

// Coulomb's law after a normal impulse: the tangential impulse that stops
// the relative sliding along t if it needs at most `limit` = mu·|j_n|
// (sticking: applied as a velocity change, so a wall stops a block bit for
// bit), otherwise `limit` against the sliding. Returns the impulse applied.
inline double apply_friction(Vector& vc, Vector& vb, Vector n, double limit, double wc, double wb) {
  const Vector t = tangent(n);
  const double vt = Vector::dot(vc - vb, t);
  const double stop = -vt / (wc + wb);
  if (std::abs(stop) <= limit) {
    change_normal_velocity(vc, vb, t, -vt, wc, wb);
    return stop;
  }
  const double jt = stop > 0.0 ? limit : -limit;
  apply_normal_impulse(vc, vb, t, jt, wc, wb);
  return jt;
}

}  // namespace physics
