// The stable contact solver (Params::solver = Solver::stable).
//
// The course resolves each overlapping pair once per step, one after the
// other. A body resting on the floor under gravity therefore sinks by g·dt²
// every step and is pushed out again, a stack's lower blocks are pushed into
// the floor by the ones above, and a heavy block on a light one drives it
// through the floor: the one pass cannot carry a weight down to the ground.
//
// This solver, per substep of h ms, in named stages (as Box2D v3's
// contact_solver.h: prepare, warm start, solve, restitution, store), each
// timed under its own name (engine/timing.hpp):
//  1. solve_velocities, before Move: prepare, warm_start, relax, restitution,
//     impact_time, store. contacts are the pairs whose boxes are
//     closer than `margin` along their separating axis (speculative, so a
//     resting body is caught before it sinks), each with the normal of
//     contact_axis (engine/contact.hpp: no ghost collision at the seams of
//     touching boxes). Sequential impulses, each
//     clamped so that the impulse accumulated on a contact never pulls
//     (Catto's accumulated clamping), warm started from the previous
//     substep's impulses of resting contacts. A real impact is first stopped
//     (target normal velocity 0), then given e times the impulse that
//     stopped it (Poisson's restitution, e = min of the pair as in the
//     course): that never adds energy, even with simultaneous contacts. Gauss-Seidel converges
//     slowly across mass ratios (a light block under a heavy one carries only
//     its own mass's worth of impulse per iteration), so the iterations end
//     with one pass of shock propagation (Guendelman, Bridson, Fedkiw 2003):
//     contacts that carry weight (normal along gravity) are taken from the
//     ground up (by each body's longest chain of support), the lower body
//     treated as immovable; then the same along the axes gravity has no
//     component on, both ways, from the fixed bodies out (a wall holds what
//     is pushed into it as the floor holds a stack). It runs only on bodies
//     that rest on a fixed one through such contacts; free bodies keep the
//     plain, momentum-conserving impulses.
//     If the solve turned a body towards one it had no contact with (a
//     light block bouncing off a wall back into its pusher), the contacts
//     are taken again from where the solve left the bodies and solved again,
//     round after round (turned_to_meet()).
//     The iterations run on a hot copy (schedule(), load_rows()): the
//     bodies' velocities and inverse masses by a dense slot, the contacts'
//     few fields they read, in an order that keeps every body's contacts in
//     the given order (so the same bits) but puts contacts that share no
//     body side by side, for the processor to overlap. What depends only on
//     which contacts there are (that order, the slots, the bottom-up order,
//     the warm start's matching) is kept while they stay the same; when no
//     body changed either (a resting pile, most substeps), so are the
//     contacts themselves and the hot rows (classify(), refresh_rows()).
//     Without friction the x rows and the y rows share no value: with
//     threads, both are swept at once (iterate()).
//  2. solve_positions (stage `positions`), after Move: what still overlaps by more than `slop` is
//     projected apart (non-linear Gauss-Seidel on positions, shared in
//     proportion to inverse masses, then the same bottom-up pass). Positions
//     only: no velocity is added, so no energy is (unlike a Baumgarte bias).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <tuple>
#include <vector>

#include "engine/components.hpp"
#include "engine/contact.hpp"
#include "engine/island_solve.hpp"
#include "engine/pairs.hpp"
#include "engine/same_bits.hpp"
#include "engine/sweep_pipeline.hpp"
#include "engine/timing.hpp"
#include "engine/union_find.hpp"
#include "engine/workers.hpp"

