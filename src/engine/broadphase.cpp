#include "engine/broadphase.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace physics {

namespace {

constexpr float float_max = std::numeric_limits<float>::max();
constexpr float float_inf = std::numeric_limits<float>::infinity();

// The largest float <= x (NaN stays NaN). Out-of-range values saturate
// instead of being converted, which would be undefined behaviour.
float float_down(double x) {
  if (!(x >= -static_cast<double>(float_max) && x <= static_cast<double>(float_max))) {
    if (x != x) return std::numeric_limits<float>::quiet_NaN();
    return x < 0 ? -float_inf : float_max;
  }
  const float f = static_cast<float>(x);  // the nearest float, maybe above x
  // One float down, by its bits, without a branch: whether f is above x is
  // a coin toss for moving bodies, and a mispredicted branch per bound cost
  // more than the whole rest of the box. 0 is taken as -0, whose next float
  // down is -denorm_min; below 0 the bits grow, above they shrink.
  std::uint32_t bits = std::bit_cast<std::uint32_t>(f);
  bits = f == 0.0f ? 0x80000000u : bits;
  const std::uint32_t down = (bits >> 31) ? 1u : ~0u;
  const std::uint32_t above = static_cast<double>(f) > x;
  return std::bit_cast<float>(bits + (down & (0u - above)));
}

// The smallest float >= x.
float float_up(double x) { return -float_down(-x); }

// x's bits as an unsigned integer in x's order (-0 as +0; not for a NaN):
// sorting these sorts the floats.
std::uint32_t ordered_bits(float x) {
  const auto bits = std::bit_cast<std::uint32_t>(x + 0.0f);
  return bits >> 31 ? ~bits : bits | 0x80000000u;
}

// Boxes whose larger side exceeds this many times the mean one are kept out
// of the grid (walls): otherwise one 1000-block-long wall would make every
// cell 1000 blocks wide.
constexpr double large_factor = 4.0;

// Cells per small body when the bodies are spread out; the cell never gets
// smaller than the largest small box. Measured on the bench scenes: 2 was
// faster than 1 (fewer boxes per cell to test) and than 4 (more empty cells
// to walk and a bigger table to clear).
constexpr double cells_per_body = 2.0;

// Whether sort_pairs() may sort by counting. Not in the browser's build
// (WebAssembly under WASI), which stays within its size budget without that
// code (docs/web.md): a comparison sort gives the same order, and its worlds
// are small.
#if defined(__wasi__)
constexpr bool sorts_by_counting = false;
#else
constexpr bool sorts_by_counting = true;
#endif

constexpr std::uint32_t no_bucket = std::numeric_limits<std::uint32_t>::max();

// A stable counting sort of the items [0, n): to.key(i) is item i's bucket
// (< buckets), to.put(i, key, slot) writes it to its slot. On return start[b] is
// where bucket b's items begin, start[buckets] how many there are. Items of
// a bucket keep their order: each is placed from the last backwards.
//
// On a team each range counts its items in a table of its own (the first
// range's is start, the others' more_tables(t)), one pass over the buckets
// turns the counts into where each range's part of each bucket ends, then
// every range places its items: the slots of one pass in order.
//
// Target::scattered(): some items have no bucket (key no_bucket: left out),
// and the others are in no order of their buckets (bodies numbered as
// registered, not in space: a million gas bodies' counters are 8 MB, their
// entries 24 MB), each count and slot a miss to the last-level cache or
// beyond. The loops then ask for them `ahead` items early (the slot in two
// steps: its counter, then the slot the counter points at, to.ahead), so
// the misses overlap instead of stalling one by one. (Not for the pairs,
// whose counters fit in the second-level cache: there the asking cost 60 %
// more instructions than it saved.)
template <class More, class Target>
void counting_sort(Workers& w, std::size_t n, std::size_t buckets, std::vector<std::uint32_t>& start,
                   More&& more_tables, Target to) {
  constexpr std::size_t ahead = 16;
  constexpr bool scattered = Target::scattered();
  // (Each key read once into a local: the counters' stores may alias it.)
  const auto count = [&](std::uint32_t* counts, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      if (scattered && i + ahead < end) {
        const std::uint32_t next = to.key(i + ahead);
        if (next != no_bucket) __builtin_prefetch(counts + next);
      }
      const std::uint32_t k = to.key(i);
      if (!scattered || k != no_bucket) ++counts[k];
    }
  };
  const auto place = [&](std::uint32_t* ends, std::size_t begin, std::size_t end) {
    for (std::size_t i = end; i-- > begin;) {
      if (scattered && i >= begin + 2 * ahead) {
        const std::uint32_t next = to.key(i - 2 * ahead);
        if (next != no_bucket) __builtin_prefetch(ends + next);
      }
      if (scattered && i >= begin + ahead) {
        const std::uint32_t next = to.key(i - ahead);
        if (next != no_bucket) to.ahead(ends[next] - 1);
      }
      const std::uint32_t k = to.key(i);
      if (!scattered || k != no_bucket) to.put(i, k, --ends[k]);
    }
  };
  start.assign(buckets + 1, 0);
  if constexpr (has_threads) {
    if (w.splits(n, min_parallel_items)) {
      const auto threads = static_cast<std::size_t>(w.threads());
      std::array<std::vector<std::uint32_t>*, max_threads> more{&start};
      for (int t = 1; t < w.threads(); ++t) more[static_cast<std::size_t>(t)] = &more_tables(t);
      std::array<std::uint32_t*, max_threads> table{};
      w.for_ranges(n, min_parallel_items, [&](int t, std::size_t begin, std::size_t end) {
        if (t != 0) more[static_cast<std::size_t>(t)]->assign(buckets, 0);  // (each range zeroes its own)
        table[static_cast<std::size_t>(t)] = more[static_cast<std::size_t>(t)]->data();
        count(table[static_cast<std::size_t>(t)], begin, end);
      });
      std::uint32_t at = 0;
      for (std::size_t b = 0; b < buckets; ++b)
        for (std::size_t t = 0; t < threads; ++t) table[t][b] = at += table[t][b];
      start[buckets] = at;
      w.for_ranges(n, min_parallel_items, [&](int t, std::size_t begin, std::size_t end) {
        place(table[static_cast<std::size_t>(t)], begin, end);
      });
      return;
    }
  }
  count(start.data(), 0, n);
  for (std::size_t b = 1; b <= buckets; ++b) start[b] += start[b - 1];
  place(start.data(), 0, n);
}

}  // namespace

