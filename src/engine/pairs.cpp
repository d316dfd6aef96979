#include "engine/pairs.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "engine/same_bits.hpp"

namespace physics {

namespace {
using Bounds = BroadPhase::Bounds;

// The box swept over [0, h] at constant velocity, grown by `reach`.
// Inlined: called, it returned the box through the stack, which the caller
// read back in 16-byte loads from its 8-byte stores (a store-forwarding
// stall, a fifth of find()'s time on the pyramid, perf annotate).
[[gnu::always_inline]] inline Bounds swept(const Components& k, EntityId e, double h, double reach) {
  const Vector p = k.position[e];
  const Vector q = p + h * k.velocity[e];
  const double w = k.box[e].width, hh = k.box[e].height;
  return {std::min(p.x, q.x) - reach, std::min(p.y, q.y) - reach, std::max(p.x, q.x) + w + reach,
          std::max(p.y, q.y) + hh + reach};
}

// Closed test: touching boxes are candidates (resting contact). A NaN bound
// fails it, so a lost body has no pair.
bool touch(const Bounds& a, const Bounds& b) { return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1; }

// Nonzero when two boxes differ in any bit (renew_swept without SSE2).
[[maybe_unused]] std::uint64_t bounds_differ(const Bounds& a, const Bounds& b) {
  return bits_differ(a.x0, b.x0) | bits_differ(a.y0, b.y0) | bits_differ(a.x1, b.x1) | bits_differ(a.y1, b.y1);
}

// Whether `inner` lies within `outer` (closed; a NaN bound fails it; the
// SSE2 versions below test it two coordinates at once).
[[maybe_unused]] bool within(const Bounds& inner, const Bounds& outer) {
  return outer.x0 <= inner.x0 && outer.y0 <= inner.y0 && inner.x1 <= outer.x1 && inner.y1 <= outer.y1;
}

// swept()'s box written to `to`: bit 1 (`changed`) set when it differs
// (bits) from the box `to` held; if so, bit 2 (`left`) when it does not lie
// within that box, and bit 4 (`escaped`) when it does not lie within `grid`
// (which held the box `to` held). With SSE2 each half, (x0, y0) and (x1,
// y1), is computed in one register's lanes by swept()'s operations in its
// order (min_pd(q, p) is std::min(p, q), max_pd(q, p) std::max(p, q), NaN
// included) and stored whole: the compiler built the box in 8-byte halves on
// the stack and copied it in 16-byte loads, a failed store forwarding each
// (four fifths of find()'s time on the resting friction pyramid, perf
// annotate). A NaN bound fails both tests.
constexpr unsigned changed = 1, left = 2, escaped = 4;
[[gnu::always_inline]] inline unsigned renew_swept(const Components& k, EntityId e, double h, double reach, Bounds& to,
                                                   const FloatBox& grid) {
#if defined(__SSE2__)
  static_assert(sizeof(Bounds) == 4 * sizeof(double) && offsetof(Vector, y) == sizeof(double) &&
                offsetof(Rect, height) == offsetof(Rect, width) + sizeof(int) && sizeof(FloatBox) == 4 * sizeof(float));
  const __m128d p = _mm_loadu_pd(&k.position[e].x);
  const __m128d q = _mm_add_pd(p, _mm_mul_pd(_mm_set1_pd(h), _mm_loadu_pd(&k.velocity[e].x)));
  const __m128d r = _mm_set1_pd(reach);
  const __m128d size = _mm_cvtepi32_pd(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(&k.box[e].width)));  // exact
  const __m128d lo = _mm_sub_pd(_mm_min_pd(q, p), r);
  const __m128d hi = _mm_add_pd(_mm_add_pd(_mm_max_pd(q, p), size), r);
  const __m128d was_lo = _mm_loadu_pd(&to.x0), was_hi = _mm_loadu_pd(&to.x1);
  _mm_storeu_pd(&to.x0, lo), _mm_storeu_pd(&to.x1, hi);
  const __m128i same = _mm_and_si128(_mm_cmpeq_epi32(_mm_castpd_si128(was_lo), _mm_castpd_si128(lo)),
                                     _mm_cmpeq_epi32(_mm_castpd_si128(was_hi), _mm_castpd_si128(hi)));
  if (_mm_movemask_epi8(same) == 0xFFFF) return 0;  // (a resting pile's bodies: asked no more)
  const __m128d inside = _mm_and_pd(_mm_cmple_pd(was_lo, lo), _mm_cmple_pd(hi, was_hi));
  const __m128 g = _mm_loadu_ps(&grid.min_x);  // floats to doubles: exact
  const __m128d in_grid =
      _mm_and_pd(_mm_cmple_pd(_mm_cvtps_pd(g), lo), _mm_cmple_pd(hi, _mm_cvtps_pd(_mm_movehl_ps(g, g))));
  return changed | (_mm_movemask_pd(inside) == 3 ? 0 : left) | (_mm_movemask_pd(in_grid) == 3 ? 0 : escaped);
#else
  const Bounds s = swept(k, e, h, reach);
  const bool in_grid = grid.min_x <= s.x0 && grid.min_y <= s.y0 && s.x1 <= grid.max_x && s.y1 <= grid.max_y;
  // (`left` is asked only where the last pairs are kept: not in the browser's build.)
  const unsigned flags =
      bounds_differ(s, to) ? changed | (!keeps_unchanged || within(s, to) ? 0 : left) | (in_grid ? 0 : escaped) : 0;
  to = s;
  return flags;
#endif
}

// Whether body e's box where it is now lies within `b`: within(swept(k, e,
// 0, 0), b), with SSE2 each corner's two coordinates at once (a resting
// pile's every substep asks it of every body).
[[gnu::always_inline]] inline bool lies_within(const Components& k, EntityId e, const Bounds& b) {
#if defined(__SSE2__)
  const __m128d lo = _mm_loadu_pd(&k.position[e].x);
  const __m128d size = _mm_cvtepi32_pd(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(&k.box[e].width)));  // exact
  const __m128d in = _mm_and_pd(_mm_cmple_pd(_mm_loadu_pd(&b.x0), lo),
                                _mm_cmple_pd(_mm_add_pd(lo, size), _mm_loadu_pd(&b.x1)));
  return _mm_movemask_pd(in) == 3;
#else
  return within(swept(k, e, 0.0, 0.0), b);
#endif
}
}  // namespace

