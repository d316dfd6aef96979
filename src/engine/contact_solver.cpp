#include "engine/contact_solver.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if PHYSICS_WIDE_ROWS  // (contact_solver.hpp)
#include <immintrin.h>
#endif

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <numeric>
#include <tuple>
#include <type_traits>

#include "engine/contact.hpp"
#include "engine/same_bits.hpp"
#include "course/utils/rect.hpp"

namespace physics {

namespace {

std::uint64_t key(EntityId c, EntityId b) { return Pair{c, b}.key(); }

// Whether a body of inverse mass w and velocity v links the contacts it is
// in (ContactSolver::schedule): any finite mass; a fixed body only when a
// component of its velocity is -0 (which a contact would turn to +0).
bool links(double w, const Vector& v) {  // (v read only for a fixed body)
  return w > 0.0 || (v.x == 0.0 && std::signbit(v.x)) || (v.y == 0.0 && std::signbit(v.y));
}

// Nonzero when a body's place (position and box) differs in any bit from the one kept.
std::uint64_t place_differs(Vector was_at, Rect was_box, Vector at, Rect box) {
  return bits_differ(was_at.x, at.x) | bits_differ(was_at.y, at.y) |
         static_cast<std::uint32_t>(was_box.width ^ box.width) |
         static_cast<std::uint32_t>(was_box.height ^ box.height);
}

// The contact law (engine/contact.hpp) on a contact's axis.
inline void apply(Components& k, const ContactConstraint& ct, double impulse) {
  apply_normal_impulse(k.velocity[ct.c], k.velocity[ct.b], axis_normal[ct.axis], impulse, ct.wc, ct.wb);
}

// Which body of a contact bears the other's weight: the one lying in the
// direction of gravity. 0: neither (side contact, or no gravity).
// +1: b is below c (c rests on b). -1: c is below b.
int support_sign(int axis, Vector g) {
  const double ng = Vector::dot(axis_normal[axis], g);
  if (ng < 0.0) return 1;   // n points up: c is above b
  if (ng > 0.0) return -1;  // n points down: b is above c
  return 0;
}

// A weight-bearing contact as the bottom-up pass reads it, for one
// direction of "down": its lower and upper body, which of them is fixed, and
// its index among the solver's contacts. shock_passes() makes these once per
// direction, so the passes below read a compact list, not the bodies' masses.
struct Support {
  EntityId lower, upper;
  bool lower_fixed, upper_fixed;
  std::uint32_t index;
};

// Depth in the support graph: fixed bodies are at 0, a body resting on a
// body of depth d is at d + 1; bodies resting on nothing fixed get `none`.
constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

// Whether the boxes of pair p overlap by more than the slop (what the position stage corrects).
bool overlaps(const Components& k, const Pair& p, double slop) { return best_axis(k, p.c, p.b).second < -slop; }

// By axis (-x, +x, -y, +y): the normal's sign, the tangent's (tangent(n) =
// (-n.y, n.x)), side by side: the friction rows load them as a pair.
struct AxisSigns {
  double normal, tangent;
};
constexpr AxisSigns axis_signs[4] = {{-1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}, {1.0, -1.0}};

// Breadth-first from the fixed bodies along the weight-bearing contacts
// (lower -> upper) finds the bodies that rest on something fixed; then each
// gets the length of its longest support chain (Kahn's order: a body once all
// its lower bodies have theirs), so that the bottom-up pass sets every lower
// body before the bodies on it. The shortest chain is not enough when g·h²
// exceeds a block's size: a stack's every block is then in a speculative
// contact with the floor through the blocks below, all at depth 1, and the
// pass skipped the contacts between them (the stack fell into the floor
// within a step and burst sideways). A body in a cycle of contacts (boxes
// that overlap as no stack does) keeps its shortest chain.
// O(bodies + contacts), where relaxing every contact until nothing changes
// costs contacts × stack height. `bodies`: the number of entities.
std::vector<std::uint32_t> support_depths(std::size_t bodies, std::span<const Support> contacts) {
  std::vector<std::uint32_t> depth(bodies, none);
  // The upper bodies of each lower one, as a compressed adjacency list (a
  // fixed upper body's depth stays 0: not listed).
  std::vector<std::uint32_t> start(bodies + 1, 0), upper_of;
  std::vector<EntityId> queue;
  for (const Support& ct : contacts)
    if (!ct.upper_fixed) ++start[ct.lower + 1];
  for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  upper_of.resize(start.back());
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (const Support& ct : contacts)
    if (!ct.upper_fixed) upper_of[fill[ct.lower]++] = ct.upper;
  for (const Support& ct : contacts) {
    if (ct.lower_fixed && depth[ct.lower] == none) depth[ct.lower] = 0, queue.push_back(ct.lower);
    if (ct.upper_fixed && depth[ct.upper] == none) depth[ct.upper] = 0, queue.push_back(ct.upper);
  }
  const std::size_t fixed = queue.size();
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const EntityId lower = queue[q];
    for (std::uint32_t a = start[lower]; a < start[lower + 1]; ++a) {
      const EntityId upper = upper_of[a];
      if (depth[upper] == none) depth[upper] = depth[lower] + 1, queue.push_back(upper);
    }
  }
  if (queue.size() == fixed) return depth;
  // The longest chains, over the bodies found (all of whose lower bodies are found too).
  std::vector<std::uint32_t> pending(bodies, 0), longest(bodies, 0);
  for (const EntityId lower : queue)
    for (std::uint32_t a = start[lower]; a < start[lower + 1]; ++a) ++pending[upper_of[a]];
  queue.resize(fixed);
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const EntityId lower = queue[q];
    for (std::uint32_t a = start[lower]; a < start[lower + 1]; ++a) {
      const EntityId upper = upper_of[a];
      longest[upper] = std::max(longest[upper], longest[lower] + 1);
      if (--pending[upper] == 0) queue.push_back(upper);
    }
  }
  for (std::size_t q = fixed; q < queue.size(); ++q) depth[queue[q]] = longest[queue[q]];
  return depth;
}

// Weight-bearing contacts whose lower body rests on the ground, lowest first
// (contacts of equal depth in their given order: a stable counting sort), by
// their indices among the solver's contacts.
std::vector<std::size_t> bottom_up(std::size_t bodies, std::span<const Support> contacts) {
  const auto anchors = [](const Support& ct) { return ct.lower_fixed || ct.upper_fixed; };
  if (std::none_of(contacts.begin(), contacts.end(), anchors)) return {};  // nothing rests on a fixed body
  const auto depth = support_depths(bodies, contacts);
  std::vector<std::size_t> order;
  std::vector<std::uint32_t> level;  // depth of each listed contact's lower body
  for (const Support& ct : contacts)
    if (depth[ct.lower] != none && depth[ct.lower] < depth[ct.upper])
      order.push_back(ct.index), level.push_back(depth[ct.lower]);
  std::uint32_t levels = 0;
  for (const std::uint32_t l : level) levels = std::max(levels, l + 1);
  std::vector<std::size_t> first(levels + 1, 0), sorted(order.size());
  for (const std::uint32_t l : level) ++first[l + 1];
  for (std::size_t l = 1; l <= levels; ++l) first[l] += first[l - 1];
  for (std::size_t i = 0; i < order.size(); ++i) sorted[first[level[i]]++] = order[i];
  return sorted;
}

// Body e's number in the order bodies are first met: ids[e] (by entity id,
// `none` until met), `met` the bodies met so far, in that order. The slots
// of schedule() and the support graph's numbers of renumber().
inline std::uint32_t number_as_met(EntityId e, std::vector<std::uint32_t>& ids, std::vector<EntityId>& met) {
  if (ids[e] == none) ids[e] = static_cast<std::uint32_t>(met.size()), met.push_back(e);
  return ids[e];
}

// The supports' bodies renumbered 0, 1, ... as first met, so that the
// support graph's tables are as long as the bodies in contacts, not as the
// world (a falling rain of 100 000 whose lowest rows land: 1.6 MB set to
// zero, fresh pages each time, for a few hundred contacts). `ids`: by entity
// id, `none` for every entity before and after. The passes read the
// contacts' indices only, so the order is the same for any numbering.
std::size_t renumber(std::span<Support> supports, std::vector<std::uint32_t>& ids, std::vector<EntityId>& met,
                     std::size_t entities) {
  ids.resize(entities, none);
  met.clear();
  for (Support& ct : supports)
    ct.lower = number_as_met(ct.lower, ids, met), ct.upper = number_as_met(ct.upper, ids, met);
  for (const EntityId e : met) ids[e] = none;
  return met.size();
}

// The directions of the bottom-up passes: gravity's, and both ways along
// each axis gravity has no component on. Along those, a fixed body anchors
// what presses on it as the floor does a stack: a light block between a
// heavy pusher and a wall, a row driven by an infinite-mass pusher
// (Gauss-Seidel alone carries a heavy body's push through a light one only
// at the light one's rate, and the projection's shares by inverse mass push
// the light one into the wall). The axes are independent (a contact's normal
// is along one), so the passes along x do not undo those along y. `ids`,
// `met`: renumber()'s scratch. ends(i): contact i's SupportEnds, read once,
// from its 12-byte key (a landing rain of 100 000 read its 64-byte contacts
// and both bodies' masses twice, 1.03 ms an order).
struct SupportEnds {
  EntityId c, b;
  std::uint8_t axis, fixed;  // fixed: bit 0, c is; bit 1, b is
};
// A contact's key (ContactSolver::TopologyKey: bodies, then flags with the
// axis in bits 0-1 and the fixed ends in bits 2-3, inverse mass 0 being an
// infinite or NaN mass) as shock_passes() reads it.
template <class Key>
SupportEnds support_ends(const Key& t) {
  return {t.c, t.b, static_cast<std::uint8_t>(t.flags & 3), static_cast<std::uint8_t>(t.flags >> 2 & 3)};
}
template <class Ends>
std::vector<ShockPass> shock_passes(std::size_t count, Ends&& ends, std::size_t entities, Vector g,
                                    std::vector<std::uint32_t>& ids, std::vector<EntityId>& met) {
  std::vector<Vector> downs;
  if (!Vector::is_zero(g)) downs.push_back(g);
  if (g.x == 0.0) downs.push_back({-1, 0}), downs.push_back({1, 0});
  if (g.y == 0.0) downs.push_back({0, -1}), downs.push_back({0, 1});
  // Along which axes a contact has a fixed end: a direction along no such
  // axis has nothing resting on a fixed body (bottom_up() would find no
  // anchor), and its supports are not listed (a pile's side contacts, most
  // of its contacts, when no wall holds it).
  std::vector<SupportEnds> all(count);
  std::array<bool, 2> anchored{};  // by component: x, y
  for (std::size_t i = 0; i < count; ++i) {
    all[i] = ends(i);
    if (all[i].fixed) anchored[all[i].axis >= 2] = true;
  }
  std::vector<ShockPass> out;
  std::vector<Support> supports;
  supports.reserve(count);
  for (const Vector down : downs) {
    // (support_sign's rule: a skewed gravity's direction takes either axis' anchors.)
    const auto anchors = [&](int axis) { return anchored[axis >= 2] && support_sign(axis, down) != 0; };
    if (!anchors(0) && !anchors(2)) continue;
    supports.clear();
    for (std::size_t i = 0; i < count; ++i) {
      const SupportEnds& ct = all[i];
      const int sign = support_sign(ct.axis, down);
      if (sign == 0) continue;
      const bool fc = ct.fixed & 1, fb = ct.fixed >> 1;
      const auto index = static_cast<std::uint32_t>(i);
      if (sign > 0) supports.push_back({ct.b, ct.c, fb, fc, index});
      else supports.push_back({ct.c, ct.b, fc, fb, index});
    }
    // (The browser's build, short of room, numbers them by entity id: the same order.)
    const std::size_t bodies = keeps_unchanged ? renumber(supports, ids, met, entities) : entities;
    const auto order = bottom_up(bodies, supports);
    if (order.empty()) continue;
    // Every listed contact's upper body is deeper than its lower one, so not fixed: the pass can move it.
    ShockPass& pass = out.emplace_back(ShockPass{.down = down, .rows = std::vector<ShockRow>(order.size())});
    for (std::size_t r = 0; r < order.size(); ++r) {
      const SupportEnds& ct = all[order[r]];
      pass.rows[r] = {ct.c, ct.b, static_cast<std::uint32_t>(order[r]), ct.axis, support_sign(ct.axis, down) > 0};
    }
  }
  return out;
}

}  // namespace

void ContactSolver::solve_velocities(Components& k, std::span<const EntityId> entities, double h, Vector g,
                                     const SolverSettings& s, BroadPhase& broadphase, StageTimes& times) {
  StageTimes::Laps laps(times);
  workers_ = s.workers;
  laps.time(Stage::pairs, [&] { broadphase.find(k, entities, h, s.margin, pairs_, PairRule::solvable, s.workers); });
  known_valid_ = false;
  for (const EntityId e : shifted_) line_start_[e] = 0.0;
  shifted_.clear();
  line_start_.resize(k.size(), 0.0);
  earlier_.clear();
  earlier_impulses_.clear();
  earlier_friction_.clear();
  earlier_jn_.clear();
  earlier_jt_.clear();
  for (int round = 0;; ++round) {
    last_round_ = s.rounds > 0 && round == s.rounds;
    laps.time(Stage::prepare, [&] {
      // Once per body and substep, not per contact end (a division each).
      if (round == 0) {
        inverse_mass_.resize(k.size());
        workers_or_one(s.workers).for_ranges(entities.size(), min_parallel_items, [&](int, std::size_t begin, std::size_t end) {
          for (const EntityId e : entities.subspan(begin, end - begin)) inverse_mass_[e] = inverse_mass(k.mass[e]);
        });
      }
      prepare(k, h, g, s);
    });
    // Later rounds start from velocities that hold this substep's impulses already.
    if (round == 0) laps.time(Stage::warm_start, [&] {
#if PHYSICS_HAS_THREADS
      // The plan takes longer than the warm start (the landing rain of
      // 100 000: 0.7 ms against 0.3): the guard's islands go beside it too,
      // which relax() would otherwise find on the thread of its rows.
      if (aside() && y_rows_unplanned())
        return beside(
            [&] {
              warm_start(k);
              if (!islands_found_) find_islands(k.size());
            },
            [&] { plan_y_rows(); });
#endif
      warm_start(k);
    });
    laps.time(Stage::relax, [&] { relax(k, g, s, false); });
    laps.time(Stage::restitution, [&] { restitution(k, g, s); });
    laps.time(Stage::impact_time, [&] { impact_time(k, h, g, s.exact_motion); });
    // With CCD on, it sweeps every pair after the solver: what the solve
    // turned towards each other is its business.
    if (!s.impacts || round == s.rounds) break;
    bool again = false;
    laps.time(Stage::pairs, [&] { again = turned_to_meet(k, entities, h, s, broadphase); });
    if (!again) break;
    keep_round();
  }
  laps.time(Stage::store, [&] { store(); });
  if (!earlier_.empty()) keep_round();
  velocity_finds_ = broadphase.finds();
}

// Contacts are the pairs whose boxes are closer than the margin along their
// separating axis, or will be within this substep (speculative). In two
// passes over ranges of the pairs (one per thread: Workers::for_ranges),
// so that each range knows where its contacts go: what each pair is, and
// how many of each a range has; then the contacts, written in place.
void ContactSolver::prepare(const Components& k, double h, Vector g, const SolverSettings& s) {
  // Slower than the speed gravity gives in two substeps: a resting contact,
  // not an impact, so no bounce (otherwise a block on the floor would hop).
  const double threshold = 2.0 * Vector::norm(g) * h + 1e-12;
  classify(k, h, threshold, s);
  islands_found_ = false;  // (this round's contacts are made below)
  const bool kept_all = keeps_unchanged && kept_all_;
  const std::uint8_t flags = kept_all ? keep_contacts() : make_contacts(k, h);
  moving_fixed_ = flags & 1;
  stats.contacts += static_cast<std::int64_t>(contacts_.size());
  prepare_friction(k, flags & 2, kept_all);
  // The rows of the last plain relaxation stay this one's when its contacts and their order are (schedule()
  // keeps the order when the contacts and gravity are the same).
  plain_rows_ = plain_rows_ && kept_all && scheduled_ && g == topology_g_;
  schedule(k, g, kept_all);
  // Velocities before any impulse, for the energy guard and the impact time.
  v_start_.resize(slot_body_.size());
  v_inelastic_.resize(slot_body_.size());
  workers_or_one(workers_).for_ranges(slot_body_.size(), min_parallel_items, [&](int, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) v_start_[i] = k.velocity[slot_body_[i]];
  });
}

