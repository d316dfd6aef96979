#include "engine/auto_mode.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "engine/pairs.hpp"

namespace physics {

bool AutoMode::plan(const Components& k, std::span<const EntityId> bodies, double h, Vector gravity) {
  // A scene under gravity starts with a solver substep: its bodies may be
  // resting on each other already (then after_solver holds the solver), and
  // three course passes would let a pile sink before it was seen.
  first_ = !started_ && !Vector::is_zero(gravity);
  started_ = true;
  ++substep_;
  h_ = h;
  if (hold_left_ > 0) --hold_left_;
  if (jam_left_ > 0) --jam_left_;
  if (start_set_ || start_.size() != k.size()) start_.assign(k.size(), 0.0), start_set_ = false;
  mark_fast(k, bodies, h, true);
  // Under gravity, the solver too when bodies bounce (the course's pass
  // reflects the whole substep's kick: the e = 1 long run's energy creeps
  // up) or when a body is fast: what it lands on may be a pile, and CCD
  // alone would carry it down the pile one impact at a time, without end.
  const bool g = !Vector::is_zero(gravity);
  gravity_ = g;
  const bool bouncing = g && bouncy(k, bodies);
  solver_path_ = first_ || hold_left_ > 0 || jam_left_ > 0 ||
                 (g && (fast_count_ > 0 || bouncing || seamed(k, bodies, gravity) || landing(k, bodies, h)));
  // Many fast bodies without gravity: the solver's path too, on trial (see
  // roll_back).
  trial_ = !solver_path_ && fast_count_ > many_fast;
  solver_path_ = solver_path_ || trial_;
  // Elastic without gravity (a row, a gas), in worlds where CCD's
  // re-prediction of each impact against every body stays cheap: the
  // solver takes a substep's impacts together, which loses energy (an e = 1
  // row or gas on the solver's path lost up to 19 % of it), so CCD takes
  // every impact. Held for pressed pairs (bodies in each other: a crowd
  // spawned so), the solver stays for its projection (sweep_all); on trial
  // only (many fast bodies), the path is ccd's: the course's pass with
  // every body swept.
  const bool elastic_free = solver_path_ && !g && jam_left_ == 0 && bodies.size() <= undo_bodies && elastic(k, bodies);
  sweep_all_ = solver_path_ && jam_left_ == 0 && ((bouncing && elastic(k, bodies)) || (elastic_free && !trial_));
  if (trial_ && elastic_free) {
    solver_path_ = trial_ = false;
    for (const EntityId e : bodies) fast_count_ += !fast_[e], fast_[e] = 1;
  }
  trial_ = trial_ && bodies.size() <= undo_bodies;  // beyond, the trial is the solver's path as it is
  // On the course's path, pairs the last pass left overlapping close through
  // sooner (a row pushed out pair by pair leaves them so, still approaching).
  const double bound = overlap_bound_;
  overlap_bound_ = infinity;  // unknown until the next pass says
  if (!solver_path_ && bound > 0.0 && std::sqrt(sq1_) + std::sqrt(sq2_) > thinnest_ - bound)
    mark_closing(k, bodies, h, bound);
  ++(solver_path_ ? stats.solver_substeps : stats.course_substeps);
  return solver_path_;
}

bool AutoMode::bouncy(const Components& k, std::span<const EntityId> bodies) {
  return std::any_of(bodies.begin(), bodies.end(),
                     [&](EntityId e) { return std::isfinite(k.mass[e]) && k.restitution[e] > 0.0; });
}

// Every restitution 1 (a pair's is the smaller of its two), and the finite
// masses within elastic_mass_ratio of each other. Then CCD never meets an
// inelastic collapse (each impact keeps the energy, and a body resting on
// another leaves it at 0: gravity_after_impact), and a light body caught
// between a heavy one and the floor is done with in about π·sqrt(M/m)
// impacts, fewer than the budget's 128 (at 1e12 it would be millions).
bool AutoMode::elastic(const Components& k, std::span<const EntityId> bodies) {
  double lightest = infinity, heaviest = 0.0;
  for (const EntityId e : bodies) {
    if (k.restitution[e] != 1.0) return false;
    if (!std::isfinite(k.mass[e])) continue;
    lightest = std::min(lightest, k.mass[e]);
    heaviest = std::max(heaviest, k.mass[e]);
  }
  return heaviest < elastic_mass_ratio * lightest;
}

// Whether two fixed bodies lie side by side, touching, along a face that
// gravity presses bodies onto (a floor of touching blocks under gravity
// down, a wall of them under gravity sideways). A body resting on such a
// surface crosses the seams, and the course's pass, which takes each pair
// alone by its shortest way out, pushes it sideways there (a ghost
// collision: it stops at the seam); the solver's contact axis follows the
// faces already touching. The course's four walls have no such seam.
bool AutoMode::seamed(const Components& k, std::span<const EntityId> bodies, Vector g) {
  const auto any_seam = [&](bool vertical_axis, bool low_side) {
    faces_.clear();
    for (const EntityId e : bodies) {
      if (std::isfinite(k.mass[e]) || !Vector::is_zero(k.velocity[e])) continue;  // moving platforms aside
      const Vector p = k.position[e];
      const double w = k.box[e].width, h = k.box[e].height;
      if (vertical_axis) faces_.push_back({low_side ? p.y : p.y + h, p.x, p.x + w});  // a floor or a ceiling
      else faces_.push_back({low_side ? p.x : p.x + w, p.y, p.y + h});                // a wall's face
    }
    std::sort(faces_.begin(), faces_.end());  // by level, then where it starts
    for (std::size_t i = 1; i < faces_.size(); ++i)
      if (faces_[i][0] == faces_[i - 1][0] && std::abs(faces_[i][1] - faces_[i - 1][2]) <= 1e-9) return true;
    return false;
  };
  // Gravity down (y grows downwards) presses bodies onto top faces, and so on.
  return (g.y != 0.0 && any_seam(true, g.y > 0.0)) || (g.x != 0.0 && any_seam(false, g.x > 0.0));
}

// Fast: Move's displacement, h·|v| (the velocity after Forces), exceeds
// the body's reach (CcdSelection::reach): half of its thinnest side plus the
// world's thinnest; an overlap up to that is pushed out on the side it came
// from. Sides do not change from one substep to the next, so one pass uses
// the last substep's thinnest and checks it, and runs again only when it
// changed (the first substep, a thinner body added, the thinnest removed).
// Then, if `closing`, the pairs of bodies that close faster than that
// (mark_closing).
void AutoMode::mark_fast(const Components& k, std::span<const EntityId> bodies, double h, bool closing) {
  fast_.resize(k.size());
  // Raw pointers: a byte store may alias anything, and through the vectors
  // every iteration would load their data pointers again.
  const Rect* box = k.box.data();
  const Vector* velocity = k.velocity.data();
  std::uint8_t* fast = fast_.data();
  double d1 = 0, d2 = 0;  // the two largest squared displacements of the bodies that are not fast
  for (;;) {
    const double world_thinnest = thinnest_;
    int thinnest = std::numeric_limits<int>::max();
    std::size_t count = 0;
    d1 = d2 = 0;
    for (const EntityId e : bodies) {
      const int side = std::min(box[e].width, box[e].height);
      thinnest = std::min(thinnest, side);
      const double reach = CcdSelection::reach(side, world_thinnest);
      const double dx = h * velocity[e].x, dy = h * velocity[e].y;
      const double d = dx * dx + dy * dy;
      const bool is_fast = d > reach * reach;  // squared: no root per body
      fast[e] = is_fast;
      count += is_fast;
      if (!is_fast && d > d2) (d > d1 ? d2 = d1, d1 = d : d2 = d);
    }
    fast_count_ = count;
    if (static_cast<double>(thinnest) == thinnest_ || bodies.empty()) break;
    thinnest_ = thinnest;
  }
  // Two bodies that are not fast close at most sqrt(d1) + sqrt(d2), and a
  // pair tunnels only past half its two sides, at least the thinnest.
  sq1_ = d1, sq2_ = d2;
  if (closing && std::sqrt(d1) + std::sqrt(d2) > thinnest_) mark_closing(k, bodies, h, 0.0);
}

// Closing speeds: two bodies, each within its reach, may still approach each
// other by more than half their two sides in a substep (head on, each at
// their reach: twice it), and pass through each other. The bodies that may
// be in such a pair (their displacement plus the largest other one exceeds
// their reach) are the candidates; of them, the pairs whose swept boxes meet
// and that close through (CcdSelection::closes_through) are marked fast, both
// bodies (a sort on x and a sweep, not all pairs). With overlap_bound > 0,
// no pair overlaps deeper than it: a pair's own overlap counts, and the
// candidates' reach is that much shorter.
void AutoMode::mark_closing(const Components& k, std::span<const EntityId> bodies, double h, double overlap_bound) {
  closing_.clear();
  for (const EntityId e : bodies) {
    if (fast_[e]) continue;
    const double dx = h * k.velocity[e].x, dy = h * k.velocity[e].y, sq = dx * dx + dy * dy;  // as mark_fast, to the bit
    const double other = std::sqrt(sq == sq1_ ? sq2_ : sq1_);
    if (std::sqrt(sq) + other <= selection().reach(k, e) - overlap_bound) continue;
    closing_.push_back(candidate(k, e, h));
  }
  meeting([&](EntityId a, EntityId b) {
    if (CcdSelection::closes_through(k, a, b, 0.0, h, overlap_bound > 0.0)) {
      fast_count_ += !fast_[a] + !fast_[b];
      fast_[a] = fast_[b] = 1;
    }
    return false;
  });
}

// Under gravity, whether two finite bodies may meet in this substep (their
// boxes swept over it overlap). The course's pass would take that landing:
// it pushes the pair apart by their masses, the lighter one into what
// carries it and back out, and a heavy body landing on a light one on the
// floor gains energy from it (the family's ratio-stack: up to 4e-3 of it, at
// mass ratios of 1e3 to 1e10 with e = 0). The solver takes the landing, then
// holds for the pair it presses (count_pressed).
bool AutoMode::landing(const Components& k, std::span<const EntityId> bodies, double h) {
  closing_.clear();
  for (const EntityId e : bodies)
    if (std::isfinite(k.mass[e])) closing_.push_back(candidate(k, e, h));
  return closing_.size() > 1 && meeting([](EntityId, EntityId) { return true; });
}

// closing_ by the left edge of its boxes (meeting's sweep). Not in the
// template: one sort for both callers (the web build's size).
void AutoMode::sort_closing() {
  std::sort(closing_.begin(), closing_.end(), [](const Candidate& a, const Candidate& b) {
    return a.box.x0 < b.box.x0 || (a.box.x0 == b.box.x0 && a.e < b.e);
  });
}

// Calls f(a, b) for each pair of closing_'s boxes that overlap (a sort on x
// and a sweep, not all pairs) until f returns true; whether one did.
template <class F>
bool AutoMode::meeting(F&& f) {
  sort_closing();
  const std::vector<Candidate>& c = closing_;
  for (std::size_t i = 0; i < c.size(); ++i)
    for (std::size_t j = i + 1; j < c.size() && c[j].box.x0 < c[i].box.x1; ++j)
      if (c[j].box.y0 < c[i].box.y1 && c[i].box.y0 < c[j].box.y1 && f(c[i].e, c[j].e)) return true;
  return false;
}

void AutoMode::keep(const Components& k) {
  if (!trial_) return;
  kept_position_ = k.position;
  kept_velocity_ = k.velocity;
}

// The solver takes the impacts of a substep together: a body with two
// contacts that pushed it, one of them a bounce, has them solved at once and
// the bounce relaxed again (Poisson's restitution with the after-bounce
// pass), which loses energy (a fast e = 1 gas of 8 px blocks at 2 px/ms lost
// 60 % in 3000 frames; an isolated pair keeps it to rounding), and its energy
// guard scales back the bounces of a whole island. CCD takes impacts one
// after the other, exactly, but costs more where such chains are rare (the
// matrix's 1 px blocks). So the solver is tried, and the islands (bodies
// joined by the solver's contacts, as its guard joins them: through finite
// bodies) that had such a chain, or whose energy changed though all their
// contacts have e = 1, are put back as they were and swept from the start.
void AutoMode::roll_back(Components& k, std::span<const EntityId> bodies, std::span<const ContactConstraint> contacts,
                         std::span<const ContactImpulse> impulses) {
  if (any_undone_) std::fill(undone_.begin(), undone_.end(), 0), any_undone_ = false;
  if (!trial_) return;
  undone_.resize(k.size(), 0);
  root_.resize(k.size());
  islands_.resize(k.size());
  for (const EntityId e : bodies) root_.add(e), islands_[e] = {};
  const auto find = [&](EntityId e) { return root_.find(e); };
  for (const ContactConstraint& ct : contacts)
    if (ct.wc > 0.0 && ct.wb > 0.0) root_.join(ct.c, ct.b);
  // Per body, its pushing contacts (1: one, 2: a bounce among them, 3: a chain).
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const ContactConstraint& ct = contacts[i];
    if (!(impulses[i].lambda + impulses[i].lambda2 > 0.0)) continue;  // no impulse: it changed nothing
    const std::uint8_t kind = !ct.resting && ct.restitution > 0.0 ? 2 : 1;
    for (const EntityId e : {ct.c, ct.b})
      if (std::isfinite(k.mass[e])) undone_[e] = undone_[e] != 0 && (undone_[e] | kind) > 1 ? 3 : std::max(undone_[e], kind);
    if (ct.restitution < 1.0) islands_[find(std::isfinite(k.mass[ct.c]) ? ct.c : ct.b)].elastic = false;
  }
  for (const EntityId e : bodies) {
    if (!std::isfinite(k.mass[e])) continue;
    Island& i = islands_[find(e)];
    i.chain = i.chain || undone_[e] == 3;
    i.before += 0.5 * k.mass[e] * Vector::dot(kept_velocity_[e], kept_velocity_[e]);
    i.after += 0.5 * k.mass[e] * Vector::dot(k.velocity[e], k.velocity[e]);
  }
  std::size_t count = 0;
  for (const EntityId e : bodies) {
    const Island& i = islands_[find(e)];
    undone_[e] = std::isfinite(k.mass[e]) && (i.chain || (i.elastic && std::abs(i.after - i.before) > 1e-12 * i.before));
    if (!undone_[e]) continue;
    k.position[e] = kept_position_[e], k.velocity[e] = kept_velocity_[e];
    fast_count_ += !fast_[e];
    fast_[e] = 1, start_[e] = 0.0;
    ++count;
  }
  any_undone_ = count > 0;
  stats.undone += static_cast<std::int64_t>(count);
}

