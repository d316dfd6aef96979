#include "engine/ccd.hpp"

#include <algorithm>
#include <cmath>
#include <queue>

#include "engine/contact.hpp"
#include "engine/geometry.hpp"
#include "engine/rules.hpp"
#include "engine/sweep.hpp"

namespace physics {

namespace {

// A relative speed this small next to the bodies' own is rounding left over
// from an impulse that zeroed it (e = 0): it must not count as approaching,
// or the pair would be "hit" again and again at the same instant.
double speed_floor(Vector vc, Vector vb) {
  return 1e-12 * (std::abs(vc.x) + std::abs(vc.y) + std::abs(vb.x) + std::abs(vb.y));
}

struct Event {
  double t;
  std::uint32_t ic, ib;  // registration indices, ic < ib
  std::uint32_t vc, vb;  // versions of the bodies when it was predicted
};
struct Later {
  bool operator()(const Event& a, const Event& b) const {
    if (a.t != b.t) return a.t > b.t;
    if (a.ic != b.ic) return a.ic > b.ic;
    return a.ib > b.ib;
  }
};

// The course's impulse at an impact at time t of the substep (the engine's
// one contact law), restitution the smaller of the pair's, with the gravity
// after t as contact.hpp's gravity_after_impact says (else an e = 1 bounce
// on the floor gains or loses energy every time). Never enough to turn the
// pair back towards each other.
// Returns the normal and tangential impulses.
std::pair<double, double> impact(Components& k, EntityId c, EntityId b, Vector n, double t, double h, Vector gravity,
                                 bool exact_motion) {
  const Vector vc = k.velocity[c], vb = k.velocity[b];
  const double vn = Vector::dot(vc - vb, n);
  const double e = std::min(k.restitution[c], k.restitution[b]);
  const Vector ac = std::isfinite(k.mass[c]) ? gravity : Vector{};
  const Vector ab = std::isfinite(k.mass[b]) ? gravity : Vector{};
  const double kick = std::max(gravity_after_impact(e, Vector::dot(ac - ab, n), h, t, exact_motion), e * vn);
  const double dv = -(1.0 + e) * vn + kick;
  Vector vc2 = vc, vb2 = vb;
  const double wc = inverse_mass(k.mass[c]), wb = inverse_mass(k.mass[b]);
  change_normal_velocity(vc2, vb2, n, dv, wc, wb);
  // Coulomb friction with this impact's normal impulse (engine/contact.hpp).
  const double jn = dv / (wc + wb);
  const double mu = pair_friction(k, c, b);
  const double jt = mu > 0.0 ? apply_friction(vc2, vb2, n, mu * jn, wc, wb) : 0.0;
  // Keep position + t·velocity continuous at t (see the header).
  k.position[c] = k.position[c] + t * (vc - vc2);
  k.position[b] = k.position[b] + t * (vb - vb2);
  k.velocity[c] = vc2;
  k.velocity[b] = vb2;
  return {jn, jt};
}

}  // namespace

double CcdSelection::overlap_at(const Components& k, EntityId a, EntityId b, double t) {
  const Vector pa = k.position[a] + t * k.velocity[a], pb = k.position[b] + t * k.velocity[b];
  const double ox = std::min(pa.x + k.box[a].width, pb.x + k.box[b].width) - std::max(pa.x, pb.x);
  const double oy = std::min(pa.y + k.box[a].height, pb.y + k.box[b].height) - std::max(pa.y, pb.y);
  return std::max(0.0, std::min(ox, oy));
}

bool CcdSelection::closes_through(const Components& k, EntityId a, EntityId b, double t, double span,
                                  bool overlapped) {
  const auto side = [&](EntityId e) { return static_cast<double>(std::min(k.box[e].width, k.box[e].height)); };
  const Vector d = span * (k.velocity[a] - k.velocity[b]);
  const double limit = std::max(0.0, 0.5 * (side(a) + side(b)) - (overlapped ? overlap_at(k, a, b, t) : 0.0));
  return Vector::dot(d, d) > limit * limit;
}

std::optional<Impact> Ccd::time_of_impact(const Components& k, EntityId c, EntityId b, double t0, double t1) {
  const Vector vc = k.velocity[c], vb = k.velocity[b];
  const auto [s, size] = minkowski_difference(k.position[c], k.box[c], k.position[b], k.box[b]);
  const Vector d = vb - vc;  // the Minkowski box moves at v_b - v_c
  const auto [enter, exit, along_x] = sweep(s, size, d);  // engine/sweep.hpp, shared with the ray cast
  if (!(enter < exit) || exit <= t0 || enter > t1) return std::nullopt;
  const double floor = speed_floor(vc, vb);
  if (enter < t0) {
    // Already overlapping at t0 (spawned so, or left so by a capped
    // substep): an impact now if the pair approaches along its shortest way
    // out. But a pair that only touches at t0 (an impact a moment ago left
    // it so) may compute as entered a rounding before t0, with a way out of
    // about 0 px of either sign or none; read as one, it let a block that
    // bounced off the floor pass into the one above it (a chain of e = 1
    // impacts cut short, the pass after Move pushed them apart, and the
    // energy grew). Such a pair enters at t0 by the sweep's face, when it is
    // entering (not leaving after its impact) and touches across that face:
    // a block sliding along a wall that rounding put 1e-13 px inside it
    // would otherwise meet the wall's end, where a corner's two walls throw
    // it back and forth for ever at one instant.
    const Vector s0{s.x + t0 * d.x, s.y + t0 * d.y};
    const Vector out = penetration_vector(s0, size);
    const double touch = 1e-12 * (std::abs(s0.x) + std::abs(s0.y) + size.width + size.height);
    const bool entering = t0 - enter < exit - t0 && (along_x ? out.y == 0.0 : out.x == 0.0);
    if (std::abs(out.x) + std::abs(out.y) > touch || !entering) {
      const Vector n = Vector::normalize(out);
      if (Vector::dot(vc - vb, n) >= -floor) return std::nullopt;
      return Impact{t0, n};
    }
  }
  // x wins a tie (along_x), as the course's penetration vector does.
  const double dn = along_x ? d.x : d.y;
  if (std::abs(dn) <= floor) return std::nullopt;
  const Vector n = along_x ? Vector{dn > 0.0 ? 1.0 : -1.0, 0.0} : Vector{0.0, dn > 0.0 ? 1.0 : -1.0};
  return Impact{std::max(enter, t0), n};
}

namespace {

// One substep's predicted impacts, in time order, with what predicting them
// needs: each entity's registration index, and a version per body (an event
// predicted before one of its bodies changed velocity is stale).
class ImpactQueue {
 public:
  ImpactQueue(Components& k, std::span<const EntityId> entities, double h, const CcdSelection* sel)
      : k_(k), entities_(entities), h_(h), sel_(sel), index_(k.size(), 0), version_(entities.size(), 0) {
    for (std::size_t i = 0; i < entities.size(); ++i) index_[entities[i]] = static_cast<std::uint32_t>(i);
  }