// The contacts of the pairs classify() found within reach, with the lists
// of impacts and of pairs apart; the bits of make_contact(), ORed.
std::uint8_t ContactSolver::make_contacts(const Components& k, double h) {
  Workers& w = workers_or_one(workers_);
  const std::size_t n = pairs_.size();
  const RangeCount& all = counts_.back();
  contacts_.resize(all.contacts), impulses_.resize(all.contacts), pair_of_.resize(all.contacts);
  topology_next_.resize(all.contacts), impacts_.resize(all.impacts), apart_.resize(all.apart);
  contact_bits_.resize(all.contacts);
  // When every pair is what it was (same_kinds_), each contact is where it
  // was: an unchanged pair's (same bodies' state, same inputs) is kept, its
  // accumulators cleared as make_contact() clears them.
  const bool keep = keeps_unchanged && same_kinds_;
  return w.or_over_ranges(n, min_parallel_items, [&](int t, std::size_t begin, std::size_t end) {
    RangeCount at = counts_[static_cast<std::size_t>(t)];
    std::uint8_t bits = 0;
    for (std::size_t i = begin; i < end; ++i) {
      if (kinds_[i] == PairKind::apart) apart_[at.apart++] = static_cast<std::uint32_t>(i);
      if (kinds_[i] < PairKind::contact) continue;
      if (kinds_[i] == PairKind::impact) impacts_[at.impacts++] = static_cast<std::uint32_t>(at.contacts);
      const std::size_t j = at.contacts++;
      if (keep && !(changed_[pairs_[i].c] | changed_[pairs_[i].b])) {
        impulses_[j] = {};
        topology_next_[j] = topology_[j];
      } else {
        contact_bits_[j] = make_contact(k, i, h, j);
      }
      bits |= contact_bits_[j];
    }
    return bits;
  });
}

// When classify() kept every pair and every body as they were (kept_all_),
// the last preparation's contacts, lists and topology are this one's: only
// the accumulators are cleared, as make_contact() clears them.
std::uint8_t ContactSolver::keep_contacts() {
  const std::span<ContactImpulse> impulses(impulses_);
  const std::span<const std::uint8_t> contact_bits(contact_bits_);
  return workers_or_one(workers_).or_over_ranges(impulses.size(), min_parallel_items, [&](int, std::size_t begin, std::size_t end) {
    std::uint8_t bits = 0;
    for (std::size_t j = begin; j < end; ++j) impulses[j] = {}, bits |= contact_bits[j];
    return bits;
  });
}

// Each pair's axis (axes_) and what prepare() makes of it (kinds_), and
// how many of each kind each range of pairs has (counts_, then summed to
// where each range's go), in one pass over the pairs. Pairs that touch
// corner to corner, whose axes depend on their bodies' other pairs
// (contact_axes()), and a later round's physical axes take a second pass.
//
// A pair of the list last classified whose two bodies are unchanged since
// (changed_since_classified()) keeps what that classification made of it:
// the same inputs, the same bits. A resting pile's pairs are nearly all
// such (many_pyramids: all but 20 of 2.18 million body substeps), and the
// pass is then one test a pair. A corner pair's axis depends on its
// bodies' other pairs too: corner_axes() takes it again when one of them
// changed.
void ContactSolver::classify(const Components& k, double h, double threshold, const SolverSettings& s) {
  Workers& w = workers_or_one(workers_);
  const std::size_t n = pairs_.size();
  // physical_axes() overwrites a later round's axes with others than these inputs give.
  const bool physical = s.physical_axes && !shifted_.empty();
  const ClassifyInputs inputs{h, threshold, s.margin, s.touch};
  const bool reuse = keeps_unchanged && classified_ && s.impacts && !physical && inputs == classified_for_ &&
                     std::equal(pairs_.begin(), pairs_.end(), classified_pairs_.begin(), classified_pairs_.end());
  if constexpr (keeps_unchanged) changed_since_classified(k);
  // No body changed either (a resting pile, most substeps): every pair's
  // axis, kind and count is the last call's.
  kept_all_ = reuse && !any_changed_ && counts_.size() == static_cast<std::size_t>(w.threads()) + 1;
  if (kept_all_) {
    same_kinds_ = true;
    return;
  }
  overlap_known_ = false;
  axes_.resize(n);
  kinds_.resize(n);
  normal_speeds_.resize(n);
  counts_.assign(static_cast<std::size_t>(w.threads()) + 1, {});
  // Bit 0: a pair touches corner to corner; bit 1: a pair's kind is not the one it had.
  const auto range = [&](int t, std::size_t begin, std::size_t end, auto with_axes) {
    RangeCount c;
    bool corner = false, moved = false;
    for (std::size_t i = begin; i < end; ++i) {
      const bool same = reuse && !(changed_[pairs_[i].c] | changed_[pairs_[i].b]);
      PairKind kind = kinds_[i];
      // (The second pass: the corner pairs whose axes corner_axes() took again.)
      if (!same || (!with_axes && axes_[i].corner && ((faces_[pairs_[i].c] | faces_[pairs_[i].b]) & tainted))) {
        if constexpr (with_axes) corner = plain_axis(k, i, s.touch) || corner;
        const PairKind was = kind;
        kind = kinds_[i] = pair_kind(k, i, h, threshold, s);
        moved = moved || kind != was;
      } else if constexpr (with_axes) {
        corner = axes_[i].corner || corner;
      }
      c.apart += kind == PairKind::apart;
      c.contacts += kind >= PairKind::contact;
      c.impacts += kind == PairKind::impact;
    }
    counts_[static_cast<std::size_t>(t) + 1] = c;
    return static_cast<std::uint8_t>(corner | moved << 1);
  };
  const std::uint8_t first = w.or_over_ranges(n, min_parallel_items, [&](int t, std::size_t begin, std::size_t end) {
    return range(t, begin, end, std::true_type{});
  });
  std::uint8_t second = 0;
  if ((first & 1) || physical) {
    if (first & 1) corner_axes(k, s, keeps_unchanged && reuse);
    physical_axes(k, s);
    second = w.or_over_ranges(n, min_parallel_items, [&](int t, std::size_t begin, std::size_t end) {
      return range(t, begin, end, std::false_type{});
    });
  }
  same_kinds_ = reuse && !((first | second) & 2);
  for (std::size_t t = 1; t <= static_cast<std::size_t>(w.threads()); ++t)
    counts_[t].apart += counts_[t - 1].apart, counts_[t].contacts += counts_[t - 1].contacts,
        counts_[t].impacts += counts_[t - 1].impacts;
  if constexpr (!keeps_unchanged) return;
  classified_ = !physical && s.impacts;
  classified_for_ = inputs;
  if (!reuse) classified_pairs_.assign(pairs_.begin(), pairs_.end());  // (reuse: they are equal)
}

// changed_: for each body of a pair, whether what prepare() reads of it
// (position, velocity, box, mass, restitution, friction) differs (bits)
// from when it was last classified; then its state kept for the next call.
// With fewer pairs than bodies, bodies in no pair are not looked at (a
// falling rain's are most): a pair of the list classified last has both its
// bodies' states from that call.
void ContactSolver::changed_since_classified(const Components& k) {
  const std::size_t n = k.size(), known = std::min(n, classified_bodies_.size());
  changed_.resize(n);
  classified_bodies_.resize(n);
  visited_.resize(n, 0);
  if (++visit_ == 0) std::fill(visited_.begin(), visited_.end(), 0), visit_ = 1;
  // (Spans, not the vectors: the byte stores could alias their pointers, reloaded at every body.)
  const std::span<const Vector> position(k.position), velocity(k.velocity);
  const std::span<const Rect> boxes(k.box);
  const std::span<const double> mass(k.mass), restitution(k.restitution), friction(k.friction);
  const std::span<ClassifiedBody> bodies(classified_bodies_);
  const std::span<std::uint8_t> changed(changed_);
  const std::span<std::uint32_t> visited(visited_);
  const auto look = [&](std::size_t e) {
    ClassifiedBody& was = bodies[e];
    const Vector p = position[e], v = velocity[e];
    const Rect box = boxes[e];
    const double m = mass[e], r = restitution[e], f = friction[e];
    const std::uint64_t differ = place_differs(was.position, was.box, p, box) | bits_differ(was.velocity.x, v.x) |
                                 bits_differ(was.velocity.y, v.y) | bits_differ(was.mass, m) |
                                 bits_differ(was.restitution, r) | bits_differ(was.friction, f);
    changed[e] = e >= known || differ != 0;
    if (changed[e]) was = {p, v, box, m, r, f};
  };
  Workers& w = workers_or_one(workers_);
  // A pile has several pairs a body: then every body, in ranges, without the marks.
  if (pairs_.size() < n) {
    // On a team, each thread looks at the bodies of a range of ids, going
    // over every pair: a body is looked at once, by one thread (a forming
    // pile of 100 000: 0.9 ms a call on one thread, 1.7 calls a step).
    const std::span<const Pair> pairs(pairs_);
    const std::size_t ranges = w.splits(pairs.size(), min_parallel_items) ? static_cast<std::size_t>(w.threads()) : 1;
    const std::array<EntityId, max_threads + 1> cut = id_cuts(pairs, ranges);
    // (One item a range of ids: the team splits them from two.)
    any_changed_ = w.or_over_ranges(ranges, 2, [&](int, std::size_t begin, std::size_t end) {
      std::uint8_t any = 0;
      for (std::size_t t = begin; t < end; ++t)
        for (const Pair& p : pairs)
          for (const EntityId e : {p.c, p.b})
            if (e >= cut[t] && e < cut[t + 1] && visited[e] != visit_) visited[e] = visit_, look(e), any |= changed[e];
      return any;
    }) != 0;
    return;
  }
  any_changed_ = w.or_over_ranges(n, min_parallel_items, [&](int, std::size_t begin, std::size_t end) {
    std::uint8_t any = 0;
    for (std::size_t e = begin; e < end; ++e) look(e), any |= changed[e];
    return any;
  });
}

// Where `ranges` ranges of ids start (changed_since_classified(), one a
// thread), then the end (above every id): at quantiles of (a sample of) the
// pairs' second bodies, so that each range has about as many (their first
// bodies are often a floor's, all one id).
std::array<EntityId, max_threads + 1> ContactSolver::id_cuts(std::span<const Pair> pairs, std::size_t ranges) {
  std::array<EntityId, max_threads + 1> cut{};
  constexpr std::size_t stride = 8;
  std::vector<EntityId>& sample = cut_sample_;
  sample.clear();
  for (std::size_t i = 0; ranges > 1 && i < pairs.size(); i += stride) sample.push_back(pairs[i].b);
  for (std::size_t t = 1; t < ranges; ++t) {
    const auto nth = sample.begin() + static_cast<std::ptrdiff_t>(sample.size() * t / ranges);
    std::nth_element(sample.begin(), nth, sample.end());
    cut[t] = std::max(cut[t - 1], *nth);  // (in order: the ranges must not overlap)
  }
  cut[ranges] = std::numeric_limits<EntityId>::max();
  return cut;
}

// What prepare() makes of pair i (its axis in axes_); keeps its normal speed.
inline ContactSolver::PairKind ContactSolver::pair_kind(const Components& k, std::size_t i, double h, double threshold,
                                                 const SolverSettings& s) {
  const Pair& p = pairs_[i];
  const auto [axis, gap, separation, separating, corner] = axes_[i];
  const Vector v = k.velocity[p.c] - k.velocity[p.b];
  // Speculative: a pair further apart than the margin is a contact only if
  // it closes the gap within this substep.
  if (separation > s.margin && separation + Vector::dot(v, axis_normal[separating]) * h > 0.0) return PairKind::apart;
  const Vector n = axis_normal[axis];
  const double vn = normal_speeds_[i] = Vector::dot(v, n);
  const bool impact = vn < -threshold && gap + vn * h <= 0.0;
  if (!s.impacts && left_to_ccd(s, p, n, impact, gap + vn * h <= 0.0 && gap > s.touch)) return PairKind::left;
  return impact ? PairKind::impact : PairKind::contact;
}

// Contact j, of pair i (pair_kind: contact or impact). Returns bit 0: a
// fixed body of it moves; bit 1: it has friction.
inline std::uint8_t ContactSolver::make_contact(const Components& k, std::size_t i, double h, std::size_t j) {
  const Pair& p = pairs_[i];
  const auto [axis, gap, separation, separating, corner] = axes_[i];
  const double vn = normal_speeds_[i];
  const double wc = inverse_mass_[p.c], wb = inverse_mass_[p.b];
  // (The bodies' velocities are read again only for a fixed one.)
  const bool moving_fixed = (wc == 0.0 && !Vector::is_zero(k.velocity[p.c])) ||
                            (wb == 0.0 && !Vector::is_zero(k.velocity[p.b]));
  // Each field written in place: a whole contact built aside and copied in
  // was read back in 16-byte loads from narrower stores (a store-forwarding
  // stall: 10 % of the pyramid's step, perf annotate).
  ContactConstraint& ct = contacts_[j];
  ct.c = p.c, ct.b = p.b, ct.axis = axis, ct.wc = wc, ct.wb = wb, ct.inv_w = 1.0 / (wc + wb);
  impulses_[j] = {};
  if (kinds_[i] == PairKind::impact) {
    // A real impact this substep: stopped here (target 0), then bounced by
    // e times the stopping impulse once the iterations are done.
    ct.restitution = std::min(k.restitution[p.c], k.restitution[p.b]);
    ct.resting = false;
    ct.target = 0.0;
    ct.toi = gap > 0.0 ? gap / -vn : 0.0;
  } else {
    // Close at most the gap (a speculative contact), never approach once touching.
    ct.restitution = ct.toi = 0.0;
    ct.resting = true;
    ct.target = gap > 0.0 ? -gap / h : 0.0;
  }
  pair_of_[j] = static_cast<std::uint32_t>(i);
  const std::uint32_t flags = static_cast<std::uint32_t>(axis) | (wc == 0.0) << 2 | (wb == 0.0) << 3 |
                              links(wc, k.velocity[p.c]) << 4 | links(wb, k.velocity[p.b]) << 5;
  topology_next_[j] = {p.c, p.b, flags};
  return static_cast<std::uint8_t>(moving_fixed | (pair_friction(k, p.c, p.b) > 0.0) << 1);
}

// With CCD on, a pair apart and not closing before Forces, whose kick closes
// it within the substep (a hop's top under gravity, a block let go just above
// another), is CCD's too, although slower than an impact: as a speculative
// contact it would stop at the gap without a bounce and arrive at the
// substep's end still moving at the gap's speed, which the next substep's
// impact gives back upward with gravity's kick added: an e = 1 block hopping
// on the floor gained 8.3e-7 of the energy in play (the family's ratio-stack
// seed 27, under stable+ccd and auto). CCD takes it at its instant.
// A tile strip gather_tiles() made in this substep, after the copy, has no
// velocity before Forces there: its pair stays the solver's.
bool ContactSolver::turned_by_forces(const SolverSettings& s, const Pair& p, Vector n) {
  const std::span<const Vector> v = s.before_forces;
  if (p.c >= v.size() || p.b >= v.size()) return false;
  return Vector::dot(v[p.c] - v[p.b], n) >= 0.0;
}

// With CCD on, impacts are its business: it finds each one's exact time and
// resolves chains of them one after the other (a cradle), and so are the
// pairs Forces turned to close within the substep (above). The solver keeps
// the resting contacts, which CCD alone cannot hold.
bool ContactSolver::left_to_ccd(const SolverSettings& s, const Pair& p, Vector n, bool impact, bool closes_apart) {
  return impact || (closes_apart && turned_by_forces(s, p, n));
}