// ---- the course pass ----

BroadPhase::CoursePairs BroadPhase::course_pairs(const Components& k, std::span<const EntityId> entities,
                                                 double h) {
  course_entities_ = entities;
  course_rules_ = k.any_rules();
  course_h_ = h;
  stats_ = {};
  found_late_.clear();
  course_build(k);
  stats_.candidates = grid_.pairs().size();
  // Past this many bodies out of their boxes (a crowded or overlapping
  // start), looking up each body's pairs when the loop reaches it costs less
  // than queuing every pair a move may form.
  rows_after_ = std::max<std::size_t>(256, entities.size() / 4);
  next_ = moved_ = 0;
  last_ = ~PairKey{0};  // never a pair: i < j < 2^32 - 1
  started_ = false;
  return CoursePairs(this, &k);
}

void BroadPhase::course_build(const Components& k) {
  const std::size_t n = course_entities_.size();
  boxes_.resize(n);
  fixed_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const EntityId e = course_entities_[i];
    boxes_[i] = FloatBox::around(k.position[e], k.box[e], course_margin);
    fixed_[i] = !std::isfinite(k.mass[e]);  // the same test as "two walls never collide"
  }
  grid_.build(boxes_, fixed_);
  fat_built_ = false;
}

bool BroadPhase::rebox(const Components& k, std::uint32_t i) {
  if (inside(k, i)) return false;
  const EntityId e = course_entities_[i];
  boxes_[i] = FloatBox::around(k.position[e], k.box[e], course_margin);
  ++stats_.requeries;
  return true;
}

bool BroadPhase::refresh(const Components& k, std::uint32_t i, PairKey current) {
  // Pushed out of its box: the pairs found when the pass began may no longer
  // hold all of its contacts. Give it a new box and queue the pairs it may
  // now form that the pass has not reached yet (the earlier ones are behind
  // us in the sheet's loop too).
  if (!rebox(k, i)) return false;
  const FloatBox box = boxes_[i];
  grid_.move(i, box);
  grid_.query(box, [&](std::uint32_t j) {
    if (j == i || (fixed_[i] && fixed_[j])) return;
    const PairKey key = pair_key(i, j);
    if (key <= current) return;
    found_late_.push_back(key);
    std::push_heap(found_late_.begin(), found_late_.end(), std::greater<>());
  });
  return true;
}