void AutoMode::after_solver(const Components& k, std::span<const EntityId> bodies,
                            std::span<const ContactConstraint> contacts, std::span<const ContactImpulse> impulses,
                            double h) {
  stats.contacts += static_cast<std::int64_t>(contacts.size());
  pressed_.clear();
  // On trial, impacts do not count: a fast gas's pairs meet again and again,
  // and holding the solver for them would give it their chains.
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const ContactConstraint& ct = contacts[i];
    if (ct.wc > 0.0 && ct.wb > 0.0 && impulses[i].lambda + impulses[i].lambda2 > 0.0 && !(trial_ && !ct.resting))
      pressed_.push_back(Pair{ct.c, ct.b}.key());
  }
  count_pressed();
  if (first_ && !pressed_.empty()) hold_left_ = hold;  // a pile from the start
  if (jam_left_ > 0) {  // a jam: the solver takes it whole (after_sweep)
    std::fill(fast_.begin(), fast_.end(), 0);
    fast_count_ = 0;
    return;
  }
  // The solver's contacts were found along each body's whole swept path
  // (speculative), so its first impact is taken already: only a body that
  // had one and is still fast may meet something else within the substep.
  // It is swept from its impact time on (the solver's impact_time shifted it
  // so that its line from then on is its motion; the earliest of its
  // impacts, as there). Pairs closing fast are not looked for again: the
  // solver's speculative contacts took their first impact too.
  mark_fast(k, bodies, h, false);
  if (fast_count_ == 0 && !trial_) return;  // on trial, roll_back may sweep bodies beside the impacted ones
  impacted_.assign(k.size(), 0);
  for (const ContactConstraint& ct : contacts) {
    if (ct.resting) continue;
    impacted_[ct.c] = impacted_[ct.b] = 1;
    if (!(ct.toi > 0.0)) continue;
    for (const EntityId e : {ct.c, ct.b})
      if (std::isfinite(k.mass[e])) start_[e] = start_[e] == 0.0 ? ct.toi : std::min(start_[e], ct.toi);
  }
  start_set_ = true;
  // And only if what is left of the substep after its impact still carries
  // it past its reach.
  const auto still_fast = [&](EntityId e) {
    const double left = h - start_[e], reach = selection().reach(k, e);
    return left * left * Vector::dot(k.velocity[e], k.velocity[e]) > reach * reach;
  };
  fast_count_ = 0;
  for (const EntityId e : bodies) {
    fast_[e] = fast_[e] && impacted_[e] && still_fast(e);
    fast_count_ += fast_[e];
  }
}

