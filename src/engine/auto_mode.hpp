// The auto mode (Params::solver = Solver::automatic, `--solver auto`): per
// substep, only the numerics the scene needs at that moment.
//
// No single mode passes the stability matrix (report/STABILITY.md): the
// course's one pass sinks stacks and tunnels fast bodies, the stable solver
// tunnels bodies that meet a second obstacle within a substep, CCD alone has
// no resting contact and, with the stable solver, stops time when a body is
// squeezed (its impacts never end). Each of them is right somewhere, and the
// cheapest is the course's pass. So, each substep:
//  - the course's pass, unless contacts persist: the same pair of finite
//    bodies resolved by two passes in a row (a stack, a squeeze, a pile), or
//    bouncing contacts under gravity (the pass reflects the whole substep's
//    gravity kick and the energy creeps up), or two finite bodies may meet
//    under gravity (a landing: the pass pushes the lighter one into what
//    carries it, and the energy grows), or, without gravity, a body about to
//    be squeezed against a fixed one (a pusher that will close the room left
//    to a block it drives into a wall: count_squeezed). Then the stable solver, held as
//    long as finite bodies carry each other's load and `hold` substeps more
//    (so that a resting pile does not flip between the two every substep);
//  - swept collision (CCD) only for the bodies whose motion this substep
//    exceeds their `reach`: half of their own thinnest side plus the
//    thinnest side of anything in the world (past that, an overlap is pushed
//    out on the wrong side: the body tunnels), and for the pairs that close
//    faster than half their two sides (two bodies head on, each within its
//    reach, close at twice it). On the solver's path CCD
//    starts after the solver, from each body's impact time: the solver stops
//    a fast body's first impact (and a heavy one landing on a stack, which
//    CCD's one-impact-at-a-time cannot: the impacts down the stack never
//    end), CCD the ones after it within the substep;
//  - under gravity with every restitution 1 (and masses within
//    elastic_mass_ratio), the solver's path is stable+ccd's: the solver
//    keeps the resting contacts and CCD sweeps every body (sweep_all).
// The CCD flag of Params is not read: auto decides which bodies to sweep.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "engine/components.hpp"
#include "engine/ccd.hpp"
#include "engine/contact.hpp"
#include "engine/contact_solver.hpp"
#include "engine/union_find.hpp"

namespace physics {

// What the next substep's choice depends on beyond the bodies: the pairs
// pressed together in the substeps just before, the pushes of the last ones
// and the solver's hold (a saved world keeps it, so that it runs on bit for
// bit).
struct AutoState {
  struct Run {
    Pair pair;
    int substeps;  // in a row, up to now
    friend bool operator==(const Run&, const Run&) = default;
  };
  // The pass's last push of `body` towards `side` (0: +x, 1: -x, 2: +y,
  // 3: -y), by `by`, `ago` substeps before the last one (AutoMode::persist
  // at most): what tells a block squeezed against a wall (count_squeezed).
  struct Push {
    EntityId body, by;
    int side, ago;
    friend bool operator==(const Push&, const Push&) = default;
  };
  int hold = 0;  // substeps the solver is still held for
  int jam = 0;   // substeps the solver still takes a jam whole for
  std::vector<Run> pressed;
  std::vector<Push> pushed;
  friend bool operator==(const AutoState&, const AutoState&) = default;
};

struct AutoStats {
  std::int64_t course_substeps = 0;  // substeps resolved by the course's pass
  std::int64_t solver_substeps = 0;  // substeps resolved by the stable solver
  std::int64_t swept = 0;            // bodies swept by CCD, summed over substeps
  std::int64_t contacts = 0;         // contacts the stable solver iterated, summed over substeps
  std::int64_t undone = 0;           // bodies whose solver substep was undone and swept instead (roll_back), summed
};

class AutoMode {
 public:
  // Substeps the solver is kept after its last load-carrying contact.
  static constexpr int hold = 8;
  // Substeps in a row a pair of finite bodies must be pressed together
  // (an impulse between them) to count as a persistent contact. Under
  // gravity one is enough: each course pass after a landing pushes the pair
  // out against gravity again, and the energy grows with every one. Also
  // the substeps within which a body's pushes from two sides make a squeeze
  // (count_squeezed).
  static constexpr int persist = 3;
  // More fast bodies than this take the solver's path: its speculative
  // contacts take each one's first impact at the cost of one broad phase,
  // and CCD then sweeps only those that had one. Without gravity, on trial:
  // the islands where it had a chain of impacts are undone (roll_back).
  static constexpr std::size_t many_fast = 16;
  // Worlds of more bodies than this keep the solver's trial as it is: CCD
  // re-predicts each impact against every body, and sweeping the undone
  // islands of a 10 000-body gas took its step from 5 to 23 ms.
  static constexpr std::size_t undo_bodies = 2048;
  // The ratio of two finite masses below which an elastic scene under
  // gravity is swept whole (sweep_all, elastic).
  static constexpr double elastic_mass_ratio = 1e3;

  // Before the substep's velocities: which path it takes (true: the stable
  // solver) and which bodies are fast, from the velocities after Forces.
  bool plan(const Components& k, std::span<const EntityId> bodies, double h, Vector gravity);
  // After the solver's velocities: whether finite bodies carry each other
  // (keeps the solver), and which bodies are still fast, from when.
  // (impulses: the contacts' accumulated impulses, beside them.)
  void after_solver(const Components& k, std::span<const EntityId> bodies, std::span<const ContactConstraint> contacts,
                    std::span<const ContactImpulse> impulses, double h);
  // After the course's pass: whether a pair of finite bodies it resolved was
  // resolved by the pass before too (switches to the solver).
  void after_course_pass(const Components& k, std::span<const Contact> contacts);
  // After CCD: whether it ran out of budget (a jam).
  void after_sweep(bool capped);