void BroadPhase::pushed_out(const Components& k) {
  // The pair handed out last was corrected: bodies it pushed out of their
  // boxes get their new pairs.
  if (stats_.by_rows) return row_pushed_out(k);
  moved_ += refresh(k, pair_first(last_), last_) + refresh(k, pair_second(last_), last_);
  if (moved_ > rows_after_) start_rows();
}

// ---- the course pass, row by row ----
//
// Many bodies pushed out (blocks placed on top of each other: each
// correction pushes the next block out, and every block in the pile is
// queued again) would fill found_late_ with copies of pairs listed ahead. On
// from here, the loop's row i takes its pairs (i, j > i) from a grid of the
// boxes as they are when it begins; only moves of i itself during its row
// look its pairs up again. A move of j changes no pair of row i but (i, j),
// which is done, so it only updates the grid for the rows ahead. Same pairs,
// same order: every pair that overlaps when the loop reaches it is listed.

void BroadPhase::start_rows() {
  stats_.by_rows = true;
  row_grid_.index(boxes_);
  row_moves_ = 0;
  found_late_.clear();
  next_ = std::numeric_limits<std::size_t>::max();  // the listed pairs are done with: course_next takes the slow path
  row_ = pair_first(last_);
  row_candidates(row_, pair_second(last_));
}

void BroadPhase::row_candidates(std::uint32_t i, std::uint32_t after) {
  row_pairs_.clear();
  row_next_ = 0;
  const FloatBox box = boxes_[i];
  // The grid may report a body for a box it has left, or twice: the test on
  // its box now and the sort keep each body that overlaps once.
  row_grid_.query(box, [&](std::uint32_t j) {
    if (j > after && !(fixed_[i] && fixed_[j]) && overlap(boxes_[j], box)) row_pairs_.push_back(j);
  });
  std::sort(row_pairs_.begin(), row_pairs_.end());
  row_pairs_.erase(std::unique(row_pairs_.begin(), row_pairs_.end()), row_pairs_.end());
}

bool BroadPhase::row_next(Pair& out) {
  while (row_next_ == row_pairs_.size()) {
    if (++row_ >= course_entities_.size()) return false;
    row_candidates(row_, row_);
  }
  last_ = pair_key(row_, row_pairs_[row_next_++]);
  out = {course_entities_[row_], course_entities_[pair_second(last_)]};
  return true;
}

bool BroadPhase::row_refresh(const Components& k, std::uint32_t i) {
  if (!rebox(k, i)) return false;
  // Old boxes stay in the grid's cells; index afresh before they outnumber the bodies.
  if (++row_moves_ > boxes_.size() + 1024) {
    row_grid_.index(boxes_);
    row_moves_ = 0;
  } else {
    row_grid_.move(i, boxes_[i]);
  }
  return true;
}

void BroadPhase::row_pushed_out(const Components& k) {
  const std::uint32_t i = pair_first(last_), j = pair_second(last_);
  row_refresh(k, j);
  // i moved: the rest of its row, looked up again from its new box.
  if (row_refresh(k, i)) row_candidates(i, j);
}

bool BroadPhase::course_next_slow(Pair& out) {
  if (stats_.by_rows) return row_next(out);
  for (;;) {
    const std::vector<PairKey>& listed = grid_.pairs();
    const bool in_list = next_ < listed.size();
    if (!in_list && found_late_.empty()) return false;
    PairKey key;
    if (!found_late_.empty() && (!in_list || found_late_.front() < listed[next_])) {
      std::pop_heap(found_late_.begin(), found_late_.end(), std::greater<>());
      key = found_late_.back();
      found_late_.pop_back();
    } else {
      key = listed[next_++];
    }
    if (key == last_) continue;  // found both when the pass began and later
    last_ = key;
    started_ = true;
    out = {course_entities_[pair_first(key)], course_entities_[pair_second(key)]};
    return true;
  }
}