namespace physics {

struct SolverSettings {
  int iterations = 8;         // velocity and position iterations
  double margin = 0.5;        // px: speculative contact distance
  double slop = 0.01;         // px: overlap left alone (keeps resting contacts alive)
  double touch = 0.05;        // px: a gap within ±touch counts as touching when choosing a normal (contact_axis)
  double projection = 0.8;    // share of the overlap beyond slop removed per position iteration
  bool shock_propagation = true;
  bool impacts = true;        // false with CCD on: impacts are left to it
  bool exact_motion = false;  // Params::integrator is exact (gravity_after_impact)
  // Rounds after the first, at most, per substep, when a solve turned a
  // body towards one it had no contact with (turned_to_meet()). 0: one round.
  // The stable solver takes 3 (World's solver_settings), and auto under
  // gravity (World::auto_before_move): the family's push-into-wall 38 -> 50
  // of 50 under stable, 41 -> 46 under auto.
  // Without impacts (CCD on) there is one round whatever this says.
  int rounds = 0;
  // A later round takes a pair's axis where its bodies really are when the
  // line-start one is the far side (physical_axes()). Auto's only for now
  // (World's solver_settings): the stable mode with it passes four bullet
  // cells of the matrix it is listed as failing (100-2000 px/ms, head on:
  // its last round stops the bullet), and as the cheapest passing mode
  // there it puts auto's cost at 3-9x its own (branch autofix-stable-axes).
  bool physical_axes = false;
  // By entity id, the velocities before this substep's Forces (the slide
  // integrator's, engine/slide.hpp); with CCD on, the pairs Forces turned to
  // close within the substep are left to it (turned_by_forces()). Empty: none.
  std::span<const Vector> before_forces;
  // The threads of the loops whose items are independent (the same bits for
  // any number); none: one thread.
  Workers* workers = nullptr;
};

// A resting contact's impulses at the end of a substep: what the next
// substep's warm start reads, and so what a saved world must keep.
struct WarmImpulse {
  Pair pair;
  int axis;   // as ContactConstraint::axis
  double jn;  // normal impulse, > 0
  double jt;  // tangential impulse
  friend bool operator==(const WarmImpulse&, const WarmImpulse&) = default;
};

struct SolverStats {
  std::int64_t contacts = 0;       // contacts solved, summed over substeps
  std::int64_t energy_clamps = 0;  // body velocities the energy guard scaled back
  std::int64_t pipelined = 0;      // relaxations whose y rows' last sweeps ran on two threads (pipelined_sweeps)
  std::int64_t orders_beside = 0;  // bottom-up orders made on a helper while the sweeps ran (beside())
  std::int64_t projections_pipelined = 0;  // projections whose sweeps ran on two threads (pipelined_projection)
  std::int64_t in_waves = 0;  // relaxations whose y rows' last sweeps ran in waves on one thread (pipelined_sweeps)
  std::int64_t pipelines_left = 0;  // relaxations and projections that would have been pipelined, on one thread: the helpers were late (Workers::prompt)
};

// One contact as the solver's iterations read it: the pair, its axis and
// inverse masses (its accumulated impulses apart: ContactImpulse).
struct ContactConstraint {
  EntityId c, b;
  int axis;          // 0: -x, 1: +x, 2: -y, 3: +y (the normal that moves c away from b)
  bool resting;      // no restitution target: its impulse may warm start the next substep
                     // (here, not last: it fills the padding after axis)
  double wc, wb;     // inverse masses
  double inv_w;      // 1 / (wc + wb): the iterations multiply by it (a division there sat on the dependency chain)
  double target;     // lowest allowed (v_c - v_b)·n
  double restitution;  // of an impact: bounce impulse = restitution × lambda
  double toi;          // of an impact found before touching: ms into the substep
};

// A contact's accumulated normal impulses, beside its ContactConstraint
// (same index), in an array of their own: the passes that clear, load, store
// and keep them at every substep read 16 bytes a contact, not its 64-byte
// contact (a resting pile's contacts, beyond the caches: those passes were a
// third of many_pyramids' step, perf).
struct ContactImpulse {
  double lambda;   // accumulated impulse
  double lambda2;  // accumulated in the relaxation after the bounces
};

// A contact's friction, beside its ContactConstraint (same index), kept only
// while some contact of the substep has friction: the frictionless loop
// reads no more memory than before friction existed.
struct FrictionRow {
  double mu;         // the pair's coefficient, sqrt(mu_c mu_b)
  double lambda;     // accumulated tangential impulse, along tangent(n), |.| <= mu × normal
  double lambda2;    // the same in the relaxation after the bounces
};

// A contact of a bottom-up pass, as the pass reads it: its bodies, axis and
// index among the solver's contacts, and which end is the upper body (the
// one the pass moves; the lower is immovable for it).
struct ShockRow {
  EntityId c, b;
  std::uint32_t index;
  std::uint8_t axis;
  bool c_upper;
};

// One bottom-up pass of shock propagation: the direction taken as down (the
// lower body of a contact lies that way and is immovable for the pass) and
// its contacts in order, lowest first. Only contacts whose upper body can
// move are listed (the others would change nothing), each with what the
// pass reads of it: a pile's pass reads this list in order and the
// velocities and targets, not the solver's 64-byte contacts at random.
// One thread runs it: a pile's pass is some hundred levels of some hundred
// rows each, a level's rows waiting for the levels below, and split by
// columns over two threads it took as long as on one (the level-by-level
// waits cost what the second thread saved: docs/performance-log.md).
struct ShockPass {
  Vector down;
  std::vector<ShockRow> rows;
};

// On x86-64, functions built for AVX2 beside the rest (friction_four:
// PHYSICS_WIDE_ROWS), with PHYSICS_AVX2 as their attribute;
// ContactSolver::wide_rows says whether they run.
#if defined(__x86_64__) && defined(__GNUC__)
#define PHYSICS_WIDE_ROWS 1
#define PHYSICS_AVX2 __attribute__((target("avx2")))
#else
#define PHYSICS_WIDE_ROWS 0
#define PHYSICS_AVX2
#endif

class ContactSolver {
 public:
  void solve_velocities(Components& k, std::span<const EntityId> entities, double h, Vector gravity,
                        const SolverSettings& s, BroadPhase& broadphase, StageTimes& times);
  void solve_positions(Components& k, std::span<const EntityId> entities, Vector gravity, const SolverSettings& s,
                       BroadPhase& broadphase, StageTimes& times);