// A contact is a pair close or closing at the start of the substep
// (prepare()), but the solve can turn a body round towards a neighbour it
// was leaving: a light block bouncing off a wall goes back into the heavy
// pusher behind it, or the pusher's impact sends it into the wall. That pair
// had no contact, so its bodies moved into each other for the whole substep
// (|v|·h: 8 to 25 px at 0.5 to 1.4 px/ms), and the position projection,
// which shares a correction by inverse mass, then pushed the light block back
// through where it had been and into the wall, which was no position contact
// either (push-into-wall: 1.7 to 4.2 px deep, once 26 px and out; at e = 1
// the light block passed through the pusher). So after a solve, if some pair
// that was not a contact now closes within the substep, the substep's
// contacts are taken again from the velocities and positions the solve left
// (impact_time has put each impacted body where its new line starts) and
// solved again, one round after the other as CCD takes impacts in turn, at
// most `rounds` times: the second impact is a bounce of its own, so an
// elastic gas keeps its energy (solving both at once, the one found later
// took no bounce: 7 % lost in 600 frames). The last round takes no bounce,
// so that what still meets then is stopped rather than sent on into
// something else. The pairs looked at are the ones found, and, if the solve
// sent some body `margin` or more beyond the box it swept, those the broad
// phase finds for the new velocities (added to pairs_ for the next round).
// A substep whose solve turns nothing round is one round, as before.
bool ContactSolver::turned_to_meet(const Components& k, std::span<const EntityId> entities, double h,
                                   const SolverSettings& s, BroadPhase& broadphase) {
  // prepare()'s test, at the positions impact_time left.
  const auto closes = [&](const Pair& p) {
    const auto [separating, separation] = best_axis(k, p.c, p.b);
    const Vector v = k.velocity[p.c] - k.velocity[p.b];
    return !(separation > s.margin && separation + Vector::dot(v, axis_normal[separating]) * h > 0.0);
  };
  bool any = std::any_of(apart_.begin(), apart_.end(), [&](std::uint32_t i) { return closes(pairs_[i]); });
  if (!swept_further(k, h, s.margin)) return any;
  // Only the solver's bodies changed since the last find (this substep's).
  broadphase.find_again(k, entities, slot_body_, h, s.margin, later_, PairRule::solvable, s.workers);
  const std::size_t added = pairs_.size();
  add_unknown_pairs();
  return any || std::any_of(pairs_.begin() + static_cast<std::ptrdiff_t>(added), pairs_.end(), closes);
}

// Appends to pairs_ the pairs of later_ it does not hold, in later_'s order.
// pairs_' keys are sorted once a substep (known_) and kept so with the pairs
// added: sorting them at every round took 8 % of the 10 000-body rain. The
// broad phase lists pairs by key when the bodies are registered in id order:
// then a walk along both lists, else a search each.
void ContactSolver::add_unknown_pairs() {
  if (!known_valid_) {
    known_.clear();
    for (const Pair& p : pairs_) known_.push_back(p.key());
    if (!keeps_unchanged || !std::is_sorted(known_.begin(), known_.end())) std::sort(known_.begin(), known_.end());
    known_valid_ = true;
  }
  // (The browser's build, short of room, always searches: the same pairs.)
  const bool ordered =
      keeps_unchanged && std::is_sorted(later_.begin(), later_.end(), [](Pair a, Pair b) { return a.key() < b.key(); });
  const std::size_t before = known_.size();
  std::size_t at = 0;
  for (const Pair& p : later_) {
    const std::uint64_t key = p.key();
    if (ordered) {
      while (at < before && known_[at] < key) ++at;
      if (at < before && known_[at] == key) continue;
    } else if (std::binary_search(known_.begin(), known_.begin() + static_cast<std::ptrdiff_t>(before), key)) {
      continue;
    }
    pairs_.push_back(p);
    known_.push_back(key);
  }
  const auto mid = known_.begin() + static_cast<std::ptrdiff_t>(before);
  if (!ordered) std::sort(mid, known_.end());
  std::inplace_merge(known_.begin(), mid, known_.end());
}

// Whether the solve sent some body of a contact `reach` or more beyond the
// box it swept at its starting velocity: only then can it meet a body the
// broad phase did not pair it with (each box was grown by `reach`).
// On a team the first range to find one stops the others at their next look
// (`found`, every 1 024 bodies): a landing's first range mostly finds one at
// once, and the other then scanned its whole range (45 us a call).
bool ContactSolver::swept_further(const Components& k, double h, double reach) const {
  const auto beyond = [&](double v0, double v1) {
    return std::max(std::min(v0, 0.0) - std::min(v1, 0.0), std::max(v1, 0.0) - std::max(v0, 0.0)) * h >= reach;
  };
  std::atomic<bool> found{false};
  return workers_or_one(workers_).or_over_ranges(slot_body_.size(), min_parallel_items, [&](int, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      if (has_threads && i % 1024 == 0 && found.load(std::memory_order_relaxed)) return std::uint8_t{1};
      const Vector v0 = v_start_[i], v1 = k.velocity[slot_body_[i]];
      if (!beyond(v0.x, v1.x) && !beyond(v0.y, v1.y)) continue;
      if (has_threads) found.store(true, std::memory_order_relaxed);
      return std::uint8_t{1};
    }
    return std::uint8_t{0};
  }) != 0;
}

// A round's contacts, kept when the substep is solved again: constraints()
// gives every round's (auto and the contact events read each impulse of
// the substep), and the resting impulses of the rounds add up, by pair, in
// what the next substep's warm start reads (store()).
void ContactSolver::keep_round() {
  earlier_jn_.resize(pairs_.size(), 0.0);
  earlier_jt_.resize(pairs_.size(), 0.0);
  // (Copied into the grown lists, not inserted: std::vector's range insert
  // took 1.7 KB more of the browser's module than this.)
  const std::size_t at = earlier_.size(), n = contacts_.size();
  earlier_.resize(at + n), earlier_impulses_.resize(at + n), earlier_friction_.resize(at + n);
  std::copy(contacts_.begin(), contacts_.end(), earlier_.begin() + static_cast<std::ptrdiff_t>(at));
  std::copy(impulses_.begin(), impulses_.end(), earlier_impulses_.begin() + static_cast<std::ptrdiff_t>(at));
  std::copy(friction_.begin(), friction_.end(), earlier_friction_.begin() + static_cast<std::ptrdiff_t>(at));
  // (A round has one contact a pair at most, make_contacts(): each range adds to its own pairs'.)
  workers_or_one(workers_).for_ranges(n, min_parallel_items, [&](int, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      if (!contacts_[i].resting) continue;
      earlier_jn_[pair_of_[i]] += impulses_[i].lambda + impulses_[i].lambda2;
      if (!friction_.empty()) earlier_jt_[pair_of_[i]] += friction_[i].lambda + friction_[i].lambda2;
    }
  });
}

// A resting contact that was there last substep starts with the impulse it
// ended with (a stack's weight is then carried from the start). When the
// contacts are those of last substep, in the same order (schedule(): a
// resting pile), contact i's impulse is last substep's i-th. The contacts
// that are not resting are the impacts, in order (make_contacts()): a merge
// with their list, so that the pass reads no contact (warm_start_one).
void ContactSolver::warm_start(Components& k) {
  // (The browser's build, short of room, always searches: the same impulses.)
  if (!keeps_unchanged || restored_ || !same_topology_) {
    warm_start_search(k);
    return;
  }
  auto impact = impacts_.begin();
  for (std::size_t i = 0; i < last_jn_.size(); ++i) {
    const bool resting = impact == impacts_.end() || *impact != i;
    impact += !resting;
    if (last_jn_[i] > 0.0 && resting) warm_start_one(k, i, last_jn_[i], last_jt_[i]);
  }
}

// Otherwise each contact's impulse is looked up by pair and axis in the
// sorted list. Contacts mostly come in the order of the list (pairs in
// registration order, ids mostly registered in increasing order), so each
// search starts where the last one ended when it can: a merge, not a binary
// search from scratch per contact.
void ContactSolver::warm_start_search(Components& k) {
  if (!restored_) last_impulses(topology_next_, warm_);
  restored_ = false;
  auto from = warm_.begin();
  for (ContactConstraint& ct : contacts_) {
    if (!ct.resting) continue;
    const auto kk = key(ct.c, ct.b);
    const auto probe = std::make_tuple(kk, ct.axis, -infinity, -infinity);
    if (!keeps_unchanged || (from != warm_.begin() && !(*std::prev(from) < probe))) from = warm_.begin();
    // Galloping: the answer is usually a step or two ahead. (The browser's
    // build, short of room, searches the whole list: the same answer.)
    auto hi = keeps_unchanged ? from : warm_.end();
    for (std::ptrdiff_t step = 1; keeps_unchanged && hi != warm_.end() && *hi < probe; step *= 2) {
      from = std::next(hi);
      hi = step < warm_.end() - hi ? hi + step : warm_.end();
    }
    const auto it = std::lower_bound(from, hi, probe);
    from = it;
    if (it != warm_.end() && std::get<0>(*it) == kk && std::get<1>(*it) == ct.axis)
      warm_start_one(k, static_cast<std::size_t>(&ct - contacts_.data()), std::get<2>(*it), std::get<3>(*it));
  }
}

// Contact i starts with the normal impulse jn and the tangential jt. Its
// bodies and axis read from its key (topology_, 12 bytes, not its 64-byte
// contact: a settled rain of 100 000 spent 8 % of its step waiting for
// those), its inverse masses from its bodies' (the contact's are those).
void ContactSolver::warm_start_one(Components& k, std::size_t i, double jn, double jt) {
  const TopologyKey& ct = topology_[i];
  const Vector n = axis_normal[ct.flags & 3];
  const double wc = inverse_mass_[ct.c], wb = inverse_mass_[ct.b];
  impulses_[i].lambda = jn;
  apply_normal_impulse(k.velocity[ct.c], k.velocity[ct.b], n, jn, wc, wb);
  if (friction_.empty()) return;
  FrictionRow& f = friction_[i];
  // Within the cone of this substep's start (mu may be 0 for a pair that had none).
  f.lambda = std::clamp(jt, -f.mu * jn, f.mu * jn);
  if (f.lambda != 0.0) apply_normal_impulse(k.velocity[ct.c], k.velocity[ct.b], tangent(n), f.lambda, wc, wb);
}

// Sequential impulses with accumulated clamping, then the bottom-up pass.
// `after_bounce`: the same on the velocities the restitution left, with
// fresh accumulators and no approach allowed at the impacts (load_rows();
// the iterations do not read it). The support order depends only on the
// contacts, not on velocities: both relaxations share it.
void ContactSolver::relax(Components& k, Vector g, const SolverSettings& s, bool after_bounce) {
#if PHYSICS_HAS_THREADS
  const bool plan = y_rows_unplanned();  // (asked on the team: beside the order, this thread has none)
#endif
  const auto rows = [&] {  // loaded, swept, stored
#if PHYSICS_HAS_THREADS
    if (plan) plan_y_rows();
#endif
    load_rows(k, after_bounce);
    if (friction_.empty())
      iterate<false>(s);
    else
      iterate<true>(s);
    store_rows(k, after_bounce);
  };
  const auto order = [&] {
    const auto ends = [&](std::size_t i) { return support_ends(topology_[i]); };  // (this substep's: schedule())
    support_order_ = shock_passes(contacts_.size(), ends, k.size(), g, support_ids_, support_met_), have_order_ = true;
  };
  if (s.shock_propagation && !have_order_ && aside()) {
    // The rows on this thread while the helper makes the order, and the
    // guard's islands by whichever is done first (the landing rain of
    // 100 000: an order 0.85 ms, the sweeps 0.53, a new plan of the y rows
    // with them 0.38).
    std::atomic<bool> islands_taken{islands_found_};
    const auto islands = [&] {
      if (!islands_taken.exchange(true)) find_islands(k.size());
    };
    beside([&] { rows(), islands(); }, [&] { order(), islands(); });
    ++stats.orders_beside;
  } else {
    rows();
  }
  if (!after_bounce && Vector::is_zero(g)) {
    islands_solve_.solve(k, contacts_, impulses_, friction_);
    axis_at_targets_ = {};  // (the velocities are the islands' now)
  }
  if (!s.shock_propagation) return;
  if (!have_order_) order();
  const std::span<Vector> velocity(k.velocity);
  const std::span<const double> targets(targets_);
  bool tame = false;  // (skips_pass(): asked once until a pass runs)
  for (const ShockPass& pass : support_order_) {
    if (skips_pass(k, pass.down, tame)) continue;
    tame = false;
    for (const ShockRow& r : pass.rows) {
      const Vector n = axis_normal[r.axis];
      const double target = targets[r.index];  // this relaxation's (load_rows)
      const double vn = Vector::dot(velocity[r.c] - velocity[r.b], n);
      if (vn >= target) continue;
      // The lower body is immovable for this pass: the upper takes it all.
      if (r.c_upper)
        velocity[r.c] = velocity[r.c] + (target - vn) * n;
      else
        velocity[r.b] = velocity[r.b] - (target - vn) * n;
    }
  }
}

template <class Here, class Helper>
void ContactSolver::beside(Here&& here, Helper&& helper) {
  struct Alone {  // here() on this thread alone (no team for it to wake), the team back after
    Workers*& workers;
    Workers* const team = std::exchange(workers, nullptr);
    ~Alone() { workers = team; }
  } alone{workers_};
  alone.team->side_by_side(here, helper);
}

// Whether the bottom-up pass along `down` would change nothing: every row
// it lists is along an axis whose relaxation ended with its rows at or above
// their targets (axis_at_targets_), so each row finds vn >= target and
// leaves its bodies as they are. The pass reads vn as a dot product, the
// sweep as a difference of one component: the same value (but a zero's
// sign) as long as the other component's difference times 0 is 0, not NaN:
// every body's velocity within ±1e300 (`tame`, looked at once for passes in
// a row that skip: a pass that runs may change them). A settled pile's x
// rows hold nothing: its two sideways passes, three quarters of the passes'
// rows, are not run (the settled rain of 100 000 on one thread: 8.9 -> 8.0
// ms a step).
bool ContactSolver::skips_pass(const Components& k, Vector down, bool& tame) {
  if (!keeps_unchanged) return false;  // (the browser's build, short of room, runs them: the same bits)
  const bool x = support_sign(0, down) != 0, y = support_sign(2, down) != 0;
  if ((x && !axis_at_targets_[0]) || (y && !axis_at_targets_[1])) return false;
  if (!tame) {
    const std::span<const Vector> velocity(k.velocity);
    const std::span<const EntityId> bodies(slot_body_);
    constexpr double most = 1e300;  // (a difference of two stays finite)
    tame = workers_or_one(workers_).or_over_ranges(bodies.size(), min_parallel_items, [&](int, std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        const Vector v = velocity[bodies[i]];
        if (!(std::abs(v.x) <= most && std::abs(v.y) <= most)) return std::uint8_t{1};
      }
      return std::uint8_t{0};
    }) == 0;
  }
  return tame;
}