bool BroadPhase::course_skip_unsolvable(const Components& k, Pair& out, bool done) {
  while (!done && !solvable(k, out.c, out.b, course_h_)) done = !course_next(k, out);
  return !done;
}

// ---- find() ----

void BroadPhase::find(const Components& k, std::span<const EntityId> entities, double h, double reach,
                      std::vector<Pair>& out, PairRule rule, Workers* workers) {
  Workers& w = workers_or_one(workers);
  const std::size_t n = entities.size();
  ++finds_;
  current_.resize(n);
  const bool same = same_bodies(entities, w);
  // The last call's pairs (last_found_) are this one's when it has the same
  // bodies and finds each one's swept box as it was (current_ holds the last
  // call's): the grid is then kept, its candidates are the same, and the
  // pairs are those of the candidates' boxes that touch (h and reach only
  // set the boxes). When a few bodies' boxes left their last ones (unheld_),
  // the pairs are near the last call's: pairs_near_last().
  const bool known = keeps_unchanged && found_valid_ && same && !k.any_rules();
  if (known) clear_unheld(w);
  const std::uint8_t flags = w.or_over_ranges(n, min_parallel_items, [&](int t, std::size_t begin, std::size_t end) {
    if (!same) {  // a new list: a rebuild
      for (std::size_t i = begin; i < end; ++i) current_[i] = swept(k, entities[i], h, reach);
      return std::uint8_t{1 | 2 | 4};
    }
    const auto index = [&](std::size_t j) { return static_cast<std::uint32_t>(begin + j); };
    const std::size_t count = end - begin;
    return renew(k, count, index, h, reach, known ? lists(t, count / unheld_share, count / regrow_share) : RenewLists{});
  });
  finish(k, entities, h, reach, out, rule, w, flags, known);
}

void BroadPhase::find_again(const Components& k, std::span<const EntityId> entities,
                            std::span<const EntityId> changed, double h, double reach, std::vector<Pair>& out,
                            PairRule rule, Workers* workers) {
  const auto listed = [&](EntityId e) {
    return e < index_of_.size() && index_of_[e] < entities_.size() && entities_[index_of_[e]] == e;
  };
  Workers& w = workers_or_one(workers);
  const bool known = keeps_unchanged && found_valid_ && !k.any_rules() && h == last_h_ && reach == last_reach_ &&
                     same_bodies(entities, w) && std::all_of(changed.begin(), changed.end(), listed);
  if (!known) return find(k, entities, h, reach, out, rule, workers);
  ++finds_;
  clear_unheld(w);
  const std::size_t share = entities.size() / static_cast<std::size_t>(w.threads());
  const auto flags = w.or_over_ranges(changed.size(), min_parallel_items, [&](int t, std::size_t begin, std::size_t end) {
    const auto index = [&](std::size_t j) { return index_of_[changed[begin + j]]; };
    return renew(k, end - begin, index, h, reach, lists(t, share / unheld_share, share / regrow_share));
  });
  finish(k, entities, h, reach, out, rule, w, flags, true);
}

// Two empty lists per thread (a list of a range that is not split this time
// would otherwise hold the last call's).
void BroadPhase::clear_unheld(const Workers& w) {
  unheld_.resize(static_cast<std::size_t>(w.threads()));
  escaped_.resize(static_cast<std::size_t>(w.threads()));
  for (std::vector<std::uint32_t>& part : unheld_) part.clear();
  for (std::vector<std::uint32_t>& part : escaped_) part.clear();
}

// (Compared by ranges on a team: at every find, 400 KB at 100 000 bodies.)
bool BroadPhase::same_bodies(std::span<const EntityId> entities, Workers& w) const {
  if (!fat_built_ || entities.size() != entities_.size()) return false;
  return w.or_over_ranges(entities.size(), min_parallel_items, [&](int, std::size_t begin, std::size_t end) {
    return static_cast<std::uint8_t>(!std::equal(entities.begin() + static_cast<std::ptrdiff_t>(begin),
                                                 entities.begin() + static_cast<std::ptrdiff_t>(end),
                                                 entities_.begin() + static_cast<std::ptrdiff_t>(begin)));
  }) == 0;
}

