// The exact velocity solve of a small free island, after Gauss-Seidel
// (the stable solver's relax stage).
//
// Sequential impulses carry, per iteration, only a light body's worth of
// impulse across it: a light block squeezed between two heavy ones that
// close on it (the stiff family's squeeze seed 24: mass ratio 2.4e4, e 0.27)
// gets the last contact's velocity each time, the heavy blocks barely slow
// down, close through it, and the order breaks. Shock propagation settles
// such chains only where they rest on a fixed body; between free bodies
// there is no immovable end, and momentum must be kept.
//
// So, where the iterations left a contact approaching faster than its target
// allows, the island of finite bodies it belongs to (joined by contacts,
// none with a fixed body, none with friction, at most max_contacts of them)
// is solved exactly: the contacts whose impulse is positive or whose target
// is violated are active, the linear system of their normal impulses
// (J M^-1 J^T δ = target - v_n) is solved directly, a contact whose total
// impulse would pull is dropped and one left approaching is added, until
// none does (an active-set method: a few rounds at most on a chain). The
// impulses are the contact law's (engine/contact.hpp), so momentum is kept
// exactly; a singular system, one too ill-conditioned (a chain past a mass
// ratio of about 1e9: solve_active()) or no convergence leaves the
// iterations' result.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/components.hpp"
#include "engine/union_find.hpp"

namespace physics {

struct ContactConstraint;  // engine/contact_solver.hpp, which holds an IslandSolve
struct ContactImpulse;
struct FrictionRow;

class IslandSolve {
 public:
  static constexpr std::size_t max_contacts = 16;

  // contacts and their impulses: the solver's after its first iterations
  // (the impulses that stop the impacts: restitution gives e times them
  // back); friction: the rows beside them (empty when no contact has friction).
  void solve(Components& k, std::span<const ContactConstraint> contacts, std::span<ContactImpulse> impulses,
             std::span<const FrictionRow> friction);

 private:
  bool violated(const Components& k, const ContactConstraint& ct) const;
  bool solve_island(Components& k, std::span<const ContactConstraint> contacts, std::span<ContactImpulse> impulses,
                    std::span<const std::uint64_t> members);
  bool solve_active(std::size_t m);
  UnionFind islands_;                       // over bodies, and `held` (solve)
  std::vector<std::uint64_t> keys_;         // root << 32 | contact, of the free islands' contacts
  // The island's system, by member: A = J M^-1 J^T, r = target - v_n, the
  // accumulated impulses, rounding's slack, the solution, the active set.
  std::array<std::array<double, max_contacts>, max_contacts> a_{};
  std::array<double, max_contacts> r_{}, lambda_{}, tol_{}, delta_{};
  std::array<bool, max_contacts> active_{};
};

}  // namespace physics