// The iterations' order (order_) and the bodies' slots. Each contact reads
// and changes its two bodies' velocities only, so any order that keeps, for
// every body, the order of its contacts gives the same bits as the given
// one (by pair). In the given order nearly every contact shares a body with
// the one before it (a body's contacts come together, and its last one
// shares a body with the next body's first), so each waits for the one
// before it to store its velocities. Here, within chunks of contacts (few
// enough bodies to stay in cache), contacts are sorted by level: one more
// than the highest level of the earlier contacts of their bodies. The
// contacts of a level share no body, and the processor overlaps them.
// A fixed body links nothing: its contacts add (0·j)·n to its velocity,
// which leaves it as it is unless a component is -0 (then it links).
// prepare() lists the contacts' keys for it.
void ContactSolver::schedule(const Components& k, Vector g, bool kept_all) {
  // All this (and the support order) depends only on the contacts' bodies,
  // axes and links (prepare() lists them in topology_next_), and on
  // gravity's direction: a resting pile keeps them from substep to substep.
  // (kept_all: the contacts are last substep's, topology_ theirs.)
  if (!kept_all) topology_.swap(topology_next_);
  same_topology_ = kept_all || topology_ == topology_next_;
  const bool kept = scheduled_ && g == topology_g_ && same_topology_;
#if PHYSICS_HAS_THREADS
  order_kept_ = kept;
#endif
  if (kept) return;
  have_order_ = false;
#if PHYSICS_HAS_THREADS
  pipeline_.forget();
#endif
  topology_g_ = g;
  for (const EntityId e : slot_body_)
    if (e < slot_of_.size()) slot_of_[e] = none;
  slot_of_.resize(k.size(), none);
  slot_body_.clear();
  for (const ContactConstraint& ct : contacts_)
    number_as_met(ct.c, slot_of_, slot_body_), number_as_met(ct.b, slot_of_, slot_body_);
  const std::size_t n = contacts_.size(), chunks = (n + schedule_chunk - 1) / schedule_chunk;
  level_.resize(n);
  order_.resize(n);
  // The chunks apart from each other: on a team, each thread orders a range of them.
  Workers& w = workers_or_one(workers_);
  level_scratch_.resize(static_cast<std::size_t>(w.threads()));
  w.for_ranges(chunks, 2, [&](int t, std::size_t begin, std::size_t end) {
    if (begin == end && t != 0) return;  // (the first's table, all 0, is order_by_axis' count)
    LevelScratch& scratch = level_scratch_[static_cast<std::size_t>(t)];
    scratch.last_level.assign(slot_body_.size(), 0);
    for (std::size_t c = begin; c < end; ++c)
      order_chunk(c * schedule_chunk, std::min(n, (c + 1) * schedule_chunk), scratch);
  });
  order_by_axis();
  // Rows i and i + 1 of by_axis_ share no linking body when they come from
  // the same chunk and level: sweep_axis may solve them side by side (with
  // SSE2; elsewhere paired_ stays all zeros). The last row of each stretch
  // of by_axis_ (order_by_axis) has no next one in its sweep.
  paired_.resize(by_axis_.size());
#if defined(__SSE2__)
  // The same in order_ for the friction sweep: rows i and i + 1 of one chunk
  // and level with normals along the same component (schedule's sort puts a
  // level's x rows before its y rows).
  friction_paired_.resize(order_.size());
  w.for_ranges(n, min_parallel_items, [&](int, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < std::min(end, n - 1); ++i) {
      paired_[i] = same_level(by_axis_[i], by_axis_[i + 1]);
      const std::uint32_t a = order_[i], b = order_[i + 1];
      friction_paired_[i] = same_level(a, b) && (contacts_[a].axis >= 2) == (contacts_[b].axis >= 2);
    }
  });
  for (const std::size_t end : {x_below_, x_below_ + x_above_, x_rows_, by_axis_.size()})
    if (end != 0) paired_[end - 1] = 0;
  if (!friction_paired_.empty()) friction_paired_.back() = 0;
#endif
  scheduled_ = true;  // (last: an allocation that throws above leaves no order taken for made)
}

// Whether contacts a and b come from one chunk and level of the order
// (order_chunk()): then they share no linking body.
bool ContactSolver::same_level(std::uint32_t a, std::uint32_t b) const {
  return a / schedule_chunk == b / schedule_chunk && level_[a] == level_[b];
}

// Contacts [start, end) of one chunk, by level (order_, level_): a
// contact's level is one more than the highest level of the earlier
// contacts of its linking bodies in the chunk (schedule()).
void ContactSolver::order_chunk(std::size_t start, std::size_t end, LevelScratch& scratch) {
  std::vector<std::uint32_t>& last_level = scratch.last_level;
  std::uint32_t levels = 0;
  for (std::size_t i = start; i < end; ++i) {
    const ContactConstraint& ct = contacts_[i];
    const bool lc = topology_[i].flags >> 4 & 1, lb = topology_[i].flags >> 5 & 1;
    std::uint32_t& nc = last_level[slot_of_[ct.c]];
    std::uint32_t& nb = last_level[slot_of_[ct.b]];
    const std::uint32_t level = std::max(lc ? nc : 0, lb ? nb : 0);
    if (lc) nc = level + 1;
    if (lb) nb = level + 1;
    level_[i] = level, levels = std::max(levels, level + 1);
  }
  // Stable counting sort of the chunk by level and, within a level, x rows
  // before y rows (any order of a level gives the same bits: the friction
  // loop then meets the axes in runs, sweep_friction); then the chunk's
  // bodies start again at 0.
  const auto key = [&](std::size_t i) { return 2 * level_[i] + (contacts_[i].axis >= 2); };
  std::vector<std::uint32_t>& count = scratch.count;
  count.assign(2 * levels + 1, 0);
  for (std::size_t i = start; i < end; ++i) ++count[key(i) + 1];
  for (std::size_t l = 1; l <= 2 * levels; ++l) count[l] += count[l - 1];
  for (std::size_t i = start; i < end; ++i) order_[start + count[key(i)]++] = static_cast<std::uint32_t>(i);
  for (std::size_t i = start; i < end; ++i) last_level[slot_of_[contacts_[i].c]] = last_level[slot_of_[contacts_[i].b]] = 0;
}

// The frictionless rows' order (by_axis_, row_order()): order_'s x rows,
// then its y rows, which touch other values (each body's x and y apart).
// With many x rows they are cut in three stretches at a slot: the rows
// whose two bodies' slots are below it, those whose two are not, then the
// rest (the rows across), each in order_. The slots follow the contacts,
// which follow the bodies' order in space (the grid's), so a pile is cut
// between two of its layers and few rows are across (a settled rain of
// 100 000: 1 888 of 298 576). The first two stretches share no body, fixed
// ones included, so two threads sweep them at once (iterate<false>: the
// first with the y rows, the second on the other thread), then the rows
// across: every body's rows keep their order in the sweep whatever the
// team, so the same bits for any number of threads, and the browser build
// (no threads) runs the same order. The cut gives both threads as many
// rows; there is none where the y rows are as many as the x rows (one
// thread has the y rows, the other the x rows). Few rows are not cut (a
// cut would change their bits for nothing): the world's size alone
// decides, not the team.
//
// The y rows are not cut: a pile's weight goes down its columns through
// them, and the rows across the cut, solved last in each sweep, held it
// back a sweep at the cut (the landing rain of 100 000, rain_phase: 9.6 ->
// 25.7 ms a step, its piles sinking into each other and projected apart).
void ContactSolver::order_by_axis() {
  constexpr int all_x = 3, y = 4;  // what append() takes besides a side of the cut
  std::uint32_t cut = 0;
  const auto side = [&](std::uint32_t i) {  // 0 below the cut, 1 not, 2 across
    const bool c = slot_of_[contacts_[i].c] < cut, b = slot_of_[contacts_[i].b] < cut;
    return c != b ? 2 : c ? 0 : 1;
  };
  std::size_t n = 0;
  by_axis_.resize(order_.size());
  const auto append = [&](int rows) {
    for (const std::uint32_t i : order_)
      if (rows == y ? contacts_[i].axis >= 2 : contacts_[i].axis < 2 && (rows == all_x || side(i) == rows))
        by_axis_[n++] = i;
  };
  append(all_x);
  x_rows_ = n, x_below_ = 0, x_above_ = n;
  const std::size_t y_rows = order_.size() - x_rows_;
  if (x_rows_ >= cut_x_rows && x_rows_ > y_rows) {
    // The lowest slot below which the rows' higher slots leave as many rows as wanted (a count a slot).
    std::vector<std::uint32_t>& rows_at = level_scratch_[0].last_level;  // (schedule()'s, all 0 again; it assigns it before each use)
    for (std::size_t r = 0; r < x_rows_; ++r)
      ++rows_at[std::max(slot_of_[contacts_[by_axis_[r]].c], slot_of_[contacts_[by_axis_[r]].b])];
    for (std::size_t below = 0; below + rows_at[cut] <= (x_rows_ - y_rows) / 2;) below += rows_at[cut++];
    n = 0;
    append(0);
    x_below_ = n;
    append(1);
    x_above_ = n - x_below_;
    append(2);
  }
  append(y);
}

// The rows' order: without friction, a row reads and changes one velocity
// component of each body (its normal's axis), so the x rows and the y rows
// touch disjoint values and each group may run on its own (iterate<false>),
// each in order_ (a large world's x rows in stretches: order_by_axis).
std::span<const std::uint32_t> ContactSolver::row_order() const { return friction_.empty() ? by_axis_ : order_; }

// The hot copies for a relaxation: the bodies' velocities and inverse
// masses by slot, the contacts in order_ with the relaxation's targets and
// accumulators (`after_bounce`: lambda2, no approach allowed at the impacts).
void ContactSolver::load_rows(const Components& k, bool after_bounce) {
  Workers& w = workers_or_one(workers_);
  const bool by_axis = friction_.empty();
  if (by_axis) {
    for (auto& bodies : axis_bodies_) bodies.resize(slot_body_.size());
  } else {
    solver_bodies_.resize(slot_body_.size());
  }
  // (Spans and values, not the members: the loops' stores could alias them, reloaded at every item.)
  const std::span<const EntityId> slot_body(slot_body_);
  const std::span<const Vector> velocity(k.velocity);
  const std::span<const double> inverse_mass(inverse_mass_);
  const std::span<SolverBody> bodies(solver_bodies_);
  const std::span<AxisBody> x_bodies(axis_bodies_[0]), y_bodies(axis_bodies_[1]);
  w.for_ranges(slot_body.size(), min_parallel_items, [&, by_axis](int, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const Vector v = velocity[slot_body[i]];
      const double im = inverse_mass[slot_body[i]];
      if (by_axis)
        x_bodies[i] = {v.x, im}, y_bodies[i] = {v.y, im};
      else
        bodies[i] = {v, im};
    }
  });
  if (keeps_unchanged && !after_bounce && plain_rows_)
    refresh_rows();
  else
    load_contact_rows(after_bounce);
  plain_rows_ = !after_bounce;
}

// The contacts in row_order() with the relaxation's targets and accumulators.
void ContactSolver::load_contact_rows(bool after_bounce) {
  Workers& w = workers_or_one(workers_);
  const bool by_axis = friction_.empty();
  const std::span<const std::uint32_t> order = row_order();
  rows_.resize(order.size());
  row_lambda_.resize(order.size());
  targets_.resize(order.size());
  friction_rows_.resize(friction_.size());
  const std::span<const ContactConstraint> contacts(contacts_);
  const std::span<const ContactImpulse> impulses(impulses_);
  const std::span<const std::uint32_t> slot_of(slot_of_);
  const std::span<SolverRow> rows(rows_);
  const std::span<double> lambdas(row_lambda_);
  const std::span<double> targets(targets_);
  w.for_ranges(order.size(), min_parallel_items, [&, by_axis, after_bounce](int, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const ContactConstraint& ct = contacts[order[i]];
      const double target = after_bounce && !ct.resting ? 0.0 : ct.target;
      // By axis (sweep_axis): each row's normal along +x or +y, its bodies swapped if it was -x or -y.
      const bool swap = by_axis && (ct.axis & 1) == 0;
      rows[i] = {slot_of[swap ? ct.b : ct.c], slot_of[swap ? ct.c : ct.b], ct.inv_w, target};
      lambdas[i] = after_bounce ? 0.0 : impulses[order[i]].lambda;
      targets[order[i]] = target;  // by contact, for the bottom-up pass
    }
    for (std::size_t i = begin; i < std::min(end, friction_.size()); ++i) {
      const FrictionRow& f = friction_[order[i]];
      friction_rows_[i] = {f.mu, after_bounce ? 0.0 : f.lambda, static_cast<std::uint32_t>(contacts[order[i]].axis)};
    }
  });
  group_friction_rows();
}

// The friction sweep's groups (refresh_rows() keeps them with the rows):
// rows i and i + 1 go side by side (2) when they are paired (friction_paired_)
// and both have friction; four rows (4) when rows i + 2 and i + 3 do too,
// the third then marked 2 for the sweep without AVX2; else one row (1). Read
// once a row in the sweep, where the tests were about 40 instructions a group.
void ContactSolver::group_friction_rows() {
#if defined(__SSE2__)
  const std::span<const FrictionHot> f(friction_rows_);
  const std::span<const std::uint8_t> paired(friction_paired_);
  friction_group_.assign(f.size(), 0);
  const auto two = [&](std::size_t i) { return paired[i] && f[i].mu != 0.0 && f[i + 1].mu != 0.0; };  // (paired: i + 1 exists)
  for (std::size_t i = 0; i < f.size();) {
    const std::uint8_t n = !two(i) ? 1 : paired[i + 1] && two(i + 2) ? 4 : 2;
    friction_group_[i] = n;
    if (n == 4) friction_group_[i + 2] = 2;
    i += n;
  }
#endif
}

// When the rows hold the last plain relaxation's contacts, in the same order
// (plain_rows_: a resting pile), only their accumulators are new: the warm
// start's impulses.
void ContactSolver::refresh_rows() {
  const std::span<const std::uint32_t> order = row_order();
  const std::span<const ContactImpulse> impulses(impulses_);
  const std::span<const FrictionRow> friction(friction_);
  const std::span<double> lambdas(row_lambda_);
  const std::span<FrictionHot> friction_rows(friction_rows_);
  workers_or_one(workers_).for_ranges(order.size(), min_parallel_items, [&](int, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) lambdas[i] = impulses[order[i]].lambda;
    for (std::size_t i = begin; i < std::min(end, friction.size()); ++i) friction_rows[i].lambda = friction[order[i]].lambda;
  });
}

// The relaxation's results back: accumulators and velocities.
void ContactSolver::store_rows(Components& k, bool after_bounce) {
  Workers& w = workers_or_one(workers_);
  const std::span<const std::uint32_t> order = row_order();
  // (Spans and values, not the members: the loops' stores could alias them, reloaded at every item.)
  const std::span<ContactImpulse> impulses(impulses_);
  const std::span<const double> lambdas(row_lambda_);
  w.for_ranges(order.size(), min_parallel_items, [&, after_bounce](int, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      ContactImpulse& j = impulses[order[i]];
      (after_bounce ? j.lambda2 : j.lambda) = lambdas[i];
    }
    for (std::size_t i = begin; i < std::min(end, friction_rows_.size()); ++i) {
      FrictionRow& f = friction_[order[i]];
      (after_bounce ? f.lambda2 : f.lambda) = friction_rows_[i].lambda;
    }
  });
  const std::span<const EntityId> slot_body(slot_body_);
  const std::span<Vector> velocity(k.velocity);
  const std::span<const SolverBody> bodies(solver_bodies_);
  const std::span<const AxisBody> x_bodies(axis_bodies_[0]), y_bodies(axis_bodies_[1]);
  w.for_ranges(slot_body.size(), min_parallel_items, [&, by_axis = friction_.empty()](int, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      velocity[slot_body[i]] = by_axis ? Vector{x_bodies[i].v, y_bodies[i].v} : bodies[i].v;
  });
}