// Each listed body's swept box made again (body index(j) for j < count, of
// entities_, the grid's bodies). Returns bit 1 when a body left its box in
// the grid (then the grid finds not every pair of boxes: regrow() or a
// rebuild) or its mass's finiteness changed, bit 8 too then (a rebuild);
// bit 2 when a box changed; bit 4 when more than `lists.few` left their last
// box, bit 16 when more than `lists.few_escaped` left their box in the grid.
// Those are appended to *lists.unheld (the last boxes are the last call's
// pairs'), these to *lists.escaped; a list not given, its bit is set.
template <class Index>
std::uint8_t BroadPhase::renew(const Components& k, std::size_t count, Index index, double h, double reach,
                               RenewLists lists) {
  // Some body left its fat box (and all were listed); some body's mass
  // turned finite or infinite (looked at until one is: the grid lists no
  // pair of two infinite masses).
  bool out = false, listed = keeps_unchanged && lists.escaped, refixed = false;
  const auto look = [&](std::uint32_t i, unsigned f) {
    if (f & escaped) [[unlikely]] {
      out = true;
      listed = listed && lists.escaped->size() < lists.few_escaped;
      if (listed) lists.escaped->push_back(i);
    }
    if (!refixed) refixed = fixed_[i] != !std::isfinite(k.mass[entities_[i]]);
  };
  std::vector<std::uint32_t>* const unheld = lists.unheld;
  const std::size_t few = lists.few;
  bool counting = keeps_unchanged && unheld, moved = false;
  std::size_t j = 0;
  for (; counting && j < count; ++j) {
    const std::uint32_t i = index(j);
    const unsigned f = renew_swept(k, entities_[i], h, reach, current_[i], boxes_[i]);
    moved = moved || f;
    if (f & left) [[unlikely]] {
      counting = unheld->size() < few;
      if (counting) unheld->push_back(i);
    }
    look(i, f);
  }
  if (j < count) moved = true;  // (not known, or a body left its last box: its box changed)
  for (; j < count; ++j) {
    const std::uint32_t i = index(j);
    const unsigned f = renew_swept(k, entities_[i], h, reach, current_[i], boxes_[i]);
    look(i, f);
  }
  return static_cast<std::uint8_t>((out || refixed ? 1 : 0) | (moved ? 2 : 0) | (counting ? 0 : 4) | (refixed ? 8 : 0) |
                                   (out && !listed ? 16 : 0));
}

// find()'s pairs once renew() has made the boxes and said what changed.
void BroadPhase::finish(const Components& k, std::span<const EntityId> entities, double h, double reach,
                        std::vector<Pair>& out, PairRule rule, Workers& w, std::uint8_t flags, bool known) {
  last_h_ = h, last_reach_ = reach;
  // (The browser's build, short of room, builds the grid again.)
  if ((flags & 1) && keeps_unchanged && known && !(flags & (8 | 16)) && regrow(k, h))
    flags &= ~1;  // every body in its fat box again
  if (flags & 1) fat_rebuild(k, entities, h, w);
  if (known && flags == 0) {
    out.assign(last_found_.begin(), last_found_.end());
    return;
  }
  if (keeps_unchanged && known && flags == 2) {
    pairs_near_last(out, w);
  } else {
    pairs_of_candidates(entities, out, w);
    if (k.any_rules()) std::erase_if(out, [&](Pair p) { return !keeps(rule, k, p.c, p.b, h); });
  }
  // Kept for the next call (a copy: the callers change theirs).
  found_valid_ = keeps_unchanged && !k.any_rules();
  if (found_valid_) last_found_.assign(out.begin(), out.end());
}

// The grid's candidates whose boxes touch, each range's in order, then
// joined in range order.
void BroadPhase::pairs_of_candidates(std::span<const EntityId> entities, std::vector<Pair>& out, Workers& w) {
  const std::vector<PairKey>& candidates = grid_.pairs();
  out.clear();
  out.reserve(candidates.size());
  w.append_over_ranges(candidates.size(), min_parallel_items, out, [&](int t) -> auto& { return range_list(t, w); },
                       [&](int, std::size_t begin, std::size_t end, std::vector<Pair>& part) {
                         for (std::size_t c = begin; c < end; ++c) {
                           const std::uint32_t i = pair_first(candidates[c]), j = pair_second(candidates[c]);
                           if (touch(current_[i], current_[j])) part.push_back({entities[i], entities[j]});
                         }
                       });
}