  void predict(Pair p) { predict(index_[p.c], index_[p.b], 0.0); }

  // The earliest valid event, or none when the queue is empty.
  std::optional<Event> next() {
    while (!queue_.empty()) {
      const Event ev = queue_.top();
      queue_.pop();
      if (ev.vc == version_[ev.ic] && ev.vb == version_[ev.ib]) return ev;
    }
    return std::nullopt;
  }

  // After an impact, the impacts of its swept bodies c and b with
  // everything again (not only the candidates, whose sweeps assumed the old
  // velocities). With contact rules, only with the bodies the broad phase
  // would pair them with (its pairs are filtered already): a compile-time
  // switch, so the loop without rules tests nothing more.
  template <bool with_rules>
  void predict_again(const Event& ev) {
    ++version_[ev.ic];  // both bodies changed course
    ++version_[ev.ib];
    const EntityId c = entities_[ev.ic], b = entities_[ev.ib];
    const bool c_fixed = !std::isfinite(k_.mass[c]), b_fixed = !std::isfinite(k_.mass[b]);
    const bool again_c = swept(c, ev.t), again_b = swept(b, ev.t);
    // A body left unswept still meets the swept ones on its new line (their
    // impacts with it were predicted on the old one), and the unswept ones
    // it now closes on faster than the pass after Move can separate.
    // (A fixed body keeps its line: its impacts with unswept bodies are the pass's, as before.)
    const auto sweeps = [&](bool again, bool fixed, EntityId e, std::uint32_t j) {
      return again || (sel_ && (sel_->fast[entities_[j]] ||
                                (!fixed && CcdSelection::closes_through(k_, e, entities_[j], ev.t, h_ - ev.t, true))));
    };
    // The boxes swept over the rest of the substep: a pair whose two do not
    // meet has no impact in it (a cheaper test than time_of_impact's).
    const SweptBox box_c = swept_box(c, ev.t), box_b = swept_box(b, ev.t);
    for (std::uint32_t j = 0; j < entities_.size(); ++j) {
      const SweptBox box_j = swept_box(entities_[j], ev.t);
      const bool j_fixed = !std::isfinite(k_.mass[entities_[j]]);
      if (meet(box_c, box_j) && j != ev.ic && !(c_fixed && j_fixed) && sweeps(again_c, c_fixed, c, j) &&
          (!with_rules || solvable(k_, c, entities_[j], h_)))
        predict(ev.ic, j, ev.t);
      if (meet(box_b, box_j) && j != ev.ib && !(b_fixed && j_fixed) &&
          !(j == ev.ic && meet(box_c, box_b) && sweeps(again_c, c_fixed, c, ev.ib)) &&
          sweeps(again_b, b_fixed, b, j) && (!with_rules || solvable(k_, b, entities_[j], h_)))
        predict(ev.ib, j, ev.t);
    }
  }