// CCD ran out of budget this substep: a jam (a light body squeezed between
// heavy ones takes ~π·sqrt(M/m) impacts, millions past 1e12) that CCD can
// only stop, losing the stopped bodies' time. The solver takes a jam's
// impacts together, so for `hold` substeps it takes the scene, sweeping
// nothing.
void AutoMode::after_sweep(bool capped) {
  if (capped) jam_left_ = hold;
}

void AutoMode::after_course_pass(const Components& k, std::span<const Contact> contacts) {
  pressed_.clear();
  for (const Contact& c : contacts)
    if (std::isfinite(k.mass[c.c]) && std::isfinite(k.mass[c.b]))
      pressed_.push_back(Pair{c.c, c.b}.key());
  count_pressed();
  if (!gravity_) count_squeezed(k, contacts);
  overlap_bound_ = overlap_after(k, contacts);
}

// The deepest overlap the pass can have left, px: a pair it resolved
// overlaps as it is now; any other pair did not overlap when the pass looked
// at it (or the broad phase would have listed it), and has since come closer
// by at most the pushes its two bodies took, each at most the sum of its
// contacts' penetrations.
double AutoMode::overlap_after(const Components& k, std::span<const Contact> contacts) {
  push_.resize(k.size(), 0.0);
  double deepest = 0.0;
  for (const Contact& c : contacts) {
    const double depth = Vector::norm(c.penetration);
    push_[c.c] += depth, push_[c.b] += depth;
    deepest = std::max(deepest, CcdSelection::overlap_at(k, c.c, c.b, 0.0));
  }
  double p1 = 0.0, p2 = 0.0;  // the two largest pushes of two bodies
  for (const Contact& c : contacts)
    for (const EntityId e : {c.c, c.b}) {
      const double p = push_[e];
      push_[e] = 0.0;  // each body once, and clean for the next pass
      if (p > p2) (p > p1 ? p2 = p1, p1 = p : p2 = p);
    }
  return std::max(deepest, p1 + p2);
}