// Sequential impulses with accumulated clamping, on the hot copies: the
// normal impulse never pulls; with friction, the tangential one then stays
// within mu times the normal impulse accumulated so far (Coulomb's cone, as
// Box2D clamps it). `friction` is a compile-time constant: the frictionless
// loop reads no friction row.
//
// A sweep that leaves every accumulated impulse with the same bits applies
// only zero impulses: every further sweep would compute the same values
// again, and the iterations stop there. (The zeros can still turn a -0
// velocity component into +0, which further sweeps could do too: the values
// are those of all the sweeps, a zero's sign may differ; traces of every
// scene file in the stable and auto modes came out byte-identical.) A
// settled pile, warm started with last substep's impulses, often gets there
// after one or two sweeps (Box2D's benchmark many_pyramids: 9 steps in 10
// after the second), and the rest of its sweeps cost nothing.
//
// Every normal is an axis (axis_normal), so a row is one-dimensional: it
// reads and changes one velocity component of each body (its tangent the
// other), with the sign of its normal (apply_axis_impulse). The values are those of the dot
// products and vector updates with the zero component written out, which
// added (±0) to the other component: only a zero's sign may differ. Less
// arithmetic a row (a settled pile: 52 -> 46 instructions a row, callgrind).
//
// Without friction the x rows and the y rows share no value (row_order()):
// each sweep runs the x rows, then the y rows, each group with its component
// known (sweep_axis), which saves the per-row choice of component. With
// threads, at once on two threads (their bodies' copies apart, axis_bodies_):
// the y rows and the x rows' first stretch on one, their second on the
// other), then the rows across the cut (order_by_axis); the same sweeps on
// the same values, so the same bits. A pile has more x rows than y rows (a
// settled rain of 100 000: 298 576 of 398 576, its squares' corner pairs
// among them): the cut gives both threads as many.
//
// Being two problems, each axis stops at its own first sweep that changes
// no accumulator, not when both do in the same sweep: the sweeps after that
// one would change nothing either. (Every impulse of such a sweep is +0,
// lambda - lambda; adding it leaves a velocity as it is but a -0, which
// turns +0, and that sweep made each velocity it could so already. The
// next sweep's rows then read the same values but zeros' signs, which move
// no accumulator: they are never -0, and old - (±0) is old. An infinite
// or NaN lambda counts as a change, sweep_axis: its impulse inf - inf is
// NaN. A blown-up world with one sweeps all its sweeps now, where it
// stopped once every accumulator kept its bits.) A settled
// pile's x rows hold nothing and are done after a sweep or two, where the
// y rows take every sweep: the rain of 100 000 settled ran 8 sweeps of its
// 298 576 x rows a relaxation for nothing (one thread, 13.2 -> 8.9 ms a
// step; 10 000: 0.80 -> 0.47).
template <bool friction>
void ContactSolver::iterate(const SolverSettings& s) {
  if constexpr (!friction) {
    const std::span<const SolverRow> rows(rows_);
    const std::span<double> lambdas(row_lambda_);
    const std::span<const std::uint8_t> paired(paired_);
    const auto sweep = [&](int axis, std::size_t from, std::size_t count) {
      return sweep_axis(rows.subspan(from, count), lambdas.subspan(from, count), paired.subspan(from, count),
                        axis_bodies_[static_cast<std::size_t>(axis)]);
    };
    const std::size_t below = x_below_, above = x_above_, across = x_rows_ - below - above;
    const std::size_t y_rows = rows.size() - x_rows_;
    Workers& w = workers_or_one(workers_);
    const bool together = has_threads && w.splits(rows.size(), min_parallel_items);
#if PHYSICS_HAS_THREADS
    bool pipeline = together && y_rows >= pipeline_rows;  // (pipelines_pay() asked once, when it would start)
    // (In waves, every later sweep runs most of its blocks before the first
    // that changes nothing is known: only where the last relaxation's y rows
    // took every sweep. A settled pile warm started from last substep's
    // impulses is often done after two: many_pyramids, 0.93 -> 1.32 ms a
    // step in waves at every relaxation.)
    const bool waves = pipeline_.planned() && y_rows >= wave_rows_ && y_sweeps_ >= s.iterations;
    y_sweeps_ = 0;
#endif
    // By axis: what its last sweep found. With no x rows (a rain landing in
    // columns) the y rows are alone from their first sweep: pipelined or in
    // waves from it (the landing rain of 100 000 on two threads: its first
    // sweep took one thread, the other waiting on an empty part).
    std::array<std::uint8_t, 2> last{x_rows_ != 0 ? changed : std::uint8_t{0}, changed};
    const auto live = [&](std::size_t axis) { return (last[axis] & changed) != 0; };
    for (int it = 0; it < s.iterations && (live(0) || live(1)); ++it) {
#if PHYSICS_HAS_THREADS
      // The x rows done (a pile's, after a sweep or two): the y rows' sweeps
      // left on both threads, or else in waves on this one if there are
      // enough of them.
      if ((pipeline || waves) && !live(0)) {
        pipeline = pipeline && pipelines_pay(w);
        if (pipeline || waves) {
          last[1] = pipelined_sweeps(pipeline ? &w : nullptr, rows.subspan(x_rows_), lambdas.subspan(x_rows_),
                                     paired.subspan(x_rows_), s.iterations - it);
          y_sweeps_ = it + pipeline_.sweeps_counted();
          break;
        }
      }
      y_sweeps_ += live(1);
#endif
      if (together && live(0)) {
        std::array<std::uint8_t, 3> x{};
        std::uint8_t y = last[1];
        w.run([&](int t) {  // (order_by_axis: the stretches each thread sweeps)
          if (t == 0) {
            x[0] = sweep(0, 0, below);
            if (live(1)) y = sweep(1, x_rows_, y_rows);
          }
          if (t == 1) x[1] = sweep(0, below, above);
        });
        x[2] = sweep(0, below + above, across);
        last = {static_cast<std::uint8_t>(x[0] | x[1] | x[2]), y};
      } else {
        if (live(0)) last[0] = sweep(0, 0, x_rows_);
        if (live(1)) last[1] = sweep(1, x_rows_, y_rows);
      }
    }
    for (std::size_t axis = 0; axis < 2; ++axis) axis_at_targets_[axis] = last[axis] == 0;
  } else {
    axis_at_targets_ = {};
    for (int it = 0; it < s.iterations; ++it)
      if (!sweep_friction()) return;
  }
}

#if PHYSICS_HAS_THREADS
// Whether the y rows of this order may be swept on two threads or in waves
// (pipelined_sweeps) and are not planned for it yet (plan_y_rows()). On
// one thread, only an order kept from the substep before is planned: a
// landing rain's new order at nearly every substep would cost its plan
// each time (0.24-0.38 ms for 100 000 bodies) for sweeps in waves that
// save about as much.
bool ContactSolver::y_rows_unplanned() const {
  const std::size_t y_rows = by_axis_.size() - x_rows_;
  return friction_.empty() && !pipeline_.planned() &&
         (aside() ? y_rows >= pipeline_rows : y_rows >= wave_rows_ && order_kept_);
}

// The y rows made ready for pipelined_sweeps: the floor's rows among their
// bodies' (SweepPipeline::defer_one_ended: every body keeps its rows'
// order, the same bits), their pairs side by side again (paired_,
// schedule()), then the plan. Before the rows are loaded: on a helper
// beside the warm start (solve_velocities(): a new order of the landing
// rain of 100 000 took 0.24-0.38 ms here at nearly every substep, the other
// thread waiting), else in relax(), beside the helper's support order when
// there is a new one; on one thread, in relax().
void ContactSolver::plan_y_rows() {
  const std::span<std::uint32_t> rows = std::span(by_axis_).subspan(x_rows_);
  const std::span<std::uint8_t> paired = std::span(paired_).subspan(x_rows_);
  pipeline_.defer_one_ended(rows, slot_body_.size(), [&](std::uint32_t i) {
    const TopologyKey& t = topology_[i];
    return SweepPipeline::Ends{slot_of_[t.c], slot_of_[t.b], t.flags >> 4 & 3};
  });
#if defined(__SSE2__)
  for (std::size_t r = 0; r + 1 < rows.size(); ++r) paired[r] = same_level(rows[r], rows[r + 1]);
  paired.back() = 0;
#endif
  const std::span<const SweepPipeline::Ends> ends = pipeline_.ends();
  pipeline_.plan(rows.size(), slot_body_.size(), pipeline_block,
                 [&](std::size_t r, auto&& body) { body(ends[r].c), body(ends[r].b); },
                 [&](std::size_t r) { return paired[r] != 0; });
  plain_rows_ = false;  // (rows_ in the order before)
}

// `sweeps` sweeps of the y rows, or up to the first that changes nothing
// (the sweeps after it change nothing either: iterate<false>), on two
// threads of `w` or, without one, in waves on this thread
// (engine/sweep_pipeline.hpp). The rows in blocks of about pipeline_block
// (a pair solved together kept in one), their bodies fixed ones included
// (so that two threads never write one body's values at once), as
// plan_y_rows() planned them. Returns what the last sweep that counts
// found (sweep_axis).
//
// In waves, the sweeps of a pile's 100 000 y rows (about 50 bytes a row
// with its body's values) keep the few blocks between the first and the
// last in the level-2 cache: the settled rain of 100 000 on one thread,
// its 7 sweeps after the first (with the x rows' first) 1.66 -> 1.38 ms a
// step (timers, medians), the step 7.74 -> 7.42 ms (runs in turns with the
// build before).
std::uint8_t ContactSolver::pipelined_sweeps(Workers* w, std::span<const SolverRow> rows, std::span<double> lambdas,
                                             std::span<const std::uint8_t> paired, int sweeps) {
  const std::span<AxisBody> bodies(axis_bodies_[1]);
  const auto sweep_block = [&](std::size_t from, std::size_t count) {
    return sweep_axis(rows.subspan(from, count), lambdas.subspan(from, count), paired.subspan(from, count), bodies);
  };
  if (!w) return ++stats.in_waves, pipeline_.run_in_waves(sweeps, changed, sweep_block);
  ++stats.pipelined;
  return pipeline_.run(*w, sweeps, changed, sweep_block);
}
#endif

#if defined(__SSE2__)
// friction_row with friction, the row's two components side by side in
// SSE2's lanes, the normal's in the low one (`y`: the normal along y, the
// lanes swapped), with the same operations in the same order as the scalar
// row, so the same bits: the tangential row's relative speed does not
// depend on the normal impulse (it changes the other component), and its
// vt·w is (vt - 0)·w, the same bits for any vt. Only the cone, which needs
// the normal impulse in the tangent's lane, is scalar.
static_assert(sizeof(Vector) == 2 * sizeof(double) && offsetof(Vector, y) == sizeof(double),
              "friction_row_sse2 loads a velocity's x and y as one pair");
template <bool y>
inline bool ContactSolver::friction_row_sse2(const SolverRow& r, double& lambda_n, FrictionHot& f,
                                             SolverBody& bc, SolverBody& bb) {
  constexpr int swap = y ? 1 : 2;  // _mm_shuffle_pd's: (high, low) for 1, (low, high) for 2
  const __m128d vc = _mm_loadu_pd(&bc.v.x), vb = _mm_loadu_pd(&bb.v.x);
  const __m128d rel = _mm_sub_pd(vc, vb);
  const __m128d sign = _mm_loadu_pd(&axis_signs[f.axis].normal);
  const __m128d v = _mm_mul_pd(sign, _mm_shuffle_pd(rel, rel, swap));  // (vn, vt)
  const __m128d old = _mm_setr_pd(lambda_n, f.lambda);
  const __m128d push = _mm_mul_pd(_mm_sub_pd(v, _mm_set_sd(r.target)), _mm_set1_pd(r.inv_w));
  const __m128d unclamped = _mm_sub_pd(old, push);
  const double lambda = std::max(_mm_cvtsd_f64(unclamped), 0.0);
  const double limit = f.mu * lambda;
  const double lt = std::clamp(_mm_cvtsd_f64(_mm_unpackhi_pd(unclamped, unclamped)), -limit, limit);
  const __m128d now = _mm_setr_pd(lambda, lt);
  const __m128d j = _mm_sub_pd(now, old);
  const __m128d dc = _mm_mul_pd(_mm_mul_pd(_mm_set1_pd(bc.w), j), sign);
  const __m128d db = _mm_mul_pd(_mm_mul_pd(_mm_set1_pd(bb.w), j), sign);
  _mm_storeu_pd(&bc.v.x, _mm_add_pd(vc, _mm_shuffle_pd(dc, dc, swap)));
  _mm_storeu_pd(&bb.v.x, _mm_sub_pd(vb, _mm_shuffle_pd(db, db, swap)));
  lambda_n = lambda, f.lambda = lt;
  // Bits, not values, as the scalar row compares them (a 32-bit compare: SSE2 has no 64-bit one).
  return _mm_movemask_epi8(_mm_cmpeq_epi32(_mm_castpd_si128(now), _mm_castpd_si128(old))) != 0xFFFF;
}
#endif

// A row of iterate<true> whose normal lies along component n, its tangent
// along t: the normal impulse, then the tangential one within the cone;
// whether either accumulator changed.
template <double Vector::*n, double Vector::*t>
inline bool ContactSolver::friction_row(const SolverRow& r, double& lambda_n, FrictionHot& f,
                                        std::span<SolverBody> bodies) {
  SolverBody& bc = bodies[r.c];
  SolverBody& bb = bodies[r.b];
#if defined(__SSE2__)
  if (f.mu != 0.0) return friction_row_sse2<n == &Vector::y>(r, lambda_n, f, bc, bb);
#endif
  const double sn = axis_signs[f.axis].normal;
  const double vn = sn * (bc.v.*n - bb.v.*n);
  const double lambda = std::max(lambda_n - (vn - r.target) * r.inv_w, 0.0);
  apply_axis_impulse(bc.v.*n, bb.v.*n, sn, lambda - lambda_n, bc.w, bb.w);
  bool changed = std::bit_cast<std::uint64_t>(lambda) != std::bit_cast<std::uint64_t>(lambda_n);
  lambda_n = lambda;
  if (f.mu == 0.0) return changed;
  const double st = axis_signs[f.axis].tangent;
  const double vt = st * (bc.v.*t - bb.v.*t);
  const double limit = f.mu * lambda;
  const double lt = std::clamp(f.lambda - vt * r.inv_w, -limit, limit);
  apply_axis_impulse(bc.v.*t, bb.v.*t, st, lt - f.lambda, bc.w, bb.w);
  changed |= std::bit_cast<std::uint64_t>(lt) != std::bit_cast<std::uint64_t>(f.lambda);
  f.lambda = lt;
  return changed;
}

// One sweep of iterate<true>; whether any accumulated impulse changed. The
// rows come in runs of one axis (schedule()), so the test of the axis is
// one the processor predicts, and each row's components are known.
// Two rows of one level with normals along the same component, both with
// friction, are solved side by side (friction_two); with AVX2, four such rows
// (friction_four): friction_group_ says which.
bool ContactSolver::sweep_friction() {
  return PHYSICS_WIDE_ROWS && wide_rows ? sweep_friction_rows<true>() : sweep_friction_rows<false>();
}

// Asked of the processor once per process.
bool ContactSolver::has_wide_rows() {
#if PHYSICS_WIDE_ROWS
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
#else
  return false;
#endif
}

template <bool wide>
bool ContactSolver::sweep_friction_rows() {
  // (Spans, not the members: the loop's stores could alias a vector's own pointers.)
  const std::span<const SolverRow> rows(rows_);
  const std::span<double> lambdas(row_lambda_);
  const std::span<FrictionHot> friction(friction_rows_);
  const std::span<SolverBody> bodies(solver_bodies_);
  [[maybe_unused]] const std::span<const std::uint8_t> group(friction_group_);
  bool changed = false;
  for (std::size_t i = 0; i < rows.size();) {
    FrictionHot& f = friction[i];
#if PHYSICS_WIDE_ROWS
    if (wide && group[i] == 4) {
      changed |= f.axis >= 2 ? friction_four<true>(&rows[i], &lambdas[i], &f, bodies.data())
                             : friction_four<false>(&rows[i], &lambdas[i], &f, bodies.data());
      i += 4;
      continue;
    }
#endif
#if defined(__SSE2__)
    if (group[i] >= 2) {
      changed |= f.axis >= 2
                     ? friction_two<true>(rows.subspan(i).first<2>(), &lambdas[i], friction.subspan(i).first<2>(), bodies)
                     : friction_two<false>(rows.subspan(i).first<2>(), &lambdas[i], friction.subspan(i).first<2>(), bodies);
      i += 2;
      continue;
    }
#endif
    changed |= f.axis >= 2 ? friction_row<&Vector::y, &Vector::x>(rows[i], lambdas[i], f, bodies)
                           : friction_row<&Vector::x, &Vector::y>(rows[i], lambdas[i], f, bodies);
    ++i;
  }
  return changed;
}

#if PHYSICS_WIDE_ROWS
namespace {
// (Helpers of friction_four with its target: a lambda in it would not have AVX2.)
// Four pairs of doubles (a body's velocity, a row's inverse mass and target,
// a friction row's coefficient and accumulator, an axis's signs) as all four
// firsts and all four seconds: two loads into each half, then unpacked.
struct Lanes {
  __m256d first, second;
};
[[gnu::target("avx2"), gnu::always_inline]] inline Lanes by_field(const double* p0, const double* p1, const double* p2,
                                                                 const double* p3) {
  const __m256d even = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p0)), _mm_loadu_pd(p2), 1);
  const __m256d odd = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p1)), _mm_loadu_pd(p3), 1);
  return {_mm256_unpacklo_pd(even, odd), _mm256_unpackhi_pd(even, odd)};
}
// x and y of four bodies' velocities (lanes 0 to 3) back to them, in lane order.
[[gnu::target("avx2"), gnu::always_inline]] inline void store_velocities(std::array<Vector*, 4> to, __m256d x,
                                                                        __m256d y) {
  const __m256d even = _mm256_unpacklo_pd(x, y), odd = _mm256_unpackhi_pd(x, y);  // bodies 0 and 2, 1 and 3
  _mm_storeu_pd(&to[0]->x, _mm256_castpd256_pd128(even)), _mm_storeu_pd(&to[1]->x, _mm256_castpd256_pd128(odd));
  _mm_storeu_pd(&to[2]->x, _mm256_extractf128_pd(even, 1)), _mm_storeu_pd(&to[3]->x, _mm256_extractf128_pd(odd, 1));
}
}  // namespace

