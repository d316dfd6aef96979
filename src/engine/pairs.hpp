// The world's one broad phase: every stage asks it for its candidate pairs
// (the course's Collision pass, CCD, the stable solver), and it keeps one
// uniform grid (engine/broadphase.hpp) for all of them.
//
// Two ways to ask:
//  - course_pairs(): the pairs of the sheet's loop "for each pair (c, b)",
//    in its order (c registered before b), as Collision::update resolves
//    them. The grid is built on each body's box grown by `course_margin`;
//    when a correction pushes a body out of its box, the pairs it may now
//    form that the loop has not reached yet are found and merged in. So the
//    pass resolves exactly the pairs the all-pairs loop finds overlapping,
//    in the same order, with the same values (tests/test_broadphase.cpp).
//    When many bodies leave their boxes (blocks started on top of each
//    other), the pass goes on row by row instead: each body's pairs with the
//    bodies after it are looked up when the loop reaches it, in a grid that
//    follows the corrections, so no list of the whole world is sorted again.
//  - find(h, reach): every pair whose boxes, each swept over h ms at its
//    velocity and grown by `reach`, overlap or touch; exactly the all-pairs
//    definition brute_force_pairs() keeps for the tests. The grid is built
//    on boxes grown by `fat_margin` (and by `fat_steps` calls' motion along
//    the velocity) and kept while every body stays inside its fat box: a
//    resting pile, or bodies falling together, cost a filter per call, not a
//    grid. The few bodies that leave theirs (bouncing off a pile) are given
//    new ones in the kept grid (regrow()); many, or a mass turned finite or
//    infinite, build it again.
// Pairs of two infinite masses are never listed (two walls never collide),
// nor pairs the bodies' contact rules exclude (engine/rules.hpp: filters,
// sensors, one-way platforms), tested only while some body has rules.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "engine/components.hpp"
#include "engine/broadphase.hpp"
#include "engine/rules.hpp"
#include "engine/workers.hpp"

namespace physics {

// A pair of bodies, c registered before b: the one pair type of the engine.
struct Pair {
  EntityId c, b;
  // Packed, so that sorting keys sorts pairs by c, then b.
  std::uint64_t key() const { return (std::uint64_t{c} << 32) | b; }
  friend bool operator==(Pair, Pair) = default;
};

class BroadPhase {
 public:
  class CoursePairs;
  // The course pass's pairs in a step of h ms (h: for one-way platforms);
  // valid until the next call on this broad phase.
  CoursePairs course_pairs(const Components& k, std::span<const EntityId> entities, double h);

  // `workers`: the threads of its loops over the bodies and the candidates
  // (the same pairs, in the same order, for any number); none: one thread.
  void find(const Components& k, std::span<const EntityId> entities, double h, double reach, std::vector<Pair>& out,
            PairRule rule = PairRule::solvable, Workers* workers = nullptr);
  // find() again, when since the last find(), for the same bodies, h and
  // reach, only the bodies of `changed` may have moved or changed velocity,
  // box or mass (the solver's, after its solve; each listed once, as the
  // threads renew their boxes apart): the others' boxes are not made again.
  // The same pairs as find(); find() itself when that last call is not
  // known to be such (another h or reach, other bodies, rules).
  void find_again(const Components& k, std::span<const EntityId> entities, std::span<const EntityId> changed,
                  double h, double reach, std::vector<Pair>& out, PairRule rule = PairRule::solvable,
                  Workers* workers = nullptr);
  // Whether every body of `entities`, where it is now, lies within the box
  // the last find() swept for it (for the same bodies, with no contact
  // rules): then every pair whose boxes overlap now was among its pairs.
  // `workers`: as find()'s.
  // `finds()` counts the calls of find(), to tell whose that last one was.
  bool holds(const Components& k, std::span<const EntityId> entities, Workers* workers = nullptr) const;
  std::uint64_t finds() const { return finds_; }
  // How many times find() built its grid (not counting the few bodies
  // given new boxes in it: regrow()).
  std::uint64_t builds() const { return builds_; }
  // The pairs of find(h, 0) that include a selected body (`selected`, by
  // entity id; CCD's fast bodies in the auto mode). A few selected bodies
  // are each tested against every body, which costs less than a grid of the
  // whole world; many take find()'s pairs.
  void find_selected(const Components& k, std::span<const EntityId> entities, std::span<const std::uint8_t> selected,
                     double h, std::vector<Pair>& out);

  // After a course pass, before anything else asks: calls f(pair) for each
  // pair the pass's grid lists (boxes grown by course_margin that overlapped
  // when the pass began), in the sheet's order. No
  // grid is built, so it costs a walk over a list: the health check's look
  // for deep overlaps (engine/health.hpp). Nothing when the grid is find()'s.
  template <class F>
  void each_course_candidate(F&& f) const {
    if (fat_built_) return;
    for (const PairKey key : grid_.pairs()) f(Pair{course_entities_[pair_first(key)], course_entities_[pair_second(key)]});
  }