  SolverStats stats;


  // The last substep's contacts (velocity stage), their accumulated
  // impulses and their friction rows (empty when no contact had friction),
  // each by the same index, for contact events.
  // When the substep took several rounds (turned_to_meet), every round's.
  std::span<const ContactConstraint> constraints() const { return earlier_.empty() ? contacts_ : earlier_; }
  std::span<const ContactImpulse> impulses() const { return earlier_.empty() ? impulses_ : earlier_impulses_; }
  std::span<const FrictionRow> friction_rows() const { return earlier_.empty() ? friction_ : earlier_friction_; }

  // The warm-start impulses the next substep reads (save and restore).
  std::vector<WarmImpulse> warm_impulses() const;
  void restore(std::span<const WarmImpulse> impulses);

  // How the frictionless x rows of the last order were cut (order_by_axis()):
  // all above and none across where they were not. For the tests.
  struct XRowCut {
    std::size_t below, above, across;
  };
  XRowCut x_row_cut() const { return {x_below_, x_above_, x_rows_ - x_below_ - x_above_}; }
#if PHYSICS_HAS_THREADS
  // The fewest y rows swept in waves on one thread (tests: a small pile's; pipelined_sweeps()).
  void sweep_in_waves_from(std::size_t y_rows) { wave_rows_ = y_rows; }
#endif

  // Whether the friction sweep solves four rows at once with AVX2, where the
  // processor has it (else two with SSE2): the same bits either way. This
  // solver's own (the tests turn it off to compare the two); false where
  // there is no such path.
  bool wide_rows = has_wide_rows();
  static bool has_wide_rows();