 private:
  // e's box over [t, h] on its line, grown by a hair (swept_box).
  SweptBox swept_box(EntityId e, double t) const { return physics::swept_box(k_, e, t, h_, true); }
  static bool meet(const SweptBox& a, const SweptBox& b) {
    return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1;
  }
  void predict(std::uint32_t ic, std::uint32_t ib, double t0) {
    if (ic > ib) std::swap(ic, ib);
    // A selected body's line holds from its start time on (before it, the
    // line is the one the solver's impact shifted, not the path).
    if (sel_) t0 = std::max({t0, sel_->start[entities_[ic]], sel_->start[entities_[ib]]});
    if (const auto hit = Ccd::time_of_impact(k_, entities_[ic], entities_[ib], t0, h_))
      queue_.push(Event{hit->t, ic, ib, version_[ic], version_[ib]});
  }
  // Whether a body of an impact at t is swept for the rest of the substep.
  bool swept(EntityId e, double t) {
    if (!sel_ || sel_->fast[e]) return true;
    if (Vector::norm(k_.velocity[e]) * (h_ - t) <= sel_->reach(k_, e)) return false;
    sel_->fast[e] = 1;
    return true;
  }

  Components& k_;
  std::span<const EntityId> entities_;
  double h_;
  const CcdSelection* sel_;
  std::vector<std::uint32_t> index_;
  std::vector<std::uint32_t> version_;
  std::priority_queue<Event, std::vector<Event>, Later> queue_;
};

// Swept sensors: a sensor takes no impulse, so CCD has no impact with it,
// and a fast body may cross it within a substep and be out again by the end
// (a bullet through a 5 px sensor 700 times gave 2 events). Each body's path
// is a line between its impacts: each piece is swept against the sensors
// when it ends (at an impact, or at the end of the substep), and a piece
// that enters one is a touch for contact events (events.hpp).
class SensorSweep {
 public:
  SensorSweep(const Components& k, std::span<const EntityId> entities, double h, ContactEvents& events,
              const CcdSelection* sel)
      : k_(k), entities_(entities), h_(h), events_(events) {
    if (!events.enabled || !k.any_rules()) return;
    for (const EntityId e : entities)
      if (k.rules(e).sensor) sensors_.push_back(e);
    if (sensors_.empty()) return;
    from_.assign(k.size(), 0.0);
    if (sel)
      for (const EntityId e : entities) from_[e] = sel->start[e];  // before it, the solver's shifted line
  }
  // e's piece of path ends at t (its velocity is about to change).
  void piece(EntityId e, double t) {
    if (sensors_.empty() || k_.rules(e).sensor) return;
    for (const EntityId s : sensors_)
      if (reported(k_, e, s, h_)) sweep_piece(e, s, from_[e], t);
    from_[e] = t;
  }
  void stop(EntityId e, double t) {
    piece(e, t);
    if (!sensors_.empty()) from_[e] = h_;  // at rest for the rest of the substep
  }
  void finish() {
    for (const EntityId e : entities_) piece(e, h_);
  }