// Four friction rows that share no linking body, one in each of AVX2's
// lanes, with friction_two's operations in its order, lane by lane: the
// same bits (AVX2's instructions round each lane as SSE2's do; no fused
// multiply-add: the build keeps -ffp-contract=off and AVX2 alone has none).
// Out of line: a function with AVX2 cannot be inlined into one without it.
template <bool y>
[[gnu::noinline]] bool ContactSolver::friction_four(const SolverRow* r, double* lambda_n, FrictionHot* f,
                                                   SolverBody* bodies) {
  SolverBody &c0 = bodies[r[0].c], &c1 = bodies[r[1].c], &c2 = bodies[r[2].c], &c3 = bodies[r[3].c];
  SolverBody &b0 = bodies[r[0].b], &b1 = bodies[r[1].b], &b2 = bodies[r[2].b], &b3 = bodies[r[3].b];
  static_assert(offsetof(SolverRow, target) == offsetof(SolverRow, inv_w) + sizeof(double) &&
                offsetof(FrictionHot, lambda) == sizeof(double) && offsetof(AxisSigns, tangent) == sizeof(double));
  const auto [cx, cy] = by_field(&c0.v.x, &c1.v.x, &c2.v.x, &c3.v.x);
  const auto [bx, by] = by_field(&b0.v.x, &b1.v.x, &b2.v.x, &b3.v.x);
  const __m256d cn = y ? cy : cx, ct = y ? cx : cy, bn = y ? by : bx, bt = y ? bx : by;
  const auto [sn, st] = by_field(&axis_signs[f[0].axis].normal, &axis_signs[f[1].axis].normal,
                                 &axis_signs[f[2].axis].normal, &axis_signs[f[3].axis].normal);
  const auto [inv_w, target] = by_field(&r[0].inv_w, &r[1].inv_w, &r[2].inv_w, &r[3].inv_w);
  const auto [mu, old_t] = by_field(&f[0].mu, &f[1].mu, &f[2].mu, &f[3].mu);
  const __m256d vn = _mm256_mul_pd(sn, _mm256_sub_pd(cn, bn)), vt = _mm256_mul_pd(st, _mm256_sub_pd(ct, bt));
  const __m256d old_n = _mm256_loadu_pd(lambda_n);
  const __m256d lambda =
      _mm256_max_pd(_mm256_setzero_pd(), _mm256_sub_pd(old_n, _mm256_mul_pd(_mm256_sub_pd(vn, target), inv_w)));
  const __m256d limit = _mm256_mul_pd(mu, lambda);
  const __m256d neg_limit = _mm256_xor_pd(limit, _mm256_set1_pd(-0.0));
  const __m256d lt = _mm256_min_pd(limit, _mm256_max_pd(neg_limit, _mm256_sub_pd(old_t, _mm256_mul_pd(vt, inv_w))));
  const __m256d jn = _mm256_sub_pd(lambda, old_n), jt = _mm256_sub_pd(lt, old_t);
  const __m256d wc = _mm256_setr_pd(c0.w, c1.w, c2.w, c3.w), wb = _mm256_setr_pd(b0.w, b1.w, b2.w, b3.w);
  const __m256d cn2 = _mm256_add_pd(cn, _mm256_mul_pd(_mm256_mul_pd(wc, jn), sn));
  const __m256d bn2 = _mm256_sub_pd(bn, _mm256_mul_pd(_mm256_mul_pd(wb, jn), sn));
  const __m256d ct2 = _mm256_add_pd(ct, _mm256_mul_pd(_mm256_mul_pd(wc, jt), st));
  const __m256d bt2 = _mm256_sub_pd(bt, _mm256_mul_pd(_mm256_mul_pd(wb, jt), st));
  // In friction_two's order: the c bodies, then the b bodies (a fixed body rows share gets the same values).
  store_velocities({&c0.v, &c1.v, &c2.v, &c3.v}, y ? ct2 : cn2, y ? cn2 : ct2);
  store_velocities({&b0.v, &b1.v, &b2.v, &b3.v}, y ? bt2 : bn2, y ? bn2 : bt2);
  _mm256_storeu_pd(lambda_n, lambda);
  const __m128d lt01 = _mm256_castpd256_pd128(lt), lt23 = _mm256_extractf128_pd(lt, 1);
  _mm_storel_pd(&f[0].lambda, lt01), _mm_storeh_pd(&f[1].lambda, lt01);
  _mm_storel_pd(&f[2].lambda, lt23), _mm_storeh_pd(&f[3].lambda, lt23);
  const __m256i same = _mm256_and_si256(_mm256_cmpeq_epi64(_mm256_castpd_si256(lambda), _mm256_castpd_si256(old_n)),
                                        _mm256_cmpeq_epi64(_mm256_castpd_si256(lt), _mm256_castpd_si256(old_t)));
  return _mm256_movemask_epi8(same) != -1;
}
#endif

#if defined(__SSE2__)
// Two friction rows that share no linking body, one in each lane, by
// component: the normals' lanes, then the tangents', with
// friction_row_sse2's operations in its order (so the same bits: the
// tangent's relative speed is read before the normal impulse, which changes
// the other component; std::clamp(v, lo, hi) is min(hi, max(lo, v)) lane by
// lane, NaN and zeros' signs included). `y`: the normals along y.
template <bool y>
inline bool ContactSolver::friction_two(std::span<const SolverRow, 2> r, double* lambda_n,
                                        std::span<FrictionHot, 2> f, std::span<SolverBody> bodies) {
  SolverBody& c0 = bodies[r[0].c];
  SolverBody& c1 = bodies[r[1].c];
  SolverBody& b0 = bodies[r[0].b];
  SolverBody& b1 = bodies[r[1].b];
  const __m128d c0v = _mm_loadu_pd(&c0.v.x), c1v = _mm_loadu_pd(&c1.v.x);
  const __m128d b0v = _mm_loadu_pd(&b0.v.x), b1v = _mm_loadu_pd(&b1.v.x);
  // x of both rows' bodies, then y; the normal's and the tangent's.
  const __m128d cx = _mm_unpacklo_pd(c0v, c1v), cy = _mm_unpackhi_pd(c0v, c1v);
  const __m128d bx = _mm_unpacklo_pd(b0v, b1v), by = _mm_unpackhi_pd(b0v, b1v);
  const __m128d cn = y ? cy : cx, ct = y ? cx : cy, bn = y ? by : bx, bt = y ? bx : by;
  const __m128d sn = _mm_setr_pd(axis_signs[f[0].axis].normal, axis_signs[f[1].axis].normal);
  const __m128d st = _mm_setr_pd(axis_signs[f[0].axis].tangent, axis_signs[f[1].axis].tangent);
  const __m128d inv_w = _mm_setr_pd(r[0].inv_w, r[1].inv_w);
  const __m128d vn = _mm_mul_pd(sn, _mm_sub_pd(cn, bn)), vt = _mm_mul_pd(st, _mm_sub_pd(ct, bt));
  const __m128d old_n = _mm_loadu_pd(lambda_n), old_t = _mm_setr_pd(f[0].lambda, f[1].lambda);
  const __m128d target = _mm_setr_pd(r[0].target, r[1].target);
  const __m128d lambda = _mm_max_pd(_mm_setzero_pd(), _mm_sub_pd(old_n, _mm_mul_pd(_mm_sub_pd(vn, target), inv_w)));
  const __m128d limit = _mm_mul_pd(_mm_setr_pd(f[0].mu, f[1].mu), lambda);
  const __m128d neg_limit = _mm_xor_pd(limit, _mm_set1_pd(-0.0));
  const __m128d lt = _mm_min_pd(limit, _mm_max_pd(neg_limit, _mm_sub_pd(old_t, _mm_mul_pd(vt, inv_w))));
  const __m128d jn = _mm_sub_pd(lambda, old_n), jt = _mm_sub_pd(lt, old_t);
  const __m128d wc = _mm_setr_pd(c0.w, c1.w), wb = _mm_setr_pd(b0.w, b1.w);
  const __m128d cn2 = _mm_add_pd(cn, _mm_mul_pd(_mm_mul_pd(wc, jn), sn));
  const __m128d bn2 = _mm_sub_pd(bn, _mm_mul_pd(_mm_mul_pd(wb, jn), sn));
  const __m128d ct2 = _mm_add_pd(ct, _mm_mul_pd(_mm_mul_pd(wc, jt), st));
  const __m128d bt2 = _mm_sub_pd(bt, _mm_mul_pd(_mm_mul_pd(wb, jt), st));
  const __m128d cx2 = y ? ct2 : cn2, cy2 = y ? cn2 : ct2, bx2 = y ? bt2 : bn2, by2 = y ? bn2 : bt2;
  // c0 before c1, b0 before b1: a fixed body both rows share gets either's (the same) values.
  _mm_storeu_pd(&c0.v.x, _mm_unpacklo_pd(cx2, cy2)), _mm_storeu_pd(&c1.v.x, _mm_unpackhi_pd(cx2, cy2));
  _mm_storeu_pd(&b0.v.x, _mm_unpacklo_pd(bx2, by2)), _mm_storeu_pd(&b1.v.x, _mm_unpackhi_pd(bx2, by2));
  _mm_storeu_pd(lambda_n, lambda);
  _mm_storel_pd(&f[0].lambda, lt), _mm_storeh_pd(&f[1].lambda, lt);
  const __m128i same = _mm_and_si128(_mm_cmpeq_epi32(_mm_castpd_si128(lambda), _mm_castpd_si128(old_n)),
                                     _mm_cmpeq_epi32(_mm_castpd_si128(lt), _mm_castpd_si128(old_t)));
  return _mm_movemask_epi8(same) != 0xFFFF;
}
#endif

// One sweep of iterate<false> over rows whose normals lie along component v
// of the velocity; whether any accumulated impulse changed. Each row's
// normal is +v (load_rows swapped the bodies of a -v row): the products by
// the normal's sign, -1 or 1, are left out. The same bits: a row of -v
// computed -(v_c - v_b), which is v_b - v_c but for the sign of a zero,
// and from a zero relative speed either sign gives the same impulse (the
// accumulated one is never -0: it starts at +0 or a positive warm start,
// and max(x, 0) is -0 only for x = -0, which only -0 minus a zero gives).
// Then v_c + (w_c j)(-1) is v_c - w_c j, bit for bit.
std::uint8_t ContactSolver::sweep_axis(std::span<const SolverRow> rows, std::span<double> lambdas,
                                       [[maybe_unused]] std::span<const std::uint8_t> paired, std::span<AxisBody> bodies) {
  std::uint8_t found = 0;
  for (std::size_t i = 0; i < rows.size();) {
#if defined(__SSE2__)
    if (paired[i]) {  // (never the last row of the span: schedule())
      found |= sweep_two(rows[i], rows[i + 1], &lambdas[i], bodies);
      i += 2;
      continue;
    }
#endif
    const SolverRow& r = rows[i];
    double& old = lambdas[i++];
    AxisBody& bc = bodies[r.c];
    AxisBody& bb = bodies[r.b];
    const double vn = bc.v - bb.v;
    const double lambda = std::max(old - (vn - r.target) * r.inv_w, 0.0);
    apply_axis_impulse(bc.v, bb.v, 1.0, lambda - old, bc.w, bb.w);
    // (An infinite or NaN accumulator counts as changing: its next impulse, inf - inf, would not be 0.)
    found |= (std::bit_cast<std::uint64_t>(lambda) != std::bit_cast<std::uint64_t>(old) || !(lambda < infinity) ? changed : 0) |
             (!keeps_unchanged || vn >= r.target ? 0 : short_of_target);  // (skips_pass(): not in the browser's build)
    old = lambda;
  }
  return found;
}

#if defined(__SSE2__)
// Two rows that share no linking body (a fixed one they share keeps its
// velocity: schedule()), one in each lane of SSE2's doubles, with the same
// operations in the same order as one row, so the same bits: each lane
// rounds as the scalar instruction does, and max(0, x) is (0 > x ? 0 : x),
// std::max(x, 0.0)'s choice for a NaN and for -0 too.
inline std::uint8_t ContactSolver::sweep_two(const SolverRow& r0, const SolverRow& r1, double* lambdas,
                                             std::span<AxisBody> bodies) {
  AxisBody& c0 = bodies[r0.c];
  AxisBody& b0 = bodies[r0.b];
  AxisBody& c1 = bodies[r1.c];
  AxisBody& b1 = bodies[r1.b];
  const __m128d vc = _mm_setr_pd(c0.v, c1.v), vb = _mm_setr_pd(b0.v, b1.v);
  const __m128d old = _mm_loadu_pd(lambdas);
  const __m128d vn = _mm_sub_pd(vc, vb);
  const __m128d target = _mm_setr_pd(r0.target, r1.target);
  const __m128d push = _mm_mul_pd(_mm_sub_pd(vn, target), _mm_setr_pd(r0.inv_w, r1.inv_w));
  const __m128d lambda = _mm_max_pd(_mm_setzero_pd(), _mm_sub_pd(old, push));
  const __m128d j = _mm_sub_pd(lambda, old);
  const __m128d vc2 = _mm_add_pd(vc, _mm_mul_pd(_mm_setr_pd(c0.w, c1.w), j));
  const __m128d vb2 = _mm_sub_pd(vb, _mm_mul_pd(_mm_setr_pd(b0.w, b1.w), j));
  _mm_storel_pd(&c0.v, vc2), _mm_storeh_pd(&c1.v, vc2);
  _mm_storel_pd(&b0.v, vb2), _mm_storeh_pd(&b1.v, vb2);
  _mm_storeu_pd(lambdas, lambda);
  // Bits, not values, as the scalar row compares them (a 32-bit compare: SSE2 has no 64-bit one).
  const bool same = _mm_movemask_epi8(_mm_cmpeq_epi32(_mm_castpd_si128(lambda), _mm_castpd_si128(old))) == 0xFFFF &&
                    _mm_movemask_pd(_mm_cmpnlt_pd(lambda, _mm_set1_pd(infinity))) == 0;  // (as sweep_axis: finite)
  return (same ? 0 : changed) |
         (_mm_movemask_pd(_mm_cmpnge_pd(vn, target)) != 0 ? short_of_target : 0);
}
#endif

// One friction row per contact if any contact has friction, none otherwise.
void ContactSolver::prepare_friction(const Components& k, bool any, bool kept_all) {
  if (kept_all && any && friction_.size() == contacts_.size()) {  // (the same pairs: the same coefficients)
    for (FrictionRow& f : friction_) f.lambda = f.lambda2 = 0.0;
    return;
  }
  friction_.clear();
  if (!any) return;
  friction_.reserve(contacts_.size());
  for (const ContactConstraint& ct : contacts_)
    friction_.push_back({pair_friction(k, ct.c, ct.b), 0.0, 0.0});
}

// Restitution, Poisson's way: each impact gets e times the impulse that
// stopped it. With one e for all contacts this is v+ = v_c + e (v_c - v-),
// v_c the inelastic (projected) velocity, so |v+| <= |v-| in the mass norm:
// the energy never grows, even for simultaneous contacts (a target velocity
// -e·v_n per contact, Newton's way, can gain energy there).
// (The inelastic velocities are copied only when some impact bounces: else
// they are the velocities themselves, which the energy guard reads then.)
void ContactSolver::restitution(Components& k, Vector g, const SolverSettings& s) {
  have_inelastic_ = false;
  if (std::none_of(impacts_.begin(), impacts_.end(), [&](std::uint32_t i) { return bounces(i); })) {
    guard_energy(k);
    return;
  }
  keep_inelastic(k);
  for (const std::uint32_t i : impacts_) {
    const ContactConstraint& ct = contacts_[i];
    if (bounces(i)) apply(k, ct, ct.restitution * impulses_[i].lambda);
  }
  // The bounce impulses were computed contact by contact: a light block
  // lying on the floor when a heavy one lands on it gets e times its share
  // pushing it into the floor, which nothing would then hold. Relax again.
  relax(k, g, s, true);
  guard_energy(k);
}