 private:
  // The stages of solve_velocities, in order.
  void prepare(const Components& k, double h, Vector g, const SolverSettings& s);
  void classify(const Components& k, double h, double threshold, const SolverSettings& s);
  std::uint8_t make_contacts(const Components& k, double h);
  std::uint8_t keep_contacts();
  enum class PairKind : std::uint8_t { apart, left /* to CCD */, contact, impact };
  // Inlined into prepare()'s loops, their only callers: called, they made
  // the pyramid's step 2.7 % longer (saved registers and reloads).
  [[gnu::always_inline]] PairKind pair_kind(const Components& k, std::size_t i, double h, double threshold,
                                            const SolverSettings& s);
  [[gnu::always_inline]] std::uint8_t make_contact(const Components& k, std::size_t i, double h, std::size_t j);
  struct RangeCount {
    std::size_t apart = 0, contacts = 0, impacts = 0;
  };
  std::vector<PairKind> kinds_;         // by pair (prepare())
  std::vector<double> normal_speeds_;   // by pair: (v_c - v_b)·n (prepare())
  std::vector<RangeCount> counts_;  // prepare(): by range, then where each range's go
  // What the pairs were last classified for (classify()): each body's
  // state, the pairs and the settings; classified_: axes_, kinds_ and
  // normal_speeds_ still hold that classification's results.
  struct ClassifiedBody {
    Vector position, velocity;
    Rect box;
    double mass, restitution, friction;
  };
  struct ClassifyInputs {
    double h, threshold, margin, touch;
    friend bool operator==(const ClassifyInputs&, const ClassifyInputs&) = default;
  };
  void changed_since_classified(const Components& k);
  bool any_overlap(const Components& k, double slop);
  std::vector<ClassifiedBody> classified_bodies_;  // by entity id
  std::vector<std::uint8_t> changed_;              // by entity id, for the bodies of pairs_: differs from classified_bodies_
  std::vector<EntityId> cut_sample_;               // id_cuts()' scratch
  std::array<EntityId, max_threads + 1> id_cuts(std::span<const Pair> pairs, std::size_t ranges);
  std::vector<std::uint32_t> visited_;             // by entity id: the call of changed_since_classified() that looked at it
  std::vector<std::uint8_t> moved_;                // by entity id (any_overlap()): place differs from classified_bodies_
  // any_overlap()'s: whether some classified pair's separation (axes_) is
  // below -overlap_slop_ (classified_overlap_), known until axes_ is written
  // again (overlap_known_).
  bool classified_overlap_ = false, overlap_known_ = false;
  double overlap_slop_ = 0.0;
  std::uint32_t visit_ = 0;
  std::vector<Pair> classified_pairs_;
  ClassifyInputs classified_for_{};
  bool classified_ = false;
  bool same_kinds_ = false;                 // classify() kept the last list and every pair's kind
  bool any_changed_ = true;                 // changed_ holds a change
  bool kept_all_ = false;                   // classify() kept everything (the same pairs, no body changed)
  std::vector<std::uint8_t> contact_bits_;  // by contact: make_contact()'s result
  static bool turned_by_forces(const SolverSettings& s, const Pair& p, Vector n);
  static bool left_to_ccd(const SolverSettings& s, const Pair& p, Vector n, bool impact, bool closes_apart);
  void schedule(const Components& k, Vector g, bool kept_all);
  void warm_start(Components& k);
  void warm_start_search(Components& k);
  void warm_start_one(Components& k, std::size_t i, double jn, double jt);
  void relax(Components& k, Vector g, const SolverSettings& s, bool after_bounce);
  void load_rows(const Components& k, bool after_bounce);
  void load_contact_rows(bool after_bounce);
  void refresh_rows();
  bool plain_rows_ = false;  // rows_ are load_contact_rows(false)'s for this substep's contacts and order
  void store_rows(Components& k, bool after_bounce);
  template <bool friction>
  void iterate(const SolverSettings& s);
  // A new bottom-up order (contacts that began or ended) is made on a helper
  // while this thread loads, sweeps and stores the rows, when there is a
  // team: an order takes longer than the sweeps (a rain of 100 000 landing:
  // 0.95 ms an order, one thread's sweeps 0.50 beside it, two threads' 0.56
  // before it), and the team's sweeps would wait for it. The order reads
  // the contacts and masses, the rows the velocities or the positions: the
  // same bits.
  bool aside() const { return has_threads && workers_ && workers_->threads() > 1; }
  // here() and helper() side by side on the team (aside(); a helper that
  // does not come leaves helper() to this thread): neither uses the team.
  template <class Here, class Helper>
  void beside(Here&& here, Helper&& helper);
  void prepare_friction(const Components& k, bool any, bool kept_all);
  void restitution(Components& k, Vector g, const SolverSettings& s);
  void guard_energy(Components& k);
  bool any_body_gained(const Components& k) const;
  void island_energies(const Components& k);
  void find_islands(std::size_t n);
  bool islands_found_ = false;  // bodies_, island_ and sums_ are this round's contacts' (find_islands())
  void list_marked(std::size_t n);  // bodies_: the ids below n whose seen_ is set, in order; the marks cleared
  void impact_time(Components& k, double h, Vector g, bool exact_motion);
  void store();
  // Another round when a solve turned apart pairs towards each other.
  bool turned_to_meet(const Components& k, std::span<const EntityId> entities, double h, const SolverSettings& s,
                      BroadPhase& broadphase);
  void add_unknown_pairs();
  bool swept_further(const Components& k, double h, double reach) const;
  void keep_round();
  bool last_round_ = false;             // round `rounds`: no bounce
  // Whether an impact bounces (its restitution stays the pair's: auto reads it).
  bool bounces(std::size_t i) const {
    return !last_round_ && contacts_[i].restitution > 0.0 && impulses_[i].lambda > 0.0;
  }
  std::vector<std::uint32_t> apart_;    // pairs prepare() did not take: neither close nor closing
  std::vector<std::uint32_t> pair_of_;  // by contact: its index in pairs_
  std::vector<Pair> later_;             // turned_to_meet(): the pairs for the solved velocities
  std::vector<std::uint64_t> known_;    // turned_to_meet(): pairs_' keys, sorted
  bool known_valid_ = false;            // known_ holds this substep's pairs_
  // The earlier rounds' contacts and friction rows (then the last round's
  // too: constraints()), and their resting impulses by pair (store()).
  std::vector<ContactConstraint> earlier_;
  std::vector<ContactImpulse> earlier_impulses_;
  std::vector<FrictionRow> earlier_friction_;
  std::vector<double> earlier_jn_, earlier_jt_;
  void contact_axes(const Components& k, const SolverSettings& s);
  bool plain_axis(const Components& k, std::size_t i, double touch);
  void corner_axes(const Components& k, const SolverSettings& s, bool local);
  static constexpr std::uint8_t tainted = 16;  // faces_' bit: corner_axes() takes this body's corner pairs again
  void physical_axes(const Components& k, const SolverSettings& s);
  std::vector<double> line_start_;   // by entity id: ms from which its line is its motion (impact_time()), or 0
  std::vector<EntityId> shifted_;    // the bodies whose line_start_ is set this substep
  std::vector<ContactAxis> axes_;    // by pair: its normal (contact_axes())
  std::vector<std::uint8_t> faces_;  // by entity id: touching_face's bits over its pairs (contact_axes())
  Workers* workers_ = nullptr;  // this call's (SolverSettings::workers)
  // solve_positions' stages.
  bool prepare_positions(const Components& k, const SolverSettings& s);
  void project(Components& k, Vector g, const SolverSettings& s);
  void measure_positions(const Components& k, const SolverSettings& s);
  // A contact of the position stage: the pair and its axis, and (project())
  // c's size along it, the sum of both sizes, each body's share of a correction.
  // `moves`: bit 0, c's position may change (links()); bit 1, b's.
  struct PositionContact {
    EntityId c, b;
    int axis;  // as ContactConstraint::axis
    std::uint8_t moves;
    double size_c, sizes, share_c, share_b;
  };
  static double gap(const Components& k, const PositionContact& ct);
  static bool project_contact(Components& k, const PositionContact& ct, const SolverSettings& s);
  std::vector<PositionContact> positions_;
  bool have_position_keys_ = false;  // position_keys_ holds the last projection's
#if PHYSICS_HAS_THREADS
  // The projection's sweeps on two threads (engine/sweep_pipeline.hpp), in
  // projection_order_ (plan_projection()), planned again when its contacts change.
  SweepPipeline projection_pipeline_;
  std::vector<std::uint32_t> projection_order_;  // indices into positions_
  void plan_projection(std::size_t body_count);
  void pipelined_projection(Components& k, const SolverSettings& s, Workers& w);
  bool pipelines_pay(const Workers& w);
#endif
  std::vector<std::vector<PositionContact>> position_parts_;  // prepare_positions()' lists of a team's threads