 private:
  void sweep_piece(EntityId e, EntityId s, double a, double b) {
    if (!(a < b)) return;
    const auto [s0, size] = minkowski_difference(k_.position[e], k_.box[e], k_.position[s], k_.box[s]);
    const Vector d = k_.velocity[s] - k_.velocity[e];
    const auto [enter, exit, along_x] = sweep(s0, size, d);
    if (!(std::max(enter, a) < std::min(exit, b))) return;
    const double dn = along_x ? d.x : d.y;
    const Vector n = along_x ? Vector{dn >= 0.0 ? 1.0 : -1.0, 0.0} : Vector{0.0, dn >= 0.0 ? 1.0 : -1.0};
    if (e < s)
      events_.touch(e, s, n, 0.0, 0.0);
    else
      events_.touch(s, e, -n, 0.0, 0.0);
  }

  const Components& k_;
  std::span<const EntityId> entities_;
  double h_;
  ContactEvents& events_;
  std::vector<EntityId> sensors_;
  std::vector<double> from_;  // by entity id: where its current piece began, ms
};

// Out of budget (an inelastic collapse, a squeeze: impacts without end at
// one place): from the first impact past the budget on, an impact stops its
// bodies where they meet, for the rest of the substep, instead of bouncing
// them, and the rest of the scene moves on, so a jam does not stop the
// world's time. A stopped body's impacts are predicted again on its new line
// (at rest), so a body that runs into it stops there too: nothing passes
// through anything (stopping each body at its own next impact as predicted
// before let a body chasing one that stopped earlier run into it). Each
// impact stops a body, so this ends. A stopped body keeps its velocity minus
// the part of the substep's gravity kick after it stopped (Forces gave the
// whole of it), else a pile stopped every substep would gather speed without
// moving, and its energy would grow (6 300 times with the stable solver,
// e = 1). A fixed body (a moving platform) keeps its course.
template <bool with_rules>
void stop_at_impacts(Components& k, ImpactQueue& queue, Event first, std::span<const EntityId> entities, double h,
                     Vector gravity, SensorSweep& sense) {
  std::vector<std::uint8_t> stopped(k.size(), 0);
  std::vector<std::pair<EntityId, Vector>> kept;  // each stopped body and the velocity it keeps
  const auto stop = [&](EntityId e, double t) {
    if (stopped[e] || !std::isfinite(k.mass[e])) return false;
    stopped[e] = 1;
    sense.stop(e, t);
    kept.emplace_back(e, k.velocity[e] - (h - t) * gravity);
    k.position[e] = k.position[e] + t * k.velocity[e];  // at rest there from t on
    k.velocity[e] = {};
    return true;
  };
  for (std::optional<Event> ev = first; ev; ev = queue.next()) {
    const EntityId c = entities[ev->ic], b = entities[ev->ib];
    const auto hit = Ccd::time_of_impact(k, c, b, ev->t, h);
    if (!hit || hit->t != ev->t) continue;
    const bool c_stops = stop(c, ev->t), b_stops = stop(b, ev->t);
    if (c_stops || b_stops) queue.predict_again<with_rules>(*ev);
  }
  for (const auto& [e, v] : kept) {
    k.position[e] = k.position[e] - h * v;  // Move's x + h·v is where it stopped
    k.velocity[e] = v;
  }
}

// How many impacts a substep may still resolve. The budget is per stretch
// of time, not per substep: a jam (an inelastic collapse, a squeeze) piles
// its impacts up at one instant, while a body that really meets many things
// in a substep (a bullet bouncing between the walls hundreds of times)
// spreads them over it. A stretch begins at the first impact past the last
// one's end and lasts h/64, so a substep holds at most 65 of them, and a jam
// is still cut after one budget: 16·n + 128 impacts.
// Without gravity, lossless impacts (e = 1, no friction, between bodies
// that are finite or at rest) have a budget of their own, larger: they
// cannot collapse (each keeps the energy, and nothing drives a gap shut
// without end: an infinite mass that moves is no such body), but a light
// body squeezed between two heavy ones, or between a heavy one and a wall,
// takes ~π·sqrt(M/m) of them, 170 000 at 3e9, most of them within one
// stretch; cut there, the squeeze lost its time or (auto) went to the
// solver, which loses energy. Each impact re-predicts against every body,
// so this budget is one of work: Ccd::elastic_work / n impacts. Under
// gravity a resting pile would spend it every substep (a heavy block resting
// on a light one on the floor takes ~π·sqrt(M/m) impacts per substep with
// e = 1: the matrix's 1e9 case took 21 s), so there every impact counts
// against the first budget.
class ImpactBudget {
 public:
  ImpactBudget(std::size_t bodies, double h, bool weightless)
      : n_(static_cast<std::int64_t>(bodies)), stretch_(h / 64.0), weightless_(weightless) {}

