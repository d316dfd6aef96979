#include "engine/slide.hpp"

#include <algorithm>

#include "engine/same_bits.hpp"

namespace physics {

void SlideIntegrator::start(const Components& k, bool needed) {
  if (needed) v_start_ = k.velocity;
  else v_start_.clear();
  sliders_.clear();
}

void SlideIntegrator::after_solver(const Components& k, std::span<const ContactConstraint> contacts,
                                   std::span<const FrictionRow> rows) {
  sliders_.clear();
  // No contact had friction (a frictionless contact keeps no tangential
  // impulse, so it makes no slider): then no look at every body. The
  // rounds' rows (ContactSolver::keep_round) are there, zero, for every
  // contact of a frictionless rain solved again.
  // (The browser's build, short of room, looks whenever there are rows.)
  if (keeps_unchanged ? std::none_of(rows.begin(), rows.end(), [](const FrictionRow& r) { return r.mu > 0.0; })
                      : rows.empty())
    return;
  touched_.assign(k.size(), 0);
  v_end_.resize(k.size());
  // (A contact's inverse masses say which end is fixed: inverse_mass() is 0
  // just for an infinite mass. Bit 32 marks a fixed body, never a slider.)
  const std::span<std::uint8_t> touched(touched_);
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const ContactConstraint& ct = contacts[i];
    // Against a finite body (one that moves with the slide) the shift is not taken: bit 4.
    const bool fixed = ct.wc == 0.0 || ct.wb == 0.0;
    const std::uint8_t bits = static_cast<std::uint8_t>((ct.axis < 2 ? 1 : 2) | (ct.resting && fixed ? 0 : 4) |
                                                        (rows[i].lambda + rows[i].lambda2 != 0.0 ? 8 : 0));
    touched[ct.c] |= bits | (ct.wc == 0.0 ? 32 : 0);
    touched[ct.b] |= bits | (ct.wb == 0.0 ? 32 : 0);
  }
  // The sliders: finite, with friction, no impact or finite support, their
  // normals on one axis. By id, each body once: a walk along the contacts,
  // which list each body several times, tested it at each one, with a
  // branch the processor mispredicted (this function: 7 % of the friction
  // pyramid's instructions, 9 % of its time; by id, 4 %). Their order does
  // not matter: each shift moves its own body.
  for (std::size_t e = 0; e < touched.size(); ++e) {
    const std::uint8_t t = touched[e];
    if ((t & (32 | 8 | 4)) != 8 || (t & 3) == 3) continue;
    v_end_[e] = k.velocity[e];
    sliders_.push_back(static_cast<EntityId>(e));
  }
}

void SlideIntegrator::shift(Components& k, double h) {
  for (const EntityId e : sliders_) {
    Vector& p = k.position[e];
    const Vector v = k.velocity[e], v0 = v_start_[e];
    const bool along_x = (touched_[e] & 3) == 2;
    if (along_x ? v.x != v_end_[e].x : v.y != v_end_[e].y) continue;  // CCD changed it since
    if (along_x) p.x -= 0.5 * h * (v.x - v0.x);
    else p.y -= 0.5 * h * (v.y - v0.y);
  }
  sliders_.clear();
}

}  // namespace physics