// Each pair of finite bodies pressed together this substep, with the number
// of substeps in a row it has been (pressed_ in, runs_ kept): `persist` in a
// row holds the solver.
void AutoMode::count_pressed() {
  // Mostly in order already (pairs come in registration order).
  if (!std::is_sorted(pressed_.begin(), pressed_.end())) std::sort(pressed_.begin(), pressed_.end());
  next_runs_.clear();
  auto old = runs_.begin();
  for (const std::uint64_t key : pressed_) {
    while (old != runs_.end() && old->first < key) ++old;
    const int run = old != runs_.end() && old->first == key ? old->second + 1 : 1;
    next_runs_.emplace_back(key, run);
    if (run >= (gravity_ ? 1 : persist)) hold_left_ = hold;
  }
  std::swap(runs_, next_runs_);
}

// A finite body pushed, within `persist` substeps, towards a fixed body by a
// finite one and back by the fixed body: a block a pusher drives into a wall.
// Once both overlap it in one pass, the pass takes the two pairs one after
// the other, each sharing its correction by the bodies' speeds, so the fast
// light block takes most of the pusher's and is left in the wall (the
// family's floating push-into-wall draws: 1.3-3.3 px deep before the pair
// had been pressed `persist` substeps in a row, which a gas's impacts rarely
// are). So this holds the solver as soon as the pusher will close, within
// the next substep, the room the block has between it and the fixed body
// (squeezes), before the pass meets both at once. Only pushes from two
// sides count: a pair pressed along one axis is count_pressed's.
void AutoMode::count_squeezed(const Components& k, std::span<const Contact> contacts) {
  pushes_.resize(k.size());
  const auto side_of = [](Vector n) { return n.x != 0.0 ? (n.x > 0.0 ? 0 : 1) : (n.y > 0.0 ? 2 : 3); };
  for (const Contact& c : contacts) {
    if (Vector::is_zero(c.normal)) continue;
    for (const auto& [e, by, n] : {std::tuple{c.c, c.b, c.normal}, std::tuple{c.b, c.c, -c.normal}}) {
      if (!std::isfinite(k.mass[e])) continue;
      const int side = side_of(n);
      pushes_[e][side] = {substep_, by};
      const Push& back = pushes_[e][side ^ 1];  // the last push the other way
      const bool fixed = !std::isfinite(k.mass[by]);
      if (substep_ - back.at >= persist || fixed == !std::isfinite(k.mass[back.by])) continue;
      if (fixed ? squeezes(k, e, back.by, by, side ^ 1) : squeezes(k, e, by, back.by, side)) hold_left_ = hold;
    }
  }
}

