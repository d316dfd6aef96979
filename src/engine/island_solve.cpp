#include "engine/island_solve.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "engine/contact.hpp"
#include "engine/contact_solver.hpp"

namespace physics {

namespace {

double normal_speed(const Components& k, const ContactConstraint& ct) {
  return Vector::dot(k.velocity[ct.c] - k.velocity[ct.b], axis_normal[ct.axis]);
}
// Rounding's share of a normal speed: an approach below it is no violation.
double slack(const Components& k, const ContactConstraint& ct) {
  const Vector a = k.velocity[ct.c], b = k.velocity[ct.b];
  return 1e-9 * (std::abs(a.x) + std::abs(a.y) + std::abs(b.x) + std::abs(b.y)) + 1e-300;
}

}  // namespace

bool IslandSolve::violated(const Components& k, const ContactConstraint& ct) const {
  return ct.target - normal_speed(k, ct) > slack(k, ct);
}

void IslandSolve::solve(Components& k, std::span<const ContactConstraint> contacts, std::span<ContactImpulse> impulses,
                        std::span<const FrictionRow> friction) {
  const auto free_pair = [&](const ContactConstraint& ct) { return ct.wc > 0.0 && ct.wb > 0.0; };
  if (std::none_of(contacts.begin(), contacts.end(),
                   [&](const ContactConstraint& ct) { return free_pair(ct) && violated(k, ct); }))
    return;
  // Islands of finite bodies. A contact with a fixed body or with friction
  // joins its island to one more node, `held` (k.size()): such islands are
  // left to the iterations (and shock propagation).
  const auto held = static_cast<EntityId>(k.size());
  islands_.resize(k.size() + 1);
  islands_.add(held);
  for (const ContactConstraint& ct : contacts) islands_.add(ct.c), islands_.add(ct.b);
  const auto find = [&](EntityId e) { return islands_.find(e); };
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const ContactConstraint& ct = contacts[i];
    const bool left = !free_pair(ct) || (!friction.empty() && friction[i].mu > 0.0);
    islands_.join(ct.c, ct.b);
    if (left) islands_.join(ct.b, held);
  }
  // The free islands' contacts, grouped by root (in their order within each).
  keys_.clear();
  for (std::size_t i = 0; i < contacts.size(); ++i)
    if (const EntityId root = find(contacts[i].c); root != find(held)) keys_.push_back(std::uint64_t{root} << 32 | i);
  std::sort(keys_.begin(), keys_.end());
  for (std::size_t from = 0, to = 0; from < keys_.size(); from = to) {
    bool any = false;
    for (to = from; to < keys_.size() && keys_[to] >> 32 == keys_[from] >> 32; ++to)
      any = any || violated(k, contacts[static_cast<std::uint32_t>(keys_[to])]);
    if (any && to - from <= max_contacts) solve_island(k, contacts, impulses, std::span(keys_).subspan(from, to - from));
  }
}

// The island (its contacts' indices in the low bits of `members`): A δ = r
// on the active contacts, the others' impulse dropped to 0, until no active
// one pulls and no other one approaches.
bool IslandSolve::solve_island(Components& k, std::span<const ContactConstraint> contacts,
                               std::span<ContactImpulse> impulses, std::span<const std::uint64_t> members) {
  const std::size_t m = members.size();
  const auto index = [&](std::size_t i) { return static_cast<std::uint32_t>(members[i]); };
  const auto member = [&](std::size_t i) -> const ContactConstraint& { return contacts[index(i)]; };
  for (std::size_t i = 0; i < m; ++i) {
    const ContactConstraint& ci = member(i);
    r_[i] = ci.target - normal_speed(k, ci);
    lambda_[i] = impulses[index(i)].lambda;
    tol_[i] = slack(k, ci);
    active_[i] = lambda_[i] > 0.0 || r_[i] > tol_[i];
    for (std::size_t j = 0; j < m; ++j) {
      const ContactConstraint& cj = member(j);
      const double w = (ci.c == cj.c ? ci.wc : 0.0) - (ci.c == cj.b ? ci.wc : 0.0) - (ci.b == cj.c ? ci.wb : 0.0) +
                       (ci.b == cj.b ? ci.wb : 0.0);
      a_[i][j] = w * Vector::dot(axis_normal[ci.axis], axis_normal[cj.axis]);
    }
  }
  for (std::size_t round = 0; round < 2 * m + 2; ++round) {
    if (!solve_active(m)) return false;
    // The most pulling active contact, else the first other one left approaching.
    std::size_t worst = m;
    double most = 0.0;
    for (std::size_t i = 0; i < m; ++i)
      if (active_[i] && lambda_[i] + delta_[i] < most) worst = i, most = lambda_[i] + delta_[i];
    for (std::size_t i = 0; i < m && worst == m; ++i) {
      if (active_[i]) continue;
      double left = r_[i];
      for (std::size_t j = 0; j < m; ++j) left -= a_[i][j] * delta_[j];
      if (left > tol_[i]) worst = i;
    }
    if (worst == m) {
      for (std::size_t i = 0; i < m; ++i) {
        const ContactConstraint& ct = member(i);
        apply_normal_impulse(k.velocity[ct.c], k.velocity[ct.b], axis_normal[ct.axis], delta_[i], ct.wc, ct.wb);
        impulses[index(i)].lambda = std::max(lambda_[i] + delta_[i], 0.0);
      }
      return true;
    }
    active_[worst] = !active_[worst];
  }
  return false;
}

// δ from A δ = r on the active rows and δ = -λ (no impulse left) on the
// others, as one system. A is J M^-1 J^T, symmetric and positive
// semi-definite: Gaussian elimination needs no pivoting, and a pivot of
// about 0 is a dependent contact (a singular system: given up). The pivot is
// compared with its row's own diagonal, which a light body dominates: along a
// light-between-heavy chain the eliminated pivot is about 2/M against 1/m, so
// past a mass ratio of about 1e9 the solve gives up too (the iterations'
// result stays), though the system is not singular.
bool IslandSolve::solve_active(std::size_t m) {
  std::array<std::array<double, max_contacts + 1>, max_contacts> s;
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t j = 0; j < m; ++j) s[i][j] = active_[i] ? a_[i][j] : i == j;
    s[i][m] = active_[i] ? r_[i] : -lambda_[i];
  }
  for (std::size_t c = 0; c < m; ++c) {
    if (!(s[c][c] > 1e-9 * (active_[c] ? a_[c][c] : 1.0))) return false;
    for (std::size_t r = c + 1; r < m; ++r) {
      const double f = s[r][c] / s[c][c];
      for (std::size_t x = c; x <= m; ++x) s[r][x] -= f * s[c][x];
    }
  }
  for (std::size_t c = m; c-- > 0;) {
    double v = s[c][m];
    for (std::size_t x = c + 1; x < m; ++x) v -= s[c][x] * delta_[x];
    delta_[c] = v / s[c][c];
  }
  return true;
}

}  // namespace physics
