#include "engine/stages.hpp"

#include <algorithm>
#include <cmath>

#include "engine/geometry.hpp"

namespace physics {

// The comments of the course's systems say why each step is what it is
// (course/systems/forces.cpp, move.cpp, collision.cpp); here only the code,
// kept identical to theirs.

void apply_forces(Components& c, std::span<const EntityId> bodies, double h, Vector gravity, Workers* workers) {
  workers_or_one(workers).for_ranges(bodies.size(), min_parallel_items, [&](int, std::size_t begin, std::size_t end) {
    for (const EntityId e : bodies.subspan(begin, end - begin)) {
      const double m = c.mass[e];
      if (!std::isfinite(m)) continue;
      const Vector f = c.sum_forces[e];
      const Vector a = Vector{f.x / m, f.y / m} + gravity;
      c.velocity[e] = c.velocity[e] + h * a;
      c.sum_forces[e] = Vector::zero();
    }
  });
}

void move_bodies(Components& c, std::span<const EntityId> bodies, double h, Workers* workers) {
  workers_or_one(workers).for_ranges(bodies.size(), min_parallel_items, [&](int, std::size_t begin, std::size_t end) {
    for (const EntityId e : bodies.subspan(begin, end - begin)) c.position[e] = c.position[e] + h * c.velocity[e];
  });
}

namespace {

// The shares N_c, N_b of the position correction (Collision::resolve's).
std::pair<double, double> correction_shares(const Components& k, EntityId c, EntityId b) {
  const double mc = k.mass[c], mb = k.mass[b];
  const double vc = Vector::norm(k.velocity[c]);
  const double vb = Vector::norm(k.velocity[b]);
  if (!std::isfinite(mb)) return {1.0, 0.0};
  if (!std::isfinite(mc)) return {0.0, 1.0};
  if (vc + vb == 0.0) return mb > mc ? std::pair{1.0, 0.0} : std::pair{0.0, 1.0};
  return {vc / (vc + vb), vb / (vc + vb)};
}

}  // namespace

bool resolve_pair(Components& k, EntityId c, EntityId b, Contact* out) {
  const double mc = k.mass[c];
  const double mb = k.mass[b];
  if (!std::isfinite(mc) && !std::isfinite(mb)) return false;

  const auto [s_pos, s] = minkowski_difference(k.position[c], k.box[c], k.position[b], k.box[b]);
  if (!contains_origin(s_pos, s)) return false;

  Vector n = penetration_vector(s_pos, s);
  const auto [nc, nb] = correction_shares(k, c, b);
  k.position[c] = k.position[c] + nc * n;
  k.position[b] = k.position[b] - nb * n;

  const Vector pen = n;
  n = Vector::normalize(n);
  const Vector v = k.velocity[c] - k.velocity[b];
  const double vn = Vector::dot(v, n);
  const bool approaching = vn < 0.0;
  double jn = 0.0, jt = 0.0;
  if (approaching) {
    const double e = std::min(k.restitution[c], k.restitution[b]);
    const double dv = -(1.0 + e) * vn;
    const double wc = inverse_mass(mc), wb = inverse_mass(mb);
    change_normal_velocity(k.velocity[c], k.velocity[b], n, dv, wc, wb);
    const double mu = pair_friction(k, c, b);
    if (mu > 0.0 || out) jn = dv / (wc + wb);
    if (mu > 0.0) jt = apply_friction(k.velocity[c], k.velocity[b], n, mu * jn, wc, wb);
  }
  if (out) *out = Contact{c, b, pen, n, approaching, jn, jt};
  return true;
}

std::size_t resolve_pairs(Components& k, BroadPhase::CoursePairs pairs, std::vector<Contact>* contacts) {
  std::size_t count = 0;
  for (const Pair p : pairs) {
    Contact contact;
    if (!resolve_pair(k, p.c, p.b, contacts ? &contact : nullptr)) continue;
    ++count;
    if (contacts) contacts->push_back(contact);
  }
  return count;
}

}  // namespace physics