// Whether `pusher`, which pushed e towards `side`, closes within the next
// substep the room e has between it and `wall` (the gap between their faces
// less e's extent along the axis; below 0 e is in one of them already).
bool AutoMode::squeezes(const Components& k, EntityId e, EntityId pusher, EntityId wall, int side) const {
  const bool x = side < 2;
  const double sign = side % 2 == 0 ? 1.0 : -1.0;
  const auto lo = [&](EntityId b) { return x ? k.position[b].x : k.position[b].y; };
  const auto size = [&](EntityId b) { return static_cast<double>(x ? k.box[b].width : k.box[b].height); };
  const auto speed = [&](EntityId b) { return x ? k.velocity[b].x : k.velocity[b].y; };
  const double gap = sign > 0.0 ? lo(wall) - (lo(pusher) + size(pusher)) : lo(pusher) - (lo(wall) + size(wall));
  const double closing = sign * (speed(pusher) - speed(wall));
  return h_ * closing >= gap - size(e);
}

AutoState AutoMode::state() const {
  AutoState s;
  s.hold = hold_left_;
  s.jam = jam_left_;
  for (const auto& [key, run] : runs_)
    s.pressed.push_back({{static_cast<EntityId>(key >> 32), static_cast<EntityId>(key & 0xFFFFFFFFu)}, run});
  for (EntityId e = 0; e < pushes_.size(); ++e)
    for (int side = 0; side < 4; ++side)
      if (const Push& p = pushes_[e][side]; substep_ - p.at < persist)
        s.pushed.push_back({e, p.by, side, static_cast<int>(substep_ - p.at)});
  return s;
}

void AutoMode::restore(const AutoState& s) {
  hold_left_ = s.hold;
  jam_left_ = s.jam;
  runs_.clear();
  for (const AutoState::Run& r : s.pressed) runs_.emplace_back(r.pair.key(), r.substeps);
  std::sort(runs_.begin(), runs_.end());
  // Counted from 0 again: a push `ago` substeps before the last one was at -ago.
  substep_ = 0;
  pushes_.assign(pushes_.size(), {});
  for (const AutoState::Push& p : s.pushed) {
    if (p.body >= pushes_.size()) pushes_.resize(p.body + 1);
    pushes_[p.body][p.side] = {-p.ago, p.by};
  }
  started_ = true;
  overlap_bound_ = infinity;
}

}  // namespace physics