  // Around the solver on trial (more than many_fast fast bodies, no
  // gravity): keep() the bodies before it; after after_solver(), roll_back()
  // puts the islands where a body had a bounce and another contact back as
  // they were and sweeps them instead. undone(e): e's solver contacts were
  // undone this substep (its events are CCD's).
  void keep(const Components& k);
  void roll_back(Components& k, std::span<const EntityId> bodies, std::span<const ContactConstraint> contacts,
                 std::span<const ContactImpulse> impulses);
  bool undone(EntityId e) const { return e < undone_.size() && undone_[e] == 1; }

  // The state a saved world keeps; restore() also marks the world as
  // started (no first-substep look with the solver).
  AutoState state() const;
  void restore(const AutoState& s);

  bool solver_path() const { return solver_path_; }
  // Under gravity with every restitution 1 (and masses within
  // elastic_mass_ratio), the solver's path is stable+ccd's:
  // the solver holds the resting contacts and CCD sweeps every body and
  // takes every impact. The solver takes a substep's impacts together, which
  // in an e = 1 pile loses or gains energy in chains and lets a light body
  // that a heavy one throws out through the walls (the family's pile and
  // fast-in-pile draws: sinks of 2-10 px, bodies out, energy up 1e-7); CCD's
  // one impact at a time keeps e = 1 exactly, and without an inelastic pair
  // it has no collapse to run out of budget on.
  bool sweep_all() const { return sweep_all_; }
  // The bodies to sweep this substep, and how many (valid until the next plan()).
  CcdSelection selection() { return {fast_, start_, thinnest_}; }
  std::size_t fast_count() const { return fast_count_; }

  AutoStats stats;

 private:
  void mark_fast(const Components& k, std::span<const EntityId> bodies, double h, bool closing);
  void mark_closing(const Components& k, std::span<const EntityId> bodies, double h, double overlap_bound);
  double overlap_after(const Components& k, std::span<const Contact> contacts);
  double sq1_ = 0, sq2_ = 0;  // mark_fast's: the two largest squared displacements of the bodies not fast
  // The deepest overlap of any pair now, px (after_course_pass), or infinity when unknown.
  double overlap_bound_ = std::numeric_limits<double>::infinity();
  std::vector<double> push_;  // overlap_after's scratch, by entity id
  static bool bouncy(const Components& k, std::span<const EntityId> bodies);
  static bool elastic(const Components& k, std::span<const EntityId> bodies);
  bool seamed(const Components& k, std::span<const EntityId> bodies, Vector gravity);
  std::vector<std::array<double, 3>> faces_;  // seamed's scratch: each fixed body's face (level, from, to)

  std::vector<std::uint8_t> fast_;  // by entity id
  std::vector<double> start_;       // by entity id, ms
  struct Candidate {  // a body and its box swept over the substep
    SweptBox box;
    EntityId e;
  };
  std::vector<Candidate> closing_;  // mark_closing's and landing's candidates (kept: no allocation per substep)
  static Candidate candidate(const Components& k, EntityId e, double h) { return {swept_box(k, e, 0.0, h, false), e}; }
  template <class F>
  bool meeting(F&& f);
  void sort_closing();
  bool landing(const Components& k, std::span<const EntityId> bodies, double h);
  std::vector<std::uint8_t> impacted_;  // by entity id: had an impact in the solver this substep
  void count_pressed();
  void count_squeezed(const Components& k, std::span<const Contact> contacts);
  bool squeezes(const Components& k, EntityId e, EntityId pusher, EntityId wall, int side) const;
  // count_squeezed's: each finite body's last push towards each side (0: +x,
  // 1: -x, 2: +y, 3: -y) in the course's pass: when (plan's count of
  // substeps) and by which body.
  struct Push {
    std::int64_t at = std::numeric_limits<std::int64_t>::min() / 2;
    EntityId by = 0;
  };
  std::vector<std::array<Push, 4>> pushes_;  // by entity id
  std::int64_t substep_ = 0;  // plan()s so far
  double h_ = 0;              // the last plan()'s substep, ms
  std::vector<std::uint64_t> pressed_;  // keys of the pairs of finite bodies pressed together this substep
  std::vector<std::pair<std::uint64_t, int>> runs_, next_runs_;  // (key, substeps in a row), sorted
  int hold_left_ = 0;
  int jam_left_ = 0;  // substeps the solver still takes a jam whole for (after_sweep)
  bool trial_ = false;  // the solver's path is on trial this substep
  bool sweep_all_ = false;  // sweep_all()
  bool any_undone_ = false;
  std::vector<Vector> kept_position_, kept_velocity_;  // keep(), by entity id
  struct Island {  // roll_back()'s, at its root
    bool chain = false, elastic = true;
    double before = 0, after = 0;  // kinetic energy
  };
  UnionFind root_;                    // roll_back()'s islands, by entity id
  std::vector<Island> islands_;       // by entity id (of the root)
  std::vector<std::uint8_t> undone_;  // by entity id
  bool solver_path_ = false;
  bool first_ = false;      // the scene's first substep, under gravity
  bool gravity_ = false;    // the last plan()'s gravity was not zero
  bool started_ = false;    // a substep was planned (or a saved state restored)
  bool start_set_ = false;  // start_ holds impact times (reset at the next plan())
  double thinnest_ = -1;    // the world's thinnest side at the last plan(), px
  std::size_t fast_count_ = 0;
};

}  // namespace physics