#if !defined(__SSE2__)
FloatBox FloatBox::around(Vector p, Rect r, double margin) {
  return outward(p.x - margin, p.y - margin, (p.x + r.width) + margin, (p.y + r.height) + margin);
}
#endif

FloatBox FloatBox::outward_scalar(double x0, double y0, double x1, double y1) {
  return {float_down(x0), float_down(y0), float_up(x1), float_up(y1)};
}

#if !defined(__SSE2__)
FloatBox FloatBox::outward(double x0, double y0, double x1, double y1) { return outward_scalar(x0, y0, x1, y1); }
#endif

// Cells for the small boxes' corners (min_x, min_y), at least as wide as the
// widest small box.
void UniformGrid::size_grid(const SmallBoxes& s) {
  const double lo_x = s.lo_x, lo_y = s.lo_y, hi_x = s.hi_x, hi_y = s.hi_y, max_extent = s.max_extent;
  const std::size_t small = s.count;
  const double w = hi_x - lo_x, h = hi_y - lo_y;
  const double bodies = static_cast<double>(std::max<std::size_t>(small, 1));
  double cell = std::max(max_extent, std::sqrt(w * h / (cells_per_body * bodies)));
  if (!(cell > 0.0) || !std::isfinite(cell)) cell = std::isfinite(cell) ? 1.0 : std::numeric_limits<double>::max();
  // At most a few cells per body: bodies spread along a line or one far away
  // would otherwise ask for a huge table. Then cells get bigger instead.
  const double max_cells = 4.0 * bodies + 64.0;
  double nx = std::floor(w / cell) + 1.0, ny = std::floor(h / cell) + 1.0;
  while (!(nx * ny <= max_cells)) {
    cell *= 2.0;
    nx = std::floor(w / cell) + 1.0, ny = std::floor(h / cell) + 1.0;
  }
  x0_ = lo_x, y0_ = lo_y, cell_ = cell, inv_cell_ = 1.0 / cell;
  nx_ = static_cast<int>(nx), ny_ = static_cast<int>(ny);
  max_small_extent_ = max_extent;
}

void UniformGrid::emit(std::vector<PairKey>& out, std::uint32_t a, std::uint32_t b) const {
  if (fixed_[a] && fixed_[b]) return;
  out.push_back(pair_key(a, b));
}

