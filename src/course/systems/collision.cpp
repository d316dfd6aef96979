#include "course/systems/collision.hpp"

#include <algorithm>
#include <cmath>

namespace physics {

Vector Collision::penetration(Vector p, Rect s) {
  // Q8 begin
  // Q8 stub: // TODO Q8: s placed at p is the Minkowski difference b - c, which contains the
  // Q8 stub: // origin. Of the four vectors from the origin to its edges, (p.x, 0),
  // Q8 stub: // (p.x + s.width, 0), (0, p.y) and (0, p.y + s.height), return the shortest
  // Q8 stub: // (on a tie, the first in that order): the penetration vector n.
  // Q8 stub: (void)p, (void)s;
  // Q8 stub: return {};
  const Vector candidates[4] = {
      {p.x, 0.0}, {p.x + s.width, 0.0}, {0.0, p.y}, {0.0, p.y + s.height}};
  Vector best = candidates[0];
  double best_len = std::abs(p.x);
  for (int i = 1; i < 4; ++i) {
    const double len = std::abs(candidates[i].x) + std::abs(candidates[i].y);  // one is 0
    if (len < best_len) {
      best = candidates[i];
      best_len = len;
    }
  }
  return best;
  // Q8 end
}

bool Collision::resolve(Components& k, EntityId c, EntityId b, Contact* out) {
  // Q8 begin
  // Q8 stub: // TODO Q8: the sheet's detailed algorithm for the pair (c, b). Return false (and
  // Q8 stub: // change nothing) if both masses are infinite or if s = mdiff(c, b) does not have
  // Q8 stub: // the origin. Otherwise: n = penetration(s); move c by N_c x n and b by -N_b x n
  // Q8 stub: // (N_c, N_b: shares of the speeds; both at rest: the heavier ejects the lighter;
  // Q8 stub: // a body of infinite mass never moves); normalise n; if v = v_c - v_b approaches
  // Q8 stub: // (v . n < 0), apply j = -(1 + e)(v . n) / (1/M_c + 1/M_b) with
  // Q8 stub: // e = min(restitution of c, of b): v_c += n j / M_c, v_b -= n j / M_b
  // Q8 stub: // (engine/contact.hpp has change_normal_velocity and inverse_mass). If out is not
  // Q8 stub: // null, fill it: Contact{c, b, penetration, normalised n, approaching, j}. Return true.
  // Q8 stub: (void)k, (void)c, (void)b, (void)out;
  // Q8 stub: return false;
  const double mc = k.mass[c];
  const double mb = k.mass[b];
  // Two walls never collide (sheet: "deux murs ne font pas de collision").
  if (!std::isfinite(mc) && !std::isfinite(mb)) return false;

  const auto [s_pos, s] = Rect::mdiff(k.position[c], k.box[c], k.position[b], k.box[b]);
  if (!Rect::has_origin(s_pos, s)) return false;

  Vector n = penetration(s_pos, s);

  // Share the position correction in proportion to the speeds (N_c, N_b).
  // A fixed body is never moved, even a moving one (a platform): the sheet's
  // ratio would otherwise push a wall out of a block resting against it.
  const double vc = Vector::norm(k.velocity[c]);
  const double vb = Vector::norm(k.velocity[b]);
  double nc, nb;
  if (!std::isfinite(mb)) {
    nc = 1.0, nb = 0.0;
  } else if (!std::isfinite(mc)) {
    nc = 0.0, nb = 1.0;
  } else if (vc + vb == 0.0) {
    // Both at rest: the heavier ejects the lighter; equal masses: b moves.
    if (mb > mc) nc = 1.0, nb = 0.0;
    else nc = 0.0, nb = 1.0;
  } else {
    nc = vc / (vc + vb);
    nb = vb / (vc + vb);
  }
  k.position[c] = k.position[c] + nc * n;
  k.position[b] = k.position[b] - nb * n;

  const Vector pen = n;
  n = Vector::normalize(n);
  const Vector v = k.velocity[c] - k.velocity[b];
  const double vn = Vector::dot(v, n);
  // Only bodies that approach along n exchange an impulse. A pair already
  // separating (it was pushed apart last frame but still overlaps) gets the
  // position correction alone: applying j there would pull it back together.
  const bool approaching = vn < 0.0;
  double jn = 0.0, jt = 0.0;
  if (approaching) {
    // The pair's restitution is the smaller of the two materials': a body made
    // of clay stays dead whatever it hits. Default 1 (the sheet's e).
    const double e = std::min(k.restitution[c], k.restitution[b]);
    // The sheet's j = -(1+e)(v·n)/(1/M_c + 1/M_b) and v_c += n j/M_c,
    // v_b -= n j/M_b: the engine's one contact law (engine/contact.hpp),
    // given the change of normal velocity -(1+e)(v·n).
    //
    // The sheet says to add these changes to sum_forces; the course's
    // correction sets the velocities. We set them: they are velocity changes
    // (impulse / mass), not forces, and Forces would scale them by dt/m a
    // frame late. Setting them now also means a body touching two others in
    // one pass meets the second one with the velocity the first gave it
    // (sequential impulses), so nothing is counted twice.
    const double dv = -(1.0 + e) * vn;
    const double wc = inverse_mass(mc), wb = inverse_mass(mb);
    change_normal_velocity(k.velocity[c], k.velocity[b], n, dv, wc, wb);
    // Beyond the sheet: Coulomb friction, when both bodies have some
    // (engine/contact.hpp); without it the pair is the sheet's.
    const double mu = pair_friction(k, c, b);
    if (mu > 0.0 || out) jn = dv / (wc + wb);
    if (mu > 0.0) jt = apply_friction(k.velocity[c], k.velocity[b], n, mu * jn, wc, wb);
  }
  if (out) *out = Contact{c, b, pen, n, approaching, jn, jt};
  return true;
  // Q8 end
}

void Collision::update(Components& k, BroadPhase::CoursePairs pairs) {
  contacts_.clear();
  contact_count_ = 0;
  // Q8 begin
  // Q8 stub: // TODO Q8: for each pair (p.c, p.b) of `pairs`, call resolve; count the collisions
  // Q8 stub: // in contact_count_, and if record_contacts, push each Contact into contacts_.
  // Q8 stub: (void)k, (void)pairs;
  for (const Pair p : pairs) {
    Contact contact;
    if (!resolve(k, p.c, p.b, record_contacts ? &contact : nullptr)) continue;
    ++contact_count_;
    if (record_contacts) contacts_.push_back(contact);
  }
  // Q8 end
}

}  // namespace physics