// An impact found before the bodies touch (gap > 0) happens at toi within the
// substep, not at its start: shift each body by toi·(v_before - v_after) of
// that impulse, so that Move's x += h·v ends it where the motion that changes
// velocity at toi does (what Ccd does at each impact). Without it a bounce
// happens up to |v|·h early, and under gravity each such bounce gains energy
// (g·v·h).
//
// And, as in Ccd, the gravity after the impact as gravity_after_impact says
// (contact.hpp), never enough to turn the pair back. A body landing on the
// floor then rests instead of hopping g·h, and an e = 1 bounce keeps its
// energy.
void ContactSolver::impact_time(Components& k, double h, Vector g, bool exact_motion) {
  for (const std::uint32_t i : impacts_) {
    const ContactConstraint& ct = contacts_[i];
    const Vector n = axis_normal[ct.axis];
    const Vector a = (ct.wc > 0.0 ? g : Vector{}) - (ct.wb > 0.0 ? g : Vector{});
    const double vn = Vector::dot(k.velocity[ct.c] - k.velocity[ct.b], n);
    const double e = last_round_ ? 0.0 : ct.restitution;  // the last round bounces nothing
    const double extra = std::max(gravity_after_impact(e, Vector::dot(a, n), h, ct.toi, exact_motion), -vn);
    if (extra == 0.0) continue;
    change_normal_velocity(k.velocity[ct.c], k.velocity[ct.b], n, extra, ct.wc, ct.wb);
  }
  // The shift uses each body's net velocity change (a light block lying on
  // the floor when a heavy one lands on it is held by the floor: it must not
  // be shifted by what the heavy one's impulse alone would do), and its
  // earliest such impact. toi_ is infinite but while this runs.
  toi_.resize(k.size(), infinity);
  for (const std::uint32_t i : impacts_) {
    const ContactConstraint& ct = contacts_[i];
    if (ct.toi <= 0.0) continue;
    toi_[ct.c] = std::min(toi_[ct.c], ct.toi);
    toi_[ct.b] = std::min(toi_[ct.b], ct.toi);
  }
  for (const std::uint32_t i : impacts_) {
    for (const EntityId e : {contacts_[i].c, contacts_[i].b}) {
      if (toi_[e] < infinity && std::isfinite(k.mass[e])) {
        k.position[e] = k.position[e] + toi_[e] * (v_start_[slot_of_[e]] - k.velocity[e]);
        if (line_start_[e] == 0.0) shifted_.push_back(e);
        line_start_[e] = std::max(line_start_[e], toi_[e]);
      }
      toi_[e] = infinity;  // once per body
    }
  }
}

// The resting contacts' impulses, for the next substep's warm start, by
// contact (last_jn_: 0 for none); the sorted list is made only when asked for.
// The contacts that are not resting are the impacts (make_contact()): with
// one round, every contact's impulse is kept, then the impacts' dropped, so
// that the pass reads the impulses and not the contacts.
void ContactSolver::store() {
  last_jn_.resize(contacts_.size());
  last_jt_.resize(contacts_.size());
  // (Spans, not the members: the stores could alias a vector's own pointers.)
  const std::span<const ContactConstraint> contacts(contacts_);
  const std::span<const ContactImpulse> impulses(impulses_);
  const std::span<const FrictionRow> friction(friction_);
  const std::span<const std::uint32_t> pair_of(pair_of_);
  const std::span<const double> earlier_jn(earlier_jn_), earlier_jt(earlier_jt_);
  const std::span<double> last_jn(last_jn_), last_jt(last_jt_);
  workers_or_one(workers_).for_ranges(contacts.size(), min_parallel_items, [&](int, std::size_t begin, std::size_t end) {
    // One round (most substeps): the sums below without the earlier rounds' terms (+ 0.0: a -0 becomes +0,
    // which only the tangential impulse keeps; the normal one is kept when positive).
    // (The browser's build, short of room, takes the general loop below: the same values.)
    for (std::size_t i = begin; keeps_unchanged && earlier_jn.empty() && i < end; ++i) {
      const double jn = impulses[i].lambda + impulses[i].lambda2;
      last_jn[i] = jn > 0.0 ? jn : 0.0;
      last_jt[i] = friction.empty() ? 0.0 : friction[i].lambda + friction[i].lambda2 + 0.0;
    }
    for (std::size_t i = begin; (!keeps_unchanged || !earlier_jn.empty()) && i < end; ++i) {
      const ContactConstraint& ct = contacts[i];
      const std::uint32_t p = pair_of[i];
      const bool earlier = p < earlier_jn.size();  // earlier rounds of this substep (keep_round())
      const double jn = impulses[i].lambda + impulses[i].lambda2 + (earlier ? earlier_jn[p] : 0.0);
      const bool keep = ct.resting && jn > 0.0;
      last_jn[i] = keep ? jn : 0.0;
      last_jt[i] =
          (friction.empty() ? 0.0 : friction[i].lambda + friction[i].lambda2) + (earlier ? earlier_jt[p] : 0.0);
    }
  });
  if (keeps_unchanged && earlier_jn.empty())
    for (const std::uint32_t i : impacts_) last_jn[i] = 0.0;
  restored_ = false;
}

// The impulses store() kept, as the sorted list of (pair key, axis, normal
// impulse, tangential impulse), into `out` (its memory kept from call to
// call: a settled 100 000-body rain whose contacts change asks for it at
// some substeps); `contacts`: the keys of the contacts they were stored for.
void ContactSolver::last_impulses(std::span<const TopologyKey> contacts,
                                  std::vector<std::tuple<std::uint64_t, int, double, double>>& out) const {
  out.clear();
  for (std::size_t i = 0; i < last_jn_.size(); ++i)
    if (last_jn_[i] > 0.0)
      out.emplace_back(key(contacts[i].c, contacts[i].b), static_cast<int>(contacts[i].flags & 3), last_jn_[i], last_jt_[i]);
  // (Mostly sorted already; the browser's build, short of room, sorts it anyway.)
  if (!keeps_unchanged || !std::is_sorted(out.begin(), out.end())) std::sort(out.begin(), out.end());
}

std::vector<WarmImpulse> ContactSolver::warm_impulses() const {
  std::vector<std::tuple<std::uint64_t, int, double, double>> last;
  if (!restored_) last_impulses(topology_, last);
  const auto& warm = restored_ ? warm_ : last;
  std::vector<WarmImpulse> out;
  out.reserve(warm.size());
  for (const auto& [kk, axis, jn, jt] : warm)
    out.push_back({{static_cast<EntityId>(kk >> 32), static_cast<EntityId>(kk & 0xFFFFFFFFu)}, axis, jn, jt});
  return out;
}

void ContactSolver::restore(std::span<const WarmImpulse> impulses) {
  warm_.clear();
  for (const WarmImpulse& w : impulses) warm_.emplace_back(w.pair.key(), w.axis, w.jn, w.jt);
  std::sort(warm_.begin(), warm_.end());
  restored_ = true;
}

// Poisson's restitution keeps the energy from growing only when the
// iterations have converged; a light body squeezed between two heavy ones
// (mass ratio 1e3 and more) does not converge in a few iterations, and
// warm starting or shock propagation can add a little too. So per island of
// touching finite bodies: if the kinetic energy ended above where it started,
// scale the restitution impulses down until it does not (and, if the
// inelastic velocities alone are above, move back towards the starting ones).
// The velocities after the inelastic relaxation, by slot (restitution()'s
// and the energy guard's v_inelastic_).
void ContactSolver::keep_inelastic(const Components& k) {
  for (std::size_t i = 0; i < slot_body_.size(); ++i) v_inelastic_[i] = k.velocity[slot_body_[i]];
  have_inelastic_ = true;
}

// Both are blends of impulse sets, so momentum is kept.
void ContactSolver::guard_energy(Components& k) {
  if (!any_body_gained(k)) return;
  if (!have_inelastic_) keep_inelastic(k);
  island_energies(k);
  // Largest s in [0, 1] with a s² + b s + c <= 0, given c <= 0.
  const auto largest = [](double a, double b, double c) {
    if (a + b + c <= 0.0) return 1.0;
    if (a <= 0.0) return b > 0.0 ? std::clamp(-c / b, 0.0, 1.0) : 1.0;
    const double s = (-b + std::sqrt(std::max(b * b - 4.0 * a * c, 0.0))) / (2.0 * a);
    return std::clamp(s, 0.0, 1.0);
  };
  std::vector<double> s_rest(sums_.size(), 1.0), s_back(sums_.size(), 1.0);
  bool any = false;
  for (std::size_t i = 0; i < sums_.size(); ++i) {
    const IslandEnergy& su = sums_[i];
    if (su.frames == 2 || su.end <= su.start * (1.0 + 1e-14)) continue;
    any = true;
    if (su.inel <= su.start) {
      s_rest[i] = largest(su.a_rest, su.b_rest, su.inel - su.start);
    } else {
      s_rest[i] = 0.0;
      s_back[i] = largest(su.a_back, su.b_back, 0.0);
    }
  }
  if (!any) return;
  for (const EntityId e : bodies_) {
    const std::uint32_t i = island_[e];
    if (s_rest[i] == 1.0 && s_back[i] == 1.0) continue;
    const std::uint32_t slot = slot_of_[e];
    const Vector vi = v_start_[slot] + s_back[i] * (v_inelastic_[slot] - v_start_[slot]);
    k.velocity[e] = vi + s_rest[i] * (k.velocity[e] - v_inelastic_[slot]);
    ++stats.energy_clamps;
  }
}

// When no body of a contact ends with more kinetic energy than it started
// with, no island can have gained (each island's sums add the same per-body
// terms, and rounding is monotone): nothing to do. A resting pile is the
// common case, and this skips the islands' bookkeeping there. (Not so in the
// frame of a moving fixed body: then the islands are always looked at.)
bool ContactSolver::any_body_gained(const Components& k) const {
  if (moving_fixed_) return true;
  for (std::size_t i = 0; i < slot_body_.size(); ++i) {
    const EntityId e = slot_body_[i];
    const double m = k.mass[e];
    const Vector v0 = v_start_[i], v1 = k.velocity[e];
    if (std::isfinite(m) && 0.5 * m * Vector::dot(v1, v1) > 0.5 * m * Vector::dot(v0, v0)) return true;
  }
  return false;
}

// The bodies marked in seen_, by id, the marks cleared. Eight marks a word:
// the contacts' bodies of a rain's landing rows (a few thousand of 100 000)
// lie in runs of ids, and the words between are skipped whole (the guard's
// islands at 100 000 bodies: 70 -> 45 µs a call against sorting the ids).
void ContactSolver::list_marked(std::size_t n) {
  bodies_.clear();
  std::uint8_t* const seen = seen_.data();
  std::size_t e = 0;
  for (; e + 8 <= n; e += 8) {
    std::uint64_t word;
    std::memcpy(&word, seen + e, sizeof word);
    if (word == 0) continue;
    for (std::size_t i = e; i < e + 8; ++i)
      if (seen[i]) bodies_.push_back(static_cast<EntityId>(i)), seen[i] = 0;
  }
  for (; e < n; ++e)
    if (seen[e]) bodies_.push_back(static_cast<EntityId>(e)), seen[e] = 0;
}

// The islands of touching finite bodies (union-find over the contacts):
// bodies_ (the finite bodies of the contacts, in increasing id order: the
// order the sums are taken in), island_ of each (numbered as their roots
// are first met), one IslandEnergy a island in sums_. They depend on the
// contacts only: found once a round (islands_found_), on a team beside the
// helper's plan of the y rows (solve_velocities()) or its new support order
// (relax()).
void ContactSolver::find_islands(std::size_t n) {
  islands_.resize(n);
  for (const ContactConstraint& ct : contacts_) islands_.add(ct.c), islands_.add(ct.b);
  for (const ContactConstraint& ct : contacts_)
    if (ct.wc > 0.0 && ct.wb > 0.0) islands_.join(ct.c, ct.b);
  // The finite bodies of the contacts, by id: marked, then listed by a look
  // at every mark, or, when they are few against the world (a rain's lowest
  // rows landing), sorted. seen_ and root_index_ are left as they were found
  // (0, none), so no pass over the world sets them.
  bodies_.clear();
  seen_.resize(n, 0);
  const auto mark = [&](EntityId e, double w) {
    if (w > 0.0 && !seen_[e]) seen_[e] = 1, bodies_.push_back(e);
  };
  for (const ContactConstraint& ct : contacts_) mark(ct.c, ct.wc), mark(ct.b, ct.wb);
  if (keeps_unchanged && bodies_.size() * 128 < n) {  // (the browser's build, short of room, reads every mark)
    std::sort(bodies_.begin(), bodies_.end());
    for (const EntityId e : bodies_) seen_[e] = 0;
  } else {
    list_marked(n);
  }
  island_.resize(n);
  root_index_.resize(n, none);
  sums_.clear();
  for (const EntityId e : bodies_) {
    const EntityId r = islands_.find(e);
    if (root_index_[r] == none) root_index_[r] = static_cast<std::uint32_t>(sums_.size()), sums_.emplace_back();
    island_[e] = root_index_[r];
  }
  for (const EntityId e : bodies_) root_index_[e] = none;  // (every root is among them)
  islands_found_ = true;
}

// Per island (find_islands()), the energies the guard needs: sums_.
void ContactSolver::island_energies(const Components& k) {
  if (!islands_found_) find_islands(k.size());
  std::fill(sums_.begin(), sums_.end(), IslandEnergy{});
  for (const ContactConstraint& ct : contacts_) {
    if ((ct.wc > 0.0) == (ct.wb > 0.0)) continue;  // the fixed bodies an island touches
    const EntityId body = ct.wc > 0.0 ? ct.c : ct.b, fixed = ct.wc > 0.0 ? ct.b : ct.c;
    IslandEnergy& su = sums_[island_[body]];
    if (su.frames == 0) su.frame = k.velocity[fixed], su.frames = 1;
    else if (su.frames == 1 && !(su.frame == k.velocity[fixed])) su.frames = 2;
  }
  for (const EntityId e : bodies_) {
    const std::uint32_t i = island_[e];
    const double m = k.mass[e];
    const Vector u = sums_[i].frame;
    const Vector v0 = v_start_[slot_of_[e]] - u, vi = v_inelastic_[slot_of_[e]] - u, v1 = k.velocity[e] - u;
    const Vector rest = v1 - vi, back = vi - v0;
    IslandEnergy& su = sums_[i];
    su.start += 0.5 * m * Vector::dot(v0, v0);
    su.inel += 0.5 * m * Vector::dot(vi, vi);
    su.end += 0.5 * m * Vector::dot(v1, v1);
    su.b_rest += m * Vector::dot(vi, rest);
    su.a_rest += 0.5 * m * Vector::dot(rest, rest);
    su.b_back += m * Vector::dot(v0, back);
    su.a_back += 0.5 * m * Vector::dot(back, back);
  }
}

void ContactSolver::solve_positions(Components& k, std::span<const EntityId> entities, Vector g,
                                    const SolverSettings& s, BroadPhase& broadphase, StageTimes& times) {
  // Touching pairs too (within the margin): they take no correction but link
  // the support graph of the bottom-up pass down to the ground.
  StageTimes::Laps laps(times);
  workers_ = s.workers;
  // Nothing to project if no pair overlaps beyond the slop. When no body
  // has left the box the velocity stage's last find() swept for it, the
  // pairs that overlap now are among that stage's (pairs_ holds them all):
  // looked for there, without finding the pairs again.
  bool none = false;
  laps.time(Stage::pairs, [&] {
    // (The browser's build, short of room, always finds them again: the same pairs overlap.)
    // (Overlaps first: when one is found, the pairs are found again whether
    // the bodies held or not, and the look at every body is saved.)
    none = keeps_unchanged && broadphase.finds() == velocity_finds_ && !any_overlap(k, s.slop) &&
           broadphase.holds(k, entities, s.workers);
    if (none) return;
    broadphase.find(k, entities, 0.0, s.margin, pairs_, PairRule::solvable, s.workers);
    classified_ = false;  // (pairs_ is no longer the list classified)
  });
  if (none) return;
  laps.time(Stage::positions, [&] {
    if (prepare_positions(k, s)) project(k, g, s);
  });
}