// In stages: classify the boxes (small in the grid, large aside), size the
// grid, sort the small boxes into cells, then the pairs: grid cells against
// their neighbours, large boxes against the grid and each other; sorted.
void UniformGrid::build(std::span<const FloatBox> boxes, std::span<const std::uint8_t> fixed, Workers* workers) {
  const std::size_t n = boxes.size();
  if (n >= std::size_t{std::numeric_limits<std::uint32_t>::max()}) throw std::length_error("broadphase: too many bodies");
  Workers& w = workers_or_one(workers);
  fixed_.assign(fixed.begin(), fixed.end());
  found_.clear();
  const SmallBoxes small = classify(boxes, w);
  size_grid(small);
  fill_cells(boxes, small.count, w);
  pairs_in_grid(w);
  pairs_of_large();
  sort_pairs(n, w);
}

void UniformGrid::index(std::span<const FloatBox> boxes) {
  if (boxes.size() >= std::size_t{std::numeric_limits<std::uint32_t>::max()}) throw std::length_error("broadphase: too many bodies");
  fixed_.clear();
  found_.clear();
  pairs_.clear();
  Workers& one = workers_or_one(nullptr);
  const SmallBoxes small = classify(boxes, one);
  size_grid(small);
  fill_cells(boxes, small.count, one);
}

namespace {
// A box's larger side, and whether the grid can hold it: no NaN bound and
// both sides finite. Branch-free (`&`): at a million bodies this runs twice a
// box per pass.
struct BoxSize {
  double extent;
  bool finite;
};
BoxSize size_of(const FloatBox& b) {
  const double dx = static_cast<double>(b.max_x) - b.min_x, dy = static_cast<double>(b.max_y) - b.min_y;
  constexpr double inf = std::numeric_limits<double>::infinity();
  return {dx < dy ? dy : dx, static_cast<bool>((dx < inf) & (dy < inf))};  // a NaN side fails both tests
}
}  // namespace

// Sorts the bodies into small (in the grid) and large (aside); boxes with a
// NaN bound are in neither and collide with nothing. Afterwards cell_of_ says
// which bodies are small (nonzero). Returns what the grid's size depends on,
// gathered in the same pass (one read of the boxes fewer: at a million
// bodies the grid's passes are bound by memory). The mean size is summed on
// one thread (a sum in another order would round otherwise); the rest is
// per range, merged in range order (RangeBoxes::add), the large bodies'
// lists joined in that order.
UniformGrid::SmallBoxes UniformGrid::classify(std::span<const FloatBox> boxes, Workers& w) {
  const std::size_t n = boxes.size();
  // large_slot_ is -1 but for the large bodies: reset those of the last pass.
  for (const std::uint32_t i : large_)
    if (i < large_slot_.size()) large_slot_[i] = -1;
  large_slot_.resize(n, -1);
  large_.clear();
  large_box_.clear();
  double sum = 0.0;
  std::size_t counted = 0;
  for (const FloatBox& b : boxes) {
    const BoxSize z = size_of(b);
    sum += z.finite ? z.extent : 0.0;
    counted += z.finite;
  }
  const double threshold = counted ? large_factor * (sum / static_cast<double>(counted)) : 0.0;
  cell_of_.resize(n);
  RangeBoxes all;
  bool split = false;
  if constexpr (has_threads) {  // (the browser's build has one thread: the one range alone)
    split = w.splits(n, min_parallel_items);
    if (split) {
      std::array<RangeBoxes, max_threads> parts{};
      w.append_over_ranges(n, min_parallel_items, large_, [&](int t) -> auto& { return part(t, w).large; },
                           [&](int t, std::size_t begin, std::size_t end, std::vector<std::uint32_t>& large) {
                             parts[static_cast<std::size_t>(t)] = classify_range(boxes, begin, end, threshold, large);
                           });
      for (const RangeBoxes& range : parts) all.add(range);  // (the ranges not run: none)
    }
  }
  if (!split) all = classify_range(boxes, 0, n, threshold, large_);
  for (std::size_t l = 0; l < large_.size(); ++l) {
    large_slot_[large_[l]] = static_cast<std::int32_t>(l);
    large_box_.push_back(boxes[large_[l]]);
  }
  if (all.count == 0) return {0.0, 0.0, 0.0, 0.0, 0.0, 0};
  return {all.lo_x, all.lo_y, all.hi_x, all.hi_y, all.max_extent, all.count};
}