  // px. How far a correction may push a body before its pairs are looked up
  // again; any value >= 0 gives the same pairs, this one was the fastest on
  // the bench scenes (fewer look-ups against more candidates).
  double course_margin = 1.0;
  // px. Larger keeps a grid longer but lists more candidates to filter;
  // 2 px is a fifth of the bench's blocks and above a resting body's drift.
  double fat_margin = 2.0;
  // Calls of h ms ahead that a fat box reaches along its body's velocity.
  double fat_steps = 3.0;

  // What the last course pass did, for the benchmark.
  struct Stats {
    std::size_t candidates = 0;  // pairs found when the pass began
    std::size_t requeries = 0;   // bodies pushed out of their box during the pass
    bool by_rows = false;        // went on row by row (many bodies pushed out)
  };
  const Stats& stats() const { return stats_; }
  const UniformGrid& grid() const { return grid_; }

  // A body's box in double, [x0, x1] x [y0, y1].
  struct Bounds {
    double x0, y0, x1, y1;
  };

 private:
  // The course pass. course_next() is inline: it runs once per candidate
  // pair, and most pairs leave both bodies in their boxes and take the next
  // listed pair; the rest goes to course_next_slow().
  void course_build(const Components& k);
  bool course_next(const Components& k, Pair& out);
  void pushed_out(const Components& k);  // the last pair's correction pushed a body out of its box
  bool course_next_slow(Pair& out);     // the next pair, merging the list with the pairs found late
  // From `out` (or the end, if done) on, the first pair the rules keep.
  bool course_skip_unsolvable(const Components& k, Pair& out, bool done);
  static constexpr std::size_t pair_ahead = 8;  // course_next() asks for the bodies of the pair this far ahead
  [[gnu::always_inline]] void prefetch_body(const Components& k, std::uint32_t i) const {
    const EntityId e = course_entities_[i];
    __builtin_prefetch(&k.position[e]);
    __builtin_prefetch(&k.box[e]);
    __builtin_prefetch(&k.mass[e]);
    __builtin_prefetch(&boxes_[i]);
  }
  bool inside(const Components& k, std::uint32_t i) const {
    const EntityId e = course_entities_[i];
    return boxes_[i].contains(k.position[e], k.box[e]);
  }
  // A new box for body i if it left its own (counted in stats_.requeries); whether it did.
  bool rebox(const Components& k, std::uint32_t i);
  bool refresh(const Components& k, std::uint32_t i, PairKey current);
  // Row by row: the pairs (i, j > after) whose boxes overlap now.
  void start_rows();
  void row_candidates(std::uint32_t i, std::uint32_t after);
  bool row_next(Pair& out);
  void row_pushed_out(const Components& k);
  bool row_refresh(const Components& k, std::uint32_t i);
  // find().
  void fat_rebuild(const Components& k, std::span<const EntityId> entities, double h, Workers& w);
  FloatBox fat_box(const Bounds& swept, Vector v, double h) const;
  bool regrow(const Components& k, double h);
  // Past one body in this many given new fat boxes since the grid was built,
  // it is built again (regrow()).
  static constexpr std::size_t regrow_share = 16;
  std::vector<std::uint32_t> moving_;  // regrow(): the bodies that left their fat boxes
  bool same_bodies(std::span<const EntityId> entities, Workers& w) const;  // the grid's, fat_built_
  void clear_unheld(const Workers& w);
  // renew()'s lists of a range: the bodies whose box left its last one (up
  // to `few`), those that left their fat box (up to `few_escaped`).
  struct RenewLists {
    std::vector<std::uint32_t>* unheld = nullptr;
    std::vector<std::uint32_t>* escaped = nullptr;
    std::size_t few = 0, few_escaped = 0;
  };
  RenewLists lists(int t, std::size_t few, std::size_t few_escaped) {
    const auto at = static_cast<std::size_t>(t);
    return {&unheld_[at], &escaped_[at], few, few_escaped};
  }
  template <class Index>
  std::uint8_t renew(const Components& k, std::size_t count, Index index, double h, double reach, RenewLists lists);
  void finish(const Components& k, std::span<const EntityId> entities, double h, double reach, std::vector<Pair>& out,
              PairRule rule, Workers& w, std::uint8_t flags, bool known);
  void pairs_of_candidates(std::span<const EntityId> entities, std::vector<Pair>& out, Workers& w);
  void pairs_near_last(std::vector<Pair>& out, Workers& w);
  // Past one body in this many of a range whose box left its last one, the
  // candidates are tested instead (a grid query costs tens of candidate tests).
  static constexpr std::size_t unheld_share = 32;

  UniformGrid grid_;
  std::vector<EntityId> entities_;   // the bodies of find()'s fat grid, in registration order
  std::vector<std::uint32_t> index_of_;  // by entity id: its rank in entities_
  std::vector<std::uint8_t> fixed_;  // infinite mass, by registration rank
  std::vector<FloatBox> boxes_;          // the grid's boxes, by registration rank
  bool fat_built_ = false;           // the grid holds find()'s fat boxes