// Whether some pair of pairs_ overlaps by more than `slop`. A pair of the
// list classified last whose bodies have kept their position and box since
// (a resting pile's, nearly all) has the separation classify() found.
// Whether any of those is below -slop is asked once per classification
// (classified_overlap_): when none is, a resting pile's substeps read the
// pairs' moved flags, not their 32-byte axes (a settled rain of 100 000: 8 %
// of its step), and when no body moved, only the pairs found after it.
bool ContactSolver::any_overlap(const Components& k, double slop) {
  const std::size_t n = k.size();
  if (!keeps_unchanged || !classified_ || classified_bodies_.size() != n)
    return std::any_of(pairs_.begin(), pairs_.end(), [&](const Pair& p) { return overlaps(k, p, slop); });
  const std::span<const Vector> position(k.position);
  const std::span<const Rect> boxes(k.box);
  const std::span<const ClassifiedBody> bodies(classified_bodies_);
  const auto moved = [&](EntityId e) {
    return place_differs(bodies[e].position, bodies[e].box, position[e], boxes[e]) != 0;
  };
  const std::size_t known = classified_pairs_.size();  // pairs_ starts with them (turned_to_meet() appends)
  Workers& w = workers_or_one(workers_);
  if (!overlap_known_ || bits_differ(overlap_slop_, slop)) {
    classified_overlap_ = w.or_over_ranges(known, min_parallel_items, [&](int, std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i)
        if (axes_[i].separation < -slop) return std::uint8_t{1};
      return std::uint8_t{0};
    }) != 0;
    overlap_known_ = true, overlap_slop_ = slop;
  }
  const auto any = [&](auto moved_pair, bool none_moved) {
    const std::size_t from = none_moved && !classified_overlap_ ? known : 0;
    return w.or_over_ranges(pairs_.size() - from, min_parallel_items, [&](int, std::size_t begin, std::size_t end) {
      for (std::size_t i = from + begin; i < from + end; ++i) {
        const Pair p = pairs_[i];
        if (i < known && !moved_pair(p) ? classified_overlap_ && axes_[i].separation < -slop : overlaps(k, p, slop))
          return std::uint8_t{1};
      }
      return std::uint8_t{0};
    }) != 0;
  };
  // A pile has several pairs a body: each body is then looked at once
  // (moved_), not at each of its pairs (a falling rain's few pairs: at each).
  if (pairs_.size() < n) return any([&](Pair p) { return moved(p.c) || moved(p.b); }, false);
  moved_.resize(n);
  const std::span<std::uint8_t> moved_by(moved_);
  const bool any_moved = w.or_over_ranges(n, min_parallel_items, [&](int, std::size_t begin, std::size_t end) {
    std::uint8_t some = 0;
    for (std::size_t e = begin; e < end; ++e) some |= moved_by[e] = moved(static_cast<EntityId>(e));
    return some;
  }) != 0;
  return any([&](Pair p) { return (moved_by[p.c] | moved_by[p.b]) != 0; }, !any_moved);
}

// Whether any pair overlaps by more than the slop; if so, the contacts
// within the margin. A resting pile often has no such overlap: then the
// look stops there, without listing the contacts.
bool ContactSolver::prepare_positions(const Components& k, const SolverSettings& s) {
  positions_.clear();
  if (!any_overlap(k, s.slop)) return false;
  classified_ = false;  // (axes_ now holds the pairs' axes after Move)
  contact_axes(k, s);
  Workers& w = workers_or_one(s.workers);
  w.append_over_ranges(pairs_.size(), min_parallel_items, positions_,
                       [&](int t) -> auto& { return part_of(position_parts_, t, w.threads()); },
                       [&](int, std::size_t begin, std::size_t end, std::vector<PositionContact>& part) {
                         for (std::size_t i = begin; i < end; ++i)
                           if (!(axes_[i].separation > s.margin))
                             part.push_back({pairs_[i].c, pairs_[i].b, axes_[i].axis, 0, 0.0, 0.0, 0.0, 0.0});
                       });
  return true;
}

// A later round (rounds after a turn) starts from where impact_time put each
// impacted body: the start of its new line, which for a fast body that
// bounced late in the substep lies behind the face it bounced off, inside
// the body it hit (pile seed 30: a 13 px block falling 42 px a substep,
// 26 px into the floor at toi 12 of 16.7 ms), where the shortest way out is
// through the far side; that round's contact sent it on down through the
// floor (two blocks out, under stable and auto). So a pair with such a body
// takes its axis where both bodies really are, at the later of their lines'
// start times, when the line-start one is the far side of it, and its gap
// along it from the lines' starts as the others. (Every such pair's axis
// taken there lost an e = 1 gas 0.07-0.1 % of its energy under stable: the
// family's gas seeds 4 and 23, and sank pile seed 46 by 1.5 px.)
void ContactSolver::physical_axes(const Components& k, const SolverSettings& s) {
  if (!s.physical_axes || shifted_.empty()) return;
  for (std::size_t i = 0; i < pairs_.size(); ++i) {
    const EntityId c = pairs_[i].c, b = pairs_[i].b;
    const double t = std::max(line_start_[c], line_start_[b]);
    if (t == 0.0) continue;
    const Vector vc = k.velocity[c], vb = k.velocity[b];
    const auto gaps = axis_gaps(k.position[c] + t * vc, k.box[c], k.position[b] + t * vb, k.box[b]);
    ContactAxis& a = axes_[i];
    const int axis = contact_axis(gaps, vc - vb, s.touch).axis;
    if (axis != (a.axis ^ 1)) continue;
    a.axis = axis;
    a.gap = axis_gaps(k, c, b)[static_cast<std::size_t>(a.axis)];
  }
}

// Each pair's normal (contact_axis). Pairs that touch corner to corner take
// the axis of their bodies' face contacts: only those bodies' pairs (marked
// with bit 2 of faces_) are looked at for them, and only when there is such a pair.
void ContactSolver::contact_axes(const Components& k, const SolverSettings& s) {
  overlap_known_ = false;
  axes_.resize(pairs_.size());
  Workers& w = workers_or_one(s.workers);
  const bool corners = w.or_over_ranges(pairs_.size(), min_parallel_items, [&](int, std::size_t begin, std::size_t end) {
    bool any = false;
    for (std::size_t i = begin; i < end; ++i) any = plain_axis(k, i, s.touch) || any;
    return static_cast<std::uint8_t>(any);
  });
  if (corners) corner_axes(k, s, false);
}

// Pair i's contact_axis without faces, into axes_[i]; whether its boxes
// touch corner to corner (then corner_axes() decides its axis).
inline bool ContactSolver::plain_axis(const Components& k, std::size_t i, double touch) {
  axes_[i] = contact_axis(k, pairs_[i].c, pairs_[i].b, touch);
  return axes_[i].corner;
}

// The axes of the pairs that touch corner to corner, once every pair has its
// plain axis (contact_axis without faces) in axes_.
// `local` (classify() kept the unchanged pairs' axes): a corner pair's axis
// depends on its bodies and on their other pairs' plain axes, so it is taken
// again only when one of its bodies, or a body paired with one of them, has
// changed (faces_' bit `tainted`); the others keep theirs.
void ContactSolver::corner_axes(const Components& k, const SolverSettings& s, bool local) {
  constexpr std::uint8_t wanted = 4;
  faces_.assign(k.size(), local ? 0 : tainted);
  if (keeps_unchanged && local)
    for (const Pair& p : pairs_)
      if (changed_[p.c] | changed_[p.b]) faces_[p.c] |= tainted, faces_[p.b] |= tainted;
  const auto taken = [&](std::size_t i) {
    return axes_[i].corner && ((faces_[pairs_[i].c] | faces_[pairs_[i].b]) & tainted);
  };
  for (std::size_t i = 0; i < pairs_.size(); ++i)
    if (taken(i)) faces_[pairs_[i].c] |= wanted, faces_[pairs_[i].b] |= wanted;
  for (std::size_t i = 0; i < pairs_.size(); ++i) {
    const Pair& p = pairs_[i];
    if (!((faces_[p.c] | faces_[p.b]) & wanted)) continue;
    // axes_[i] is still the pair's contact_axis without faces (touching_face's), or a corner pair's (then 0).
    const auto f = static_cast<std::uint8_t>(touching_face(axes_[i], s.touch));
    faces_[p.c] |= f, faces_[p.b] |= f;
  }
  for (std::size_t i = 0; i < pairs_.size(); ++i) {
    const Pair& p = pairs_[i];
    if (taken(i)) axes_[i] = contact_axis(k, p.c, p.b, s.touch, (faces_[p.c] | faces_[p.b]) & 3);
  }
}

// Signed distance between the boxes of a position contact along its axis
// (negative: overlap), from their Minkowski difference s = b ⊖ c (the
// sheet's mdiff): -x: s.x, +x: -(s.x + s.w), -y: s.y, +y: -(s.y + s.h).
// Rect::mdiff's arithmetic, written out with the box sizes it adds taken
// once per substep (same operations in the same order, so the same bits):
// this runs per contact per iteration.
// Selects, not branches: the axes of a pile's contacts alternate unpredictably.
inline double ContactSolver::gap(const Components& k, const PositionContact& ct) {
  const Vector pc = k.position[ct.c], pb = k.position[ct.b];
  const bool y = ct.axis >= 2;
  const double d = (y ? pb.y : pb.x) - (y ? pc.y : pc.x) - ct.size_c;
  return ct.axis & 1 ? -(d + ct.sizes) : d;
}

// One contact of the projection: its bodies pushed apart by `projection`
// of its overlap beyond the slop, each by its share; whether it pushed. A
// fixed end is not written (it would take (push·0)·n, which leaves it as it
// is unless a coordinate is -0: then it moves, links()), so that threads
// sweeping at once never write the floor that all their blocks read.
inline bool ContactSolver::project_contact(Components& k, const PositionContact& ct, const SolverSettings& s) {
  const double depth = -gap(k, ct) - s.slop;
  if (!(depth > 0.0)) return false;
  const Vector n = axis_normal[ct.axis];
  const double push = s.projection * depth;
  if (ct.moves & 1) k.position[ct.c] = k.position[ct.c] + (push * ct.share_c) * n;
  if (ct.moves & 2) k.position[ct.b] = k.position[ct.b] - (push * ct.share_b) * n;
  return true;
}

// Each position contact's sizes along its axis, its bodies' shares of a
// correction and its moving ends, and its key (position_keys_next_).
void ContactSolver::measure_positions(const Components& k, const SolverSettings& s) {
  position_keys_next_.resize(positions_.size());
  workers_or_one(s.workers).for_ranges(positions_.size(), min_parallel_items, [&](int, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      PositionContact& ct = positions_[i];
      const Rect rc = k.box[ct.c], rb = k.box[ct.b];
      const bool x = ct.axis < 2;
      ct.size_c = x ? rc.width : rc.height;
      ct.sizes = x ? rb.width + rc.width : rb.height + rc.height;
      const double wc = inverse_mass(k.mass[ct.c]), wb = inverse_mass(k.mass[ct.b]);
      const double w = wc + wb;
      ct.share_c = wc / w, ct.share_b = wb / w;
      ct.moves = static_cast<std::uint8_t>(links(wc, k.position[ct.c]) | links(wb, k.position[ct.b]) << 1);
      const auto flags = static_cast<std::uint32_t>(ct.axis) | (wc == 0.0) << 2 | (wb == 0.0) << 3 | ct.moves << 4;
      position_keys_next_[i] = {ct.c, ct.b, flags};
    }
  });
}

// Non-linear Gauss-Seidel on positions, shared in proportion to inverse
// masses, then the same bottom-up pass as the velocities'. A sweep that
// pushes nothing ends the sweeps (the next would find the same overlaps).
void ContactSolver::project(Components& k, Vector g, const SolverSettings& s) {
  measure_positions(k, s);
  // The order and the sweeps' plan depend only on the contacts' bodies,
  // axes and moving ends, and (the order) on gravity: a resting pile keeps
  // them from substep to substep.
  position_keys_.swap(position_keys_next_);
  const bool same_contacts = have_position_keys_ && position_keys_ == position_keys_next_;
  have_position_keys_ = true;
#if PHYSICS_HAS_THREADS
  if (!same_contacts) projection_pipeline_.forget();
#endif
  const auto sweeps = [&] {
#if PHYSICS_HAS_THREADS
    Workers& w = workers_or_one(workers_);  // (none beside an order: beside())
    if (w.splits(positions_.size(), min_parallel_items) && s.iterations > 0 && pipelines_pay(w))
      return pipelined_projection(k, s, w);
#endif
    for (int it = 0; it < s.iterations; ++it) {
      bool pushed = false;
      for (const PositionContact& ct : positions_) pushed = project_contact(k, ct, s) || pushed;
      if (!pushed) return;
    }
  };
  if (!s.shock_propagation) {
    have_position_order_ = false;  // (not made for these contacts)
    return sweeps();
  }
  const bool new_order = !have_position_order_ || g != position_g_ || !same_contacts;
  const auto order = [&] {
    const auto ends = [&](std::size_t i) { return support_ends(position_keys_[i]); };  // (this projection's)
    position_order_ = shock_passes(positions_.size(), ends, k.size(), g, support_ids_, support_met_), position_g_ = g,
    have_position_order_ = true;
  };
  if (new_order && aside()) {
    beside(sweeps, order);
    ++stats.orders_beside;
  } else {
    sweeps();
    if (new_order) order();
  }
  for (const ShockPass& pass : position_order_)
    for (const ShockRow& r : pass.rows) {
      const PositionContact& ct = positions_[r.index];
      const double depth = -gap(k, ct) - s.slop;
      if (!(depth > 0.0)) continue;
      const Vector n = axis_normal[ct.axis];
      if (r.c_upper)
        k.position[ct.c] = k.position[ct.c] + depth * n;
      else
        k.position[ct.b] = k.position[ct.b] - depth * n;
    }
}

#if PHYSICS_HAS_THREADS
// The projection's contacts in the order its sweeps take them on two
// threads (projection_order_), and its blocks. Each contact reads its two
// bodies and writes its moving ends only (project_contact()), so a fixed
// end ties no block to another, and its contacts go among their moving
// bodies' (SweepPipeline::defer_one_ended: the walls' contacts reach from
// the bottom of a pile to its top).
void ContactSolver::plan_projection(std::size_t body_count) {
  projection_order_.resize(positions_.size());
  std::iota(projection_order_.begin(), projection_order_.end(), 0u);
  projection_pipeline_.defer_one_ended(projection_order_, body_count, [&](std::uint32_t i) {
    return SweepPipeline::Ends{positions_[i].c, positions_[i].b, positions_[i].moves};
  });
  const std::span<const SweepPipeline::Ends> ends = projection_pipeline_.ends();
  projection_pipeline_.plan(
      positions_.size(), body_count, pipeline_block,
      [&](std::size_t i, auto&& body) {
        if (ends[i].moving & 1) body(ends[i].c);
        if (ends[i].moving & 2) body(ends[i].b);
      },
      [](std::size_t) { return false; });
}

// Whether sweeps pipelined on two threads (whose blocks wait for each
// other's) are worth running: the helpers come at once (Workers::prompt).
// Otherwise one thread sweeps: the same bits.
bool ContactSolver::pipelines_pay(const Workers& w) {
  if (w.prompt()) return true;
  ++stats.pipelines_left;
  return false;
}

void ContactSolver::pipelined_projection(Components& k, const SolverSettings& s, Workers& w) {
  if (!projection_pipeline_.planned()) plan_projection(k.size());
  ++stats.projections_pipelined;
  const std::span<const std::uint32_t> order(projection_order_);
  projection_pipeline_.run(w, s.iterations, 1, [&](std::size_t from, std::size_t count) {
    bool pushed = false;
    for (const std::uint32_t i : order.subspan(from, count)) pushed = project_contact(k, positions_[i], s) || pushed;
    return static_cast<std::uint8_t>(pushed);
  });
}
#endif

}  // namespace physics