// classify() on the boxes [begin, end): marks the small ones in cell_of_,
// appends the large ones to `large`.
UniformGrid::RangeBoxes UniformGrid::classify_range(std::span<const FloatBox> boxes, std::size_t begin,
                                                    std::size_t end, double threshold,
                                                    std::vector<std::uint32_t>& large) {
  // In locals, not in the result's fields: those live in memory, which the
  // stores to cell_of_ may alias, so each body reloaded and stored all six.
  // The corners' bounds in float (exact; converted once at the end).
  RangeBoxes none;
  float lo_x = none.lo_x, lo_y = none.lo_y, hi_x = none.hi_x, hi_y = none.hi_y;
  double max_extent = 0.0;
  std::size_t count = 0;
  std::uint32_t* const cell = cell_of_.data();
  for (std::size_t i = begin; i < end; ++i) {
    const FloatBox& b = boxes[i];
    const BoxSize z = size_of(b);
    const bool small = z.finite & (z.extent <= threshold);
    cell[i] = small;
    if (small) {
      ++count;
      max_extent = z.extent > max_extent ? z.extent : max_extent;
      lo_x = b.min_x < lo_x ? b.min_x : lo_x, hi_x = b.min_x > hi_x ? b.min_x : hi_x;
      lo_y = b.min_y < lo_y ? b.min_y : lo_y, hi_y = b.min_y > hi_y ? b.min_y : hi_y;
    } else if (b.valid()) {
      large.push_back(static_cast<std::uint32_t>(i));
    }
  }
  return {lo_x, lo_y, hi_x, hi_y, max_extent, count};
}

// Merged in range order, with the comparisons of classify_range(): the
// bounds one range would have found (-0 and +0 included; no small box has a
// NaN bound), its widest box and its count.
void UniformGrid::RangeBoxes::add(const RangeBoxes& o) {
  lo_x = o.lo_x < lo_x ? o.lo_x : lo_x, lo_y = o.lo_y < lo_y ? o.lo_y : lo_y;
  hi_x = o.hi_x > hi_x ? o.hi_x : hi_x, hi_y = o.hi_y > hi_y ? o.hi_y : hi_y;
  max_extent = o.max_extent > max_extent ? o.max_extent : max_extent;
  count += o.count;
}

// Counting sort of the small boxes by cell (row-major), each cell's bodies
// in increasing index order.
void UniformGrid::fill_cells(std::span<const FloatBox> boxes, std::size_t small, Workers& w) {
  const std::size_t n = boxes.size();
  const std::size_t cells = table_size();
  std::uint32_t* const cell = cell_of_.data();
  w.for_ranges(n, min_parallel_items, [&](int, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
      cell[i] = cell[i] ? static_cast<std::uint32_t>(corner_cell(boxes[i])) : no_bucket;
  });
  // Padding after the last entry: pairs_in_run reads four entries at a time.
  entries_.resize(small + entry_padding);
  struct ToEntries {
    static constexpr bool scattered() { return true; }
    std::span<const FloatBox> boxes;
    const std::uint32_t* cell;
    Entry* entry;
    std::uint32_t key(std::size_t i) const { return cell[i]; }
    void ahead(std::uint32_t slot) const { __builtin_prefetch(entry + slot); }
    void put(std::size_t i, std::uint32_t c, std::uint32_t slot) const {
      entry[slot] = Entry{boxes[i], static_cast<std::uint32_t>(i), c};
    }
  };
  counting_sort(w, n, cells, cell_start_, [&](int t) -> auto& { return part(t, w).counts; },
                ToEntries{boxes, cell, entries_.data()});
  // No moved bodies yet: clear the lists the last pass left.
  for (const std::uint32_t c : moved_cells_)
    if (c < moved_head_.size()) moved_head_[c] = -1;
  moved_cells_.clear();
  moved_.clear();
  updated_ = 0;
  moved_head_.resize(cells, -1);
}

// On a team, each range of entries finds its pairs, joined in order.
void UniformGrid::pairs_in_grid(Workers& w) {
  const std::uint32_t count = cell_start_[table_size()];
  w.append_over_ranges(count, min_parallel_items, found_,
                       [&](int t) -> auto& { return part(t, w).found; },
                       [&](int, std::size_t begin, std::size_t end, std::vector<PairKey>& out) {
                         pairs_of_entries(static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(end), out);
                       });
}