// The pairs when every body's box lies in its fat box and in the box the
// last call found for it, but for the few of unheld_: a pair of two held
// bodies that touches now touched then, so it is among the last call's
// pairs; the unheld bodies' pairs are looked up in the grid, whose boxes
// hold every body's box now. The same pairs in the same order as the
// candidates' test (the tests check it against brute force), without
// testing every candidate: the second and third finds of a falling rain's
// step (the solver's turned velocities, the position stage), whose bodies
// mostly move within their last boxes.
void BroadPhase::pairs_near_last(std::vector<Pair>& out, Workers& w) {
  out.clear();
  w.append_over_ranges(last_found_.size(), min_parallel_items, out,
                       [&](int t) -> auto& { return range_list(t, w); },
                       [&](int, std::size_t begin, std::size_t end, std::vector<Pair>& part) {
                         for (std::size_t k = begin; k < end; ++k) {
                           const Pair p = last_found_[k];
                           if (touch(current_[index_of_[p.c]], current_[index_of_[p.b]])) part.push_back(p);
                         }
                       });
  late_.clear();
  for (const std::vector<std::uint32_t>& part : unheld_) {
    for (const std::uint32_t i : part) {
      const Bounds& a = current_[i];
      const FloatBox box = FloatBox::outward(a.x0, a.y0, a.x1, a.y1);
      if (!box.valid()) continue;  // (a NaN bound touches nothing)
      grid_.query(box, [&](std::uint32_t j) {
        if (j != i && !(fixed_[i] && fixed_[j]) && touch(a, current_[j])) late_.push_back(pair_key(i, j));
      });
    }
  }
  if (late_.empty()) return;
  std::sort(late_.begin(), late_.end());
  late_.erase(std::unique(late_.begin(), late_.end()), late_.end());
  // Merged by key: the pairs found late may be among the kept ones.
  merged_.clear();
  std::size_t a = 0;
  const auto key_of = [&](Pair p) { return pair_key(index_of_[p.c], index_of_[p.b]); };
  for (const PairKey key : late_) {
    while (a < out.size() && key_of(out[a]) < key) merged_.push_back(out[a++]);
    if (a < out.size() && key_of(out[a]) == key) ++a;
    merged_.push_back({entities_[pair_first(key)], entities_[pair_second(key)]});
  }
  merged_.insert(merged_.end(), out.begin() + static_cast<std::ptrdiff_t>(a), out.end());
  out.swap(merged_);
}

bool BroadPhase::holds(const Components& k, std::span<const EntityId> entities, Workers* workers) const {
  if (k.any_rules() || !fat_built_ || !std::equal(entities.begin(), entities.end(), entities_.begin(), entities_.end()))
    return false;
  const auto left = [&](int, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      if (!lies_within(k, entities[i], current_[i])) return std::uint8_t{1};
    return std::uint8_t{0};
  };
  return workers_or_one(workers).or_over_ranges(entities.size(), min_parallel_items, left) == 0;
}

void BroadPhase::find_selected(const Components& k, std::span<const EntityId> entities,
                               std::span<const std::uint8_t> selected, double h, std::vector<Pair>& out) {
  constexpr std::size_t few = 16;  // ~ the grid's cost per body over a box test's
  std::size_t count = 0;
  for (const EntityId e : entities) count += selected[e];
  if (count > few) {
    find(k, entities, h, 0.0, out);
    std::erase_if(out, [&](Pair p) { return !selected[p.c] && !selected[p.b]; });
    return;
  }
  out.clear();
  scan_.resize(entities.size());
  for (std::size_t i = 0; i < entities.size(); ++i) scan_[i] = swept(k, entities[i], h, 0.0);
  const bool rules = k.any_rules();
  for (std::size_t i = 0; i < entities.size(); ++i) {
    if (!selected[entities[i]]) continue;
    const Bounds& a = scan_[i];
    for (std::size_t j = 0; j < entities.size(); ++j) {
      const EntityId c = entities[std::min(i, j)], b = entities[std::max(i, j)];
      if (j == i || (selected[entities[j]] && j < i)) continue;  // a pair of two selected bodies once
      if (!std::isfinite(k.mass[c]) && !std::isfinite(k.mass[b])) continue;
      if (touch(a, scan_[j]) && (!rules || solvable(k, c, b, h))) out.push_back({c, b});
    }
  }
}