  // Course pass state.
  std::span<const EntityId> course_entities_;  // the Collision system's bodies, during its pass
  bool course_rules_ = false;  // some body has contact rules: test each pair
  double course_h_ = 0.0;
  std::vector<PairKey> found_late_;  // min-heap: pairs found after a body left its box
  std::size_t next_ = 0, moved_ = 0, rows_after_ = 0;
  PairKey last_ = ~PairKey{0};
  bool started_ = false;
  Stats stats_;
  // Row by row (stats_.by_rows): a grid of the boxes as they are now, the
  // loop's current row and its candidates, sorted.
  UniformGrid row_grid_;
  std::size_t row_moves_ = 0;  // moves since row_grid_ was indexed
  std::uint32_t row_ = 0;
  std::vector<std::uint32_t> row_pairs_;
  std::size_t row_next_ = 0;

  // find() state.
  std::vector<Bounds> current_;  // this call's exact boxes
  double last_h_ = 0.0, last_reach_ = 0.0;  // this call's h and reach
  std::uint64_t finds_ = 0;      // calls of find()
  std::uint64_t builds_ = 0;     // fat_rebuild()s
  std::vector<Bounds> scan_;     // find_selected()'s swept boxes
  std::vector<std::vector<Pair>> range_pairs_;  // find() with threads: each range's pairs, joined in order
  std::vector<Pair>& range_list(int t, const Workers& w) { return part_of(range_pairs_, t, w.threads()); }
  // The last call's pairs: a resting pile's bodies sweep the same boxes
  // call after call, and testing the grid's candidates again would list the
  // same pairs (the pyramids: 7 % of a step); bodies that move within their
  // last boxes keep a subset of them (pairs_near_last()).
  std::vector<Pair> last_found_;
  bool found_valid_ = false;  // (never with contact rules: they read more than the boxes)
  std::vector<std::vector<std::uint32_t>> unheld_;  // by thread: its range's bodies whose box left its last one
  std::vector<std::vector<std::uint32_t>> escaped_;  // by thread: its range's bodies whose box left its fat box
  std::vector<PairKey> late_;                        // pairs_near_last(): the unheld bodies' pairs
  std::vector<Pair> merged_;                         // pairs_near_last(): scratch
};

// The course pass's pairs as a range: `for (const Pair p : pairs)`. Moving on
// to the next pair first checks whether the last one's correction pushed a
// body out of its box.
class BroadPhase::CoursePairs {
 public:
  struct End {};
  class Iterator {
   public:
    Pair operator*() const { return pair_; }
    // Always inlined into the pass's loop, with course_next (they run once
    // per candidate pair; GCC's heuristics stopped inlining them once the
    // rules' test was added: +2.5 % of a gas 10 000 step).
    [[gnu::always_inline]] Iterator& operator++() {
      done_ = !bp_->course_next(*k_, pair_);
      // Contact rules: tested out of line, so that the pass without any
      // (every scene of the sheet) keeps its inlined loop.
      if (bp_->course_rules_) [[unlikely]]
        done_ = !bp_->course_skip_unsolvable(*k_, pair_, done_);
      return *this;
    }
    bool operator!=(End) const { return !done_; }

   private:
    friend class CoursePairs;
    Iterator(BroadPhase* bp, const Components* k) : bp_(bp), k_(k) { ++*this; }
    BroadPhase* bp_;
    const Components* k_;
    Pair pair_{};
    bool done_ = false;
  };
  Iterator begin() const { return Iterator(bp_, k_); }
  End end() const { return {}; }

 private:
  friend class BroadPhase;
  CoursePairs(BroadPhase* bp, const Components* k) : bp_(bp), k_(k) {}
  BroadPhase* bp_;
  const Components* k_;
};

[[gnu::always_inline]] inline bool BroadPhase::course_next(const Components& k, Pair& out) {
  if (started_ && !(inside(k, pair_first(last_)) && inside(k, pair_second(last_)))) pushed_out(k);
  // The next listed pair, unless a pair found late comes first (or the list
  // is done, or the pair was found late already).
  const std::vector<PairKey>& listed = grid_.pairs();
  if (next_ >= listed.size() || (!found_late_.empty() && found_late_.front() < listed[next_]) ||
      listed[next_] == last_)
    return course_next_slow(out);
  // The pair a few ahead, asked for now: bodies are numbered as registered,
  // not in space, so in a mixed gas each pair's second body is a miss (its
  // mass, position, box), and they overlap only when asked for early.
  if (next_ + pair_ahead < listed.size()) {
    prefetch_body(k, pair_first(listed[next_ + pair_ahead]));
    prefetch_body(k, pair_second(listed[next_ + pair_ahead]));
  }
  last_ = listed[next_++];
  started_ = true;
  out = {course_entities_[pair_first(last_)], course_entities_[pair_second(last_)]};
  return true;
}

// One-off versions (a fresh BroadPhase each call) and the all-pairs
// definition, for the tests.
void candidate_pairs(const Components& k, std::span<const EntityId> entities, double h, double reach,
                     std::vector<Pair>& out);
void brute_force_pairs(const Components& k, std::span<const EntityId> entities, double h, double reach,
                       std::vector<Pair>& out);

}  // namespace physics