// The pairs of the entries [from, to) with the entries after them, to `out`.
// Walks the entries (in cell order) rather than the cells: most cells hold
// zero, one or two bodies at random, and a test per cell for emptiness was a
// mispredicted branch about every other cell (walking the cells, a 200 000-body
// gas spent 119 M instructions here over 5 steps; walking the entries, 61 M).
// Each pair of neighbouring cells is visited once, from the
// earlier one: an entry meets the later entries of its cell and those of its
// right neighbour, then the three cells below it (below-left, below,
// below-right); each run is contiguous in entries_, and the table's empty
// last column and row stand for the neighbours beyond the edges. (The
// tables' pointers in locals that no call can change: reached through a
// closure, they were loaded again after every pair found, +30 % here.)
void UniformGrid::pairs_of_entries(std::uint32_t from, std::uint32_t to, std::vector<PairKey>& out) const {
  const std::uint32_t* const start = cell_start_.data();
  const Entry* const entry = entries_.data();
  const std::size_t below = stride();
  for (std::uint32_t a = from; a < to; ++a) {
    const std::size_t c = entry[a].cell;
    const std::uint32_t same_end = start[c + 2];  // this cell and the right one
    const std::uint32_t below_s = start[c + below - 1], below_e = start[c + below + 2];
    const RunTest test(entry[a].box);
    pairs_in_run(out, test, entry, a, a + 1, same_end);
    pairs_in_run(out, test, entry, a, below_s, below_e);
  }
}

#if defined(__SSE2__)
// Entry a against the entries [b, e), four at a time (RunTest::lanes). A run
// usually holds 0 to 4 entries, at random (1.5 on average for the three
// cells below, in a gas): looping over its entries one by one, the loop's
// end and the overlap test were 1.7 mispredicted branches an entry, 95 % of
// the step's (callgrind --branch-sim, a 200 000-body gas). Here the first
// group is always tested (the entries past the last are padding), so the
// only branches left are on a run of more than four and on a hit, both rare.
// The hit is marked unlikely: with emit's call on the loop's path, GCC kept
// the box's vectors on the stack and reloaded them every group; now it saves
// them only around the call.
[[gnu::always_inline]] inline void UniformGrid::pairs_in_run(std::vector<PairKey>& out, const RunTest& test,
                                                             const Entry* entry, std::uint32_t a, std::uint32_t b,
                                                             std::uint32_t e) const {
  do {
    const std::uint32_t hits = test.lanes(entry + b, e - b);
    if (hits) [[unlikely]]
      emit_lanes(out, entry[a].index, entry + b, hits);
    b += 4;
  } while (b < e);
}

void UniformGrid::emit_lanes(std::vector<PairKey>& out, std::uint32_t body, const Entry* from,
                             std::uint32_t hits) const {
  for (; hits; hits &= hits - 1) emit(out, body, from[std::countr_zero(hits)].index);
}
#else
[[gnu::always_inline]] inline void UniformGrid::pairs_in_run(std::vector<PairKey>& out, const RunTest& test,
                                                             const Entry* entry, std::uint32_t a, std::uint32_t b,
                                                             std::uint32_t e) const {
  for (; b < e; ++b)
    if (overlap(test.box, entry[b].box)) emit(out, entry[a].index, entry[b].index);
}
#endif

// Large bodies against the grid, then against each other by a sweep on x:
// "large" is relative to the mean, so when resting bodies make most of a
// scene, every falling one (its box swept over the step) can be large, and
// testing them all pairwise was quadratic (tens of ms at 100 000).
void UniformGrid::pairs_of_large() {
  for (std::size_t l = 0; l < large_.size(); ++l) {
    const std::uint32_t i = large_[l];
    query_grid(large_box_[l], [&](std::uint32_t j) { emit(found_, i, j); });
  }
  // By min_x, then by index: keys whose order is the floats' (one sort of
  // integers, shared with the pairs', instead of one more of its own).
  large_order_.resize(large_.size());
  for (std::size_t l = 0; l < large_.size(); ++l) {
    large_order_[l] = std::uint64_t{ordered_bits(large_box_[l].min_x)} << 32 | l;
  }
  std::sort(large_order_.begin(), large_order_.end());
  const auto at = [&](std::size_t a) { return static_cast<std::uint32_t>(large_order_[a]); };  // (l)
  for (std::size_t a = 0; a < large_order_.size(); ++a) {
    const FloatBox& box = large_box_[at(a)];
    for (std::size_t b = a + 1; b < large_order_.size(); ++b) {
      const FloatBox& other = large_box_[at(b)];
      if (other.min_x > box.max_x) break;
      if (overlap(box, other)) emit(found_, large_[at(a)], large_[at(b)]);
    }
  }
}