void BroadPhase::fat_rebuild(const Components& k, std::span<const EntityId> entities, double h, Workers& w) {
  const std::size_t n = entities.size();
  ++builds_;
  boxes_.resize(n);
  fixed_.resize(n);
  w.for_ranges(n, min_parallel_items, [&](int, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      boxes_[i] = fat_box(current_[i], k.velocity[entities[i]], h);
      fixed_[i] = !std::isfinite(k.mass[entities[i]]);
    }
  });
  grid_.build(boxes_, fixed_, &w);
  entities_.assign(entities.begin(), entities.end());
  if (keeps_unchanged) {  // (pairs_near_last() and find_again(), not in the browser's build)
    index_of_.resize(k.size());
    for (std::size_t i = 0; i < n; ++i) index_of_[entities[i]] = static_cast<std::uint32_t>(i);
  }
  fat_built_ = true;
}

// A body's fat box: its swept box grown by fat_margin, and ahead along its
// velocity by fat_steps calls of h ms, only ahead: a falling body stays in
// its box for a few calls instead of leaving it at every one, and the box
// does not grow behind it (where it only adds candidate pairs). Rounded
// outwards to float: the grid's boxes contain the exact ones, so it finds a
// superset of the pairs, which the exact test trims.
FloatBox BroadPhase::fat_box(const Bounds& c, Vector v, double h) const {
  const Vector d = (fat_steps * h) * v;
  return FloatBox::outward(c.x0 - fat_margin + std::min(d.x, 0.0), c.y0 - fat_margin + std::min(d.y, 0.0),
                           c.x1 + fat_margin + std::max(d.x, 0.0), c.y1 + fat_margin + std::max(d.y, 0.0));
}

// When but a few bodies left their fat boxes (renew() listed them all in
// escaped_ and said none's mass turned finite or infinite), only those
// take new fat boxes in the grid (UniformGrid::update)
// instead of a build of every body's: a landing rain of 100 000 has some
// hundred bodies bounce out of their boxes at nearly every step, where a
// build took 3.7 ms. The same pairs either way: the grid's candidates are
// a superset of the fat boxes' overlapping pairs, and the pairs are those
// of the exact boxes. False where a build is due (the grid untouched; it
// makes every fat box again): a box with a NaN bound (a build keeps it out
// of the grid), or more than one body in regrow_share moved since the last
// build (the moved boxes slow the grid's queries, and their old pairs stay
// among its candidates).
bool BroadPhase::regrow(const Components& k, double h) {
  moving_.clear();
  for (const std::vector<std::uint32_t>& part : escaped_) moving_.insert(moving_.end(), part.begin(), part.end());
  if (grid_.updated() + moving_.size() > entities_.size() / regrow_share) return false;
  for (const std::uint32_t i : moving_)
    if (!(boxes_[i] = fat_box(current_[i], k.velocity[entities_[i]], h)).valid()) return false;
  grid_.update(moving_, boxes_);
  return true;
}

void candidate_pairs(const Components& k, std::span<const EntityId> entities, double h, double reach,
                     std::vector<Pair>& out) {
  BroadPhase().find(k, entities, h, reach, out);
}

void brute_force_pairs(const Components& k, std::span<const EntityId> entities, double h, double reach,
                       std::vector<Pair>& out) {
  out.clear();
  const std::size_t n = entities.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Bounds bi = swept(k, entities[i], h, reach);
    for (std::size_t j = i + 1; j < n; ++j) {
      if (!std::isfinite(k.mass[entities[i]]) && !std::isfinite(k.mass[entities[j]])) continue;
      if (!solvable(k, entities[i], entities[j], h)) continue;
      const Bounds bj = swept(k, entities[j], h, reach);
      if (touch(bi, bj)) out.push_back({entities[i], entities[j]});
    }
  }
}

}  // namespace physics