  std::vector<Pair> pairs_;
  std::vector<ContactConstraint> contacts_;
  std::vector<ContactImpulse> impulses_;  // by contact
  IslandSolve islands_solve_;  // relax's exact solve of small free islands (engine/island_solve.hpp)
  // The iterations' copy of the contacts and their bodies (schedule()):
  // what the hot loop reads and nothing else, bodies by a dense slot.
  struct SolverBody {
    Vector v;  // velocity
    double w;  // inverse mass
  };
  // (Without friction, by axis: c and b swapped where the normal is -x or
  // -y, load_rows(). With friction, the axis is the friction row's: a row
  // without it is 24 bytes, not 32.)
  // A row's accumulator is apart (row_lambda_), in an array of its own: a
  // sweep writes only it, so in a pile too large for the cache the rows
  // stream in and only the accumulators go back out (a settled rain of
  // 100 000: 8 bytes a row written back instead of the row's 32).
  struct SolverRow {
    std::uint32_t c, b;    // slots
    double inv_w, target;  // as ContactConstraint's
  };
  struct FrictionHot {
    double mu, lambda;
    std::uint32_t axis;  // the contact's (the normal's, as ContactConstraint::axis)
  };
  bool sweep_friction();
  template <bool wide>
  bool sweep_friction_rows();
  // The rows' functions are inlined into the sweeps: the attribute on these
  // declarations, where GCC reads it for a template's instances (on the
  // definition alone it was dropped, and friction_two was called per pair).
  template <double Vector::*n, double Vector::*t>
  [[gnu::always_inline]] static bool friction_row(const SolverRow& r, double& lambda, FrictionHot& f,
                                                  std::span<SolverBody> bodies);
  template <bool y>
  [[gnu::always_inline]] static bool friction_row_sse2(const SolverRow& r, double& lambda, FrictionHot& f,
                                                       SolverBody& bc, SolverBody& bb);
  template <bool y>
  [[gnu::always_inline]] static bool friction_two(std::span<const SolverRow, 2> r, double* lambda,
                                                  std::span<FrictionHot, 2> f, std::span<SolverBody> bodies);
  template <bool y>
  PHYSICS_AVX2 static bool friction_four(const SolverRow* r, double* lambda, FrictionHot* f, SolverBody* bodies);
  // Without friction, one velocity component and the inverse mass: the x
  // rows and the y rows each read their own (axis_bodies_), so that two
  // threads sweep them at once without sharing a cache line (but where the
  // x rows' two stretches meet, order_by_axis(): a line at most, no value).
  struct AxisBody {
    double v, w;
  };
  // A sweep's findings (sweep_axis): bit `changed`, some accumulator
  // changed; bit `short_of_target`, some row's relative speed was below its
  // target (or NaN) when it was solved.
  static constexpr std::uint8_t changed = 1, short_of_target = 2;
  static std::uint8_t sweep_axis(std::span<const SolverRow> rows, std::span<double> lambda,
                                 std::span<const std::uint8_t> paired, std::span<AxisBody> bodies);
  [[gnu::always_inline]] static std::uint8_t sweep_two(const SolverRow& r0, const SolverRow& r1, double* lambda,
                                                       std::span<AxisBody> bodies);
  // By axis (x, y): the last frictionless relaxation stopped on a sweep of
  // that axis that changed nothing and found every row at or above its
  // target (iterate<false>), so its rows still are there (relax()).
  std::array<bool, 2> axis_at_targets_{};
#if PHYSICS_HAS_THREADS  // (not in the browser's build: no threads, and each member costs bytes)
  // The y rows' sweeps on two threads, one sweep behind the other, or in
  // waves on one (pipelined_sweeps(), engine/sweep_pipeline.hpp). Planned
  // again after schedule().
  SweepPipeline pipeline_;
  static constexpr std::size_t pipeline_block = 1024;                // items (y rows, projection contacts)
  static constexpr std::size_t pipeline_rows = min_parallel_items;  // the fewest y rows pipelined
  bool y_rows_unplanned() const;
  void plan_y_rows();
  std::uint8_t pipelined_sweeps(Workers* w, std::span<const SolverRow> rows, std::span<double> lambdas,
                                std::span<const std::uint8_t> paired, int sweeps);
  // The fewest y rows swept in waves on one thread (pipelined_sweeps):
  // about 1.6 MB of rows and bodies' values, beyond the level-2 cache.
  std::size_t wave_rows_ = 32768;
  bool order_kept_ = false;  // the last schedule() kept the order it found
  int y_sweeps_ = 0;         // the y rows' sweeps that counted in the last frictionless relaxation
#endif
  bool skips_pass(const Components& k, Vector down, bool& tame);
  std::span<const std::uint32_t> row_order() const;
  std::uint64_t velocity_finds_ = ~std::uint64_t{0};  // the broad phase's finds() after solve_velocities
  std::vector<std::uint32_t> slot_of_;     // by entity id: slot, or none when not in a contact
  std::vector<EntityId> slot_body_;        // by slot: the entity
  std::vector<SolverBody> solver_bodies_;  // by slot (with friction)
  std::array<std::vector<AxisBody>, 2> axis_bodies_;  // by slot, x then y (without friction)
  std::vector<std::uint32_t> order_;       // contacts in the iterations' order
  std::vector<std::uint32_t> by_axis_;     // order_'s x rows, then its y rows (row_order(), order_by_axis())
  std::size_t x_rows_ = 0;                 // how many of by_axis_ are x rows
  std::size_t x_below_ = 0, x_above_ = 0;  // of those, how many below the cut, how many above (order_by_axis())
  // How many x rows a world needs for them to be cut (order_by_axis()).
  static constexpr std::size_t cut_x_rows = min_parallel_items;
  void order_by_axis();
  bool same_level(std::uint32_t a, std::uint32_t b) const;
  std::vector<std::uint8_t> paired_;       // by row of by_axis_: it and the next may be solved together
  std::vector<std::uint8_t> friction_paired_;  // the same by row of order_ (with SSE2: group_friction_rows)
  // By row of order_, with friction: how many rows from it the friction sweep
  // solves together (group_friction_rows()).
  std::vector<std::uint8_t> friction_group_;
  void group_friction_rows();
  std::vector<SolverRow> rows_;            // contacts_[row_order()[i]], hot fields
  std::vector<double> row_lambda_;         // by row: its accumulator (SolverRow)
  std::vector<FrictionHot> friction_rows_; // friction_[order_[i]], hot fields
  // schedule()'s: each contact's level in its chunk; per thread of the team,
  // each slot's level after its last contact in the chunk (all 0 between
  // chunks; order_by_axis counts in the first) and a count per level.
  struct LevelScratch {
    std::vector<std::uint32_t> last_level, count;
  };
  static constexpr std::size_t schedule_chunk = 4096;  // contacts
  void order_chunk(std::size_t start, std::size_t end, LevelScratch& scratch);
  std::vector<std::uint32_t> level_;
  std::vector<LevelScratch> level_scratch_;
  // What order_, the slots and support_order_ were made for (schedule()):
  // each contact's bodies, axis, fixed ends (bits 2, 3) and links (bits 4, 5).
  struct TopologyKey {
    EntityId c, b;
    std::uint32_t flags;
    friend bool operator==(const TopologyKey&, const TopologyKey&) = default;
  };
  std::vector<TopologyKey> topology_, topology_next_;
  bool scheduled_ = false;
  bool same_topology_ = false;  // this substep's contacts are last substep's (topology_next_ holds last substep's)
  Vector topology_g_{};
  // The position stage's bottom-up order, and what it was made for: each
  // contact's bodies, axis and fixed ends (bits 2, 3), gravity.
  std::vector<ShockPass> position_order_;
  std::vector<TopologyKey> position_keys_, position_keys_next_;
  Vector position_g_{};
  bool have_position_order_ = false;
  std::vector<FrictionRow> friction_;          // empty, or one per contact
  std::vector<ShockPass> support_order_;       // bottom-up passes over this substep's contacts
  std::vector<std::uint32_t> support_ids_;     // by entity id: none (shock_passes()' scratch)
  std::vector<EntityId> support_met_;          // shock_passes()' scratch
  bool have_order_ = false;
  std::vector<double> targets_;                // by contact: its target in this relaxation (load_rows(), for the bottom-up pass)
  std::vector<double> inverse_mass_;           // by entity id, this substep's (solve_velocities)
  std::vector<Vector> v_start_, v_inelastic_;  // by slot
  bool have_inelastic_ = false;                // v_inelastic_ holds this round's (keep_inelastic())
  void keep_inelastic(const Components& k);
  std::vector<std::uint32_t> impacts_;         // the contacts that are not resting, in order
  // The energy guard's islands: kinetic energies at the start, after the
  // inelastic relaxation and at the end, and the coefficients of the
  // quadratics in the blend factors (rest: the bounces; back: towards the start).
  // Energies are taken in the frame of the fixed bodies the island touches:
  // a moving one (a pusher of infinite mass) does work on it, and its
  // impacts keep the relative energy, not the absolute one.
  struct IslandEnergy {
    double start = 0, inel = 0, end = 0, b_rest = 0, a_rest = 0, b_back = 0, a_back = 0;
    Vector frame{};  // the velocity of the fixed bodies it touches
    int frames = 0;  // how many different ones: 0, 1, or 2 (several: no frame keeps its energy, no guard)
  };
  bool moving_fixed_ = false;  // some contact of the substep has a fixed body that moves
  std::vector<IslandEnergy> sums_;
  std::vector<EntityId> bodies_;               // finite bodies of the contacts, by id
  UnionFind islands_;                          // the energy guard's islands
  std::vector<std::uint32_t> island_;
  std::vector<std::uint8_t> seen_;             // guard_energy: bodies of the contacts (0 between calls)
  std::vector<std::uint32_t> root_index_;      // guard_energy: island of each root (none between calls)
  std::vector<double> toi_;                    // earliest impact time per body, by entity id (infinity between calls)
  // The impulses of the last substep's contacts (store()), by contact; the
  // normal one 0 for a contact that does not warm start the next substep.
  std::vector<double> last_jn_, last_jt_;
  void last_impulses(std::span<const TopologyKey> contacts,
                     std::vector<std::tuple<std::uint64_t, int, double, double>>& out) const;
  // The warm_start's sorted list (pair key, axis, normal impulse, tangential
  // impulse): made from the above when the contacts changed, or given by
  // restore() (restored_: the list holds the impulses, the above do not).
  bool restored_ = false;
  std::vector<std::tuple<std::uint64_t, int, double, double>> warm_;
};

}  // namespace physics