void UniformGrid::sort_pairs(std::size_t n, Workers& w) {
  // Few pairs among many bodies (a thin gas: a million bodies, a few
  // thousand pairs a pass): a comparison sort of the pairs costs less than
  // the counting sort's pass over every body. Both give the same order
  // (each pair is found once).
  if (!sorts_by_counting || found_.size() * 32 < n) {
    pairs_.swap(found_);  // (found_ is read by build() alone, which clears it first, as index() does)
    std::sort(pairs_.begin(), pairs_.end());
    return;
  }
  // Counting sort on the first index, then each (short) run of pairs sharing
  // it by insertion sort: O(n + pairs), where a full sort would cost
  // O(pairs log pairs) and dominate the broadphase. Each run keeps the order
  // the pairs were found in, which is mostly increasing (a cell's bodies are
  // in index order): insertion sort is then nearly free, where a reversed
  // run cost O(len²) (1 000 blocks on one spot: 0.1 s a pass).
  pairs_.resize(found_.size());
  struct ToPairs {
    static constexpr bool scattered() { return false; }
    const PairKey* found;
    PairKey* pairs;
    std::uint32_t key(std::size_t k) const { return pair_first(found[k]); }
    void ahead(std::uint32_t) const {}
    void put(std::size_t k, std::uint32_t, std::uint32_t slot) const { pairs[slot] = found[k]; }
  };
  counting_sort(w, found_.size(), n, first_count_, [&](int t) -> auto& { return part(t, w).counts; },
                ToPairs{found_.data(), pairs_.data()});
  // first_count_[i] is now where the pairs of first index i begin.
  w.for_ranges(n, min_parallel_items, [&](int, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      PairKey* const run = pairs_.data() + first_count_[i];
      const std::size_t len = first_count_[i + 1] - first_count_[i];
      for (std::size_t a = 1; a < len; ++a) {
        const PairKey k = run[a];
        std::size_t b = a;
        for (; b > 0 && run[b - 1] > k; --b) run[b] = run[b - 1];
        run[b] = k;
      }
    }
  });
}

void UniformGrid::move(std::uint32_t i, const FloatBox& box) {
  if (large_slot_[i] >= 0) {
    large_box_[static_cast<std::size_t>(large_slot_[i])] = box;
    return;
  }
  if (!box.valid()) return;
  if (!(size_of(box).extent <= max_small_extent_)) {
    // Rounding to float can widen a box by an ulp at larger coordinates; the
    // grid's queries only look max_small_extent_ back, so such a box goes to
    // the large list instead (rare, and always correct).
    large_slot_[i] = static_cast<std::int32_t>(large_.size());
    large_.push_back(i);
    large_box_.push_back(box);
    return;
  }
  const std::size_t c = corner_cell(box);
  if (moved_head_[c] < 0) moved_cells_.push_back(static_cast<std::uint32_t>(c));
  moved_.push_back(Moved{Entry{box, i, static_cast<std::uint32_t>(c)}, moved_head_[c]});
  moved_head_[c] = static_cast<std::int32_t>(moved_.size() - 1);
}

// The moved bodies' new pairs, found by queries (which see the new boxes
// and the old), tested on the boxes as they are now; those pairs() lacks
// are merged in from the back, each list's largest first: the memory
// behind the first new pair is moved once, and no scratch list is made.
void UniformGrid::update(std::span<const std::uint32_t> moved, std::span<const FloatBox> boxes) {
  for (const std::uint32_t i : moved) move(i, boxes[i]);
  updated_ += moved.size();
  found_.clear();  // (scratch: build() clears it before use)
  for (const std::uint32_t i : moved)
    query(boxes[i], [&](std::uint32_t j) {
      if (j != i && !(fixed_[i] && fixed_[j]) && overlap(boxes[i], boxes[j])) found_.push_back(pair_key(i, j));
    });
  std::sort(found_.begin(), found_.end());
  found_.erase(std::unique(found_.begin(), found_.end()), found_.end());
  std::erase_if(found_, [&](PairKey key) { return std::binary_search(pairs_.begin(), pairs_.end(), key); });
  std::size_t a = pairs_.size(), b = found_.size();
  pairs_.resize(a + b);
  for (std::size_t to = a + b; b > 0;) pairs_[--to] = a > 0 && pairs_[a - 1] > found_[b - 1] ? pairs_[--a] : found_[--b];
}

}  // namespace physics