  // Whether an impact at time t is past the budget of its stretch.
  bool spent(double t) {
    if (t >= stretch_end_) {
      stretch_end_ = t + stretch_;
      resolved_ = lossless_ = 0;
    }
    return resolved_ == budget() || lossless_ == lossless_budget();
  }
  // Counts the impact of c and b about to be resolved.
  void spend(const Components& k, EntityId c, EntityId b) { ++(lossless(k, c, b) ? lossless_ : resolved_); }

 private:
  std::int64_t budget() const { return 16 * n_ + 128; }
  std::int64_t lossless_budget() const { return std::max(budget(), Ccd::elastic_work / n_); }
  bool lossless(const Components& k, EntityId c, EntityId b) const {
    const auto held_or_free = [&](EntityId e) { return std::isfinite(k.mass[e]) || Vector::is_zero(k.velocity[e]); };
    return weightless_ && held_or_free(c) && held_or_free(b) &&
           std::min(k.restitution[c], k.restitution[b]) == 1.0 && pair_friction(k, c, b) == 0.0;
  }

  std::int64_t n_;
  double stretch_;
  bool weightless_;
  double stretch_end_ = -1.0;
  std::int64_t resolved_ = 0, lossless_ = 0;
};

}  // namespace

void Ccd::resolve(Components& k, std::span<const EntityId> entities, double h, Vector gravity, bool exact_motion,
                  BroadPhase& broadphase, ContactEvents& events, const CcdSelection* sel) {
  if (entities.size() < 2) return;
  if (sel)
    broadphase.find_selected(k, entities, sel->fast, h, pairs_);
  else
    broadphase.find(k, entities, h, 0.0, pairs_);
  SensorSweep sense(k, entities, h, events, sel);
  if (pairs_.empty()) return sense.finish();
  ImpactQueue queue(k, entities, h, sel);
  for (const Pair& p : pairs_) queue.predict(p);
  const bool rules = k.any_rules();
  ImpactBudget budget(entities.size(), h, Vector::is_zero(gravity));
  while (const auto ev = queue.next()) {
    if (budget.spent(ev->t)) {
      ++stats.capped_substeps;
      if (rules)
        stop_at_impacts<true>(k, queue, *ev, entities, h, gravity, sense);
      else
        stop_at_impacts<false>(k, queue, *ev, entities, h, gravity, sense);
      break;
    }
    const EntityId c = entities[ev->ic], b = entities[ev->ib];
    // Predicted with these very velocities, so it still holds; recompute the
    // normal at the event's time (the function is deterministic).
    const auto hit = time_of_impact(k, c, b, ev->t, h);
    if (!hit || hit->t != ev->t) continue;
    sense.piece(c, ev->t), sense.piece(b, ev->t);
    budget.spend(k, c, b);
    const auto [jn, jt] = impact(k, c, b, hit->n, ev->t, h, gravity, exact_motion);
    events.touch(c, b, hit->n, jn, jt);
    ++stats.impacts;
    if (rules)
      queue.predict_again<true>(*ev);
    else
      queue.predict_again<false>(*ev);
  }
  sense.finish();
}

}  // namespace physics
