// Broadphase: finds the pairs of bodies whose boxes may touch, so that
// Collision does not test every pair (the sheet's loop is O(n²): fine for ten
// blocks, hopeless for ten thousand).
//
// Why a uniform grid and not sort-and-sweep (measured by `make bench`, section
// "broadphase", same boxes fed to both, see bench/RESULTS.md): one sorted axis
// only separates bodies along x, so in a square world of n bodies each box is
// tested against the ~sqrt(n) boxes that share its x range; at 100 000 gas
// bodies that is ~100 tests per body per pass and sort-and-sweep was 13-15
// times slower than the grid, which tests each box against the few boxes of
// its 3×3 neighbouring cells whatever n is. The grid's cost grows linearly.
//
// The grid is built from scratch (counting sort of the boxes by cell), so
// bodies that were moved, resized, given another mass, registered or
// unregistered by anyone are always seen as they are: O(n), cheaper than
// keeping a tree in sync. What keeps one is its owner's business: the
// broad phase (engine/pairs.hpp) keeps its grid of fat boxes while the
// bodies stay in them, and gives the few that leave new boxes (update()).
#pragma once

#include <bit>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "course/utils/rect.hpp"
#include "course/utils/vect.hpp"
#include "engine/workers.hpp"

namespace physics {

// An axis-aligned box in float, rounded outwards from the double box it was
// made from, so it always contains it: a pair of bodies whose Aabbs do not
// overlap cannot overlap either. Float halves the memory the grid walks.
struct FloatBox {
  float min_x = 0, min_y = 0, max_x = 0, max_y = 0;

  // The box of a body at p of size r, grown by `margin` px on every side:
  // outward() of its bounds (with SSE2, both axes at once, below).
  static FloatBox around(Vector p, Rect r, double margin);
  // The smallest float box containing [x0, x1] x [y0, y1].
  static FloatBox outward(double x0, double y0, double x1, double y1);
  // outward() one bound at a time: its definition, which the versions with
  // SSE2 (around() and outward(), below) are tested against.
  static FloatBox outward_scalar(double x0, double y0, double x1, double y1);
  // Whether the body at p of size r is still inside this box, computed as
  // the body's own corners p and p + r are in double: exactly the values that
  // Collision::resolve compares.
  bool contains(Vector p, Rect r) const {
    return min_x <= p.x && min_y <= p.y && p.x + r.width <= max_x && p.y + r.height <= max_y;
  }
  // False when a bound is NaN (a body at NaN collides with nothing, as in
  // Collision::resolve). Bounds may be infinite for bodies beyond float range.
  bool valid() const { return min_x == min_x && min_y == min_y && max_x == max_x && max_y == max_y; }

  // Closed test: boxes that merely touch count as overlapping (a superset of
  // the strict test of Rect::has_origin, so no contact is ever missed).
  // `&`, not `&&`: most tested pairs fail on some axis, unpredictably, and
  // four compares cost less than a mispredicted branch.
  friend bool overlap(const FloatBox& a, const FloatBox& b) {
    return (a.min_x <= b.max_x) & (b.min_x <= a.max_x) & (a.min_y <= b.max_y) & (b.min_y <= a.max_y);
  }
};

// A pair (i, j), i < j, of indices into the boxes given to the broadphase,
// packed so that sorting keys sorts pairs in the order of the sheet's loop
// "for i, for j > i".
using PairKey = std::uint64_t;
constexpr PairKey pair_key(std::uint32_t a, std::uint32_t b) {
  return a < b ? (PairKey{a} << 32) | b : (PairKey{b} << 32) | a;
}
constexpr std::uint32_t pair_first(PairKey k) { return static_cast<std::uint32_t>(k >> 32); }
constexpr std::uint32_t pair_second(PairKey k) { return static_cast<std::uint32_t>(k); }

#if defined(__SSE2__)
namespace detail {
// float_down of two doubles at once (in the low two lanes), the same values:
// the nearest float, one down by its bits where it is above x or is +inf
// (float_down saturates at the largest float). Only a zero's sign may differ
// (+0 where float_down gives -0), which no comparison sees.
inline __m128 floats_down(__m128d x) {
  const __m128 f = _mm_cvtpd_ps(x);  // nearest; beyond float range ±inf, NaN stays NaN
  const __m128d back = _mm_cvtps_pd(f);
  const __m128d above = _mm_or_pd(_mm_cmpgt_pd(back, x), _mm_cmpeq_pd(back, _mm_set1_pd(__builtin_inf())));
  const __m128 above32 = _mm_shuffle_ps(_mm_castpd_ps(above), _mm_castpd_ps(above), _MM_SHUFFLE(2, 0, 2, 0));
  const __m128i bits = _mm_castps_si128(f);
  // One float down: -1 on the bits at or above +0, +1 below.
  const __m128i step = _mm_or_si128(_mm_slli_epi32(_mm_srai_epi32(bits, 31), 1), _mm_set1_epi32(1));
  return _mm_castsi128_ps(_mm_sub_epi32(bits, _mm_and_si128(step, _mm_castps_si128(above32))));
}

// The float box of [lo.x, hi.x] x [lo.y, hi.y] (each pair x in the low lane),
// rounded outwards: float_up(x) = -float_down(-x), by the sign bits.
inline FloatBox box_outward(__m128d lo, __m128d hi) {
  const __m128 up = _mm_xor_ps(floats_down(_mm_xor_pd(hi, _mm_set1_pd(-0.0))), _mm_set1_ps(-0.0f));
  return std::bit_cast<FloatBox>(_mm_movelh_ps(floats_down(lo), up));
}
}  // namespace detail

// The grid's hottest loop makes one box per body per pass (a million gas
// bodies: 97 instructions a box in scalar, 35 like this). Inline, so that the
// position is loaded from its array as a pair: passed in two registers and
// stored, its load as one stalled on the stores (slower than the scalar code).
inline FloatBox FloatBox::around(Vector p, Rect r, double margin) {
  const __m128d pos = _mm_set_pd(p.y, p.x);
  const __m128d m = _mm_set1_pd(margin);
  const __m128d lo = _mm_sub_pd(pos, m);
  const __m128d hi = _mm_add_pd(_mm_add_pd(pos, _mm_set_pd(r.height, r.width)), m);
  return detail::box_outward(lo, hi);
}

// The same, from the bounds (the stable solver's fat boxes: a falling rain
// rebuilds its grid every few calls, and the scalar version was 7 % of it).
inline FloatBox FloatBox::outward(double x0, double y0, double x1, double y1) {
  return detail::box_outward(_mm_set_pd(y0, x0), _mm_set_pd(y1, x1));
}
#endif

// Uniform grid of square cells, each body stored once, in the cell of its
// box's lower corner. A cell is at least as wide as the largest "small" box,
// so a box can only overlap boxes stored in its own cell and the 8 around it.
// Boxes much larger than the typical one (walls, platforms) would force huge
// cells: they are kept aside in a short list and tested against the grid.
class UniformGrid {
 public:
  // Finds every pair of overlapping boxes except pairs of two fixed bodies
  // (two infinite masses never collide, so they never enter the list).
  // Boxes with a NaN bound (a body at NaN) overlap nothing.
  // O(n + pairs); the result is in pairs(), sorted. The same grid and pairs
  // on any team (`workers`: its passes split over the threads).
  void build(std::span<const FloatBox> boxes, std::span<const std::uint8_t> fixed, Workers* workers = nullptr);
  const std::vector<PairKey>& pairs() const { return pairs_; }
  // The cells of build() without its pairs (pairs() is left empty), for
  // queries that only ask which boxes lie somewhere (engine/query.hpp).
  void index(std::span<const FloatBox> boxes);

  // Body i now has the box `box` for later queries. The pairs of build() are
  // left as they are; the box i had when the grid was built stays in its cell
  // (queries may report it: callers must accept extra candidates).
  void move(std::uint32_t i, const FloatBox& box);

  // After build(), the bodies of `moved` (each once) have new boxes, as
  // `boxes` says (every body's, the others' as build() had them): each is
  // moved (move()), and pairs() gains its pairs with every box it overlaps
  // now. Its pairs of the old box stay: pairs() is then a superset of the
  // overlapping pairs, still sorted, each pair once (its callers test the
  // exact boxes). For a few bodies, far less than build(); queries slow as
  // the moves add up (updated(): how many since build()).
  void update(std::span<const std::uint32_t> moved, std::span<const FloatBox> boxes);
  std::size_t updated() const { return updated_; }

  // Calls f(j) for every body j whose current box may overlap `box`; every j
  // whose box does overlap is reported at least once. j may be reported more
  // than once, and the body whose box is queried may be reported itself.
  template <class F>
  void query(const FloatBox& box, F&& f) const {
    query_grid(box, f);
    for (std::size_t l = 0; l < large_.size(); ++l)
      if (overlap(large_box_[l], box)) f(large_[l]);
  }

  // Diagnostics for the benchmark.
  std::size_t cells() const { return static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_); }
  double cell_size() const { return cell_; }
  std::size_t large_count() const { return large_.size(); }

 private:
  struct Entry {
    FloatBox box;
    std::uint32_t index;
    std::uint32_t cell;  // its cell (pairs_of_entries walks the entries, not the cells)
  };
  struct Moved {
    Entry entry;
    std::int32_t next;  // next moved entry of the same cell, -1 at the end
  };

  // query() without the large bodies.
  template <class F>
  void query_grid(const FloatBox& box, F&& f) const;
  // The column and row of a point, clamped to the grid (NaN to 0).
  int cell_x(double x) const { return clamp_cell((x - x0_) * inv_cell_, nx_); }
  int cell_y(double y) const { return clamp_cell((y - y0_) * inv_cell_, ny_); }
  static int clamp_cell(double t, int n) {
    t = t > 0.0 ? t : 0.0;
    const double last = n - 1;
    return static_cast<int>(t < last ? t : last);
  }
  // The cell of a box's lower corner: cell_at(cell_x(min_x), cell_y(min_y)).
  std::size_t corner_cell(const FloatBox& b) const;
  std::size_t cell_at(int cx, int cy) const {
    return static_cast<std::size_t>(cy) * stride() + static_cast<std::size_t>(cx);
  }
  // The table has a row of stride() = nx_ + 1 cells per grid row, the last
  // one always empty, and one more empty row below: the left, right and
  // lower neighbours of every cell exist, so no walk tests for the edges.
  std::size_t stride() const { return static_cast<std::size_t>(nx_) + 1; }
  std::size_t table_size() const { return (static_cast<std::size_t>(ny_) + 1) * stride(); }
  // build()'s stages.
  struct SmallBoxes {
    double lo_x, lo_y, hi_x, hi_y;  // the bounds of their corners (min_x, min_y)
    double max_extent;              // the widest one's larger side
    std::size_t count;
  };
  struct RangeBoxes {  // classify()'s findings in a range of the boxes (none yet: a small box's min is finite)
    float lo_x = std::numeric_limits<float>::infinity(), lo_y = std::numeric_limits<float>::infinity();
    float hi_x = -std::numeric_limits<float>::infinity(), hi_y = -std::numeric_limits<float>::infinity();
    double max_extent = 0.0;
    std::size_t count = 0;
    void add(const RangeBoxes& other);
  };
  SmallBoxes classify(std::span<const FloatBox> boxes, Workers& w);
  RangeBoxes classify_range(std::span<const FloatBox> boxes, std::size_t begin, std::size_t end, double threshold,
                            std::vector<std::uint32_t>& large);
  void size_grid(const SmallBoxes& small);
  void fill_cells(std::span<const FloatBox> boxes, std::size_t small, Workers& w);
  void pairs_in_grid(Workers& w);
  void pairs_of_entries(std::uint32_t from, std::uint32_t to, std::vector<PairKey>& out) const;
  struct RunTest;
  void pairs_in_run(std::vector<PairKey>& out, const RunTest& test, const Entry* entry, std::uint32_t a,
                    std::uint32_t b, std::uint32_t e) const;
  // body with from[k], k in hits
  void emit_lanes(std::vector<PairKey>& out, std::uint32_t body, const Entry* from, std::uint32_t hits) const;
  static constexpr std::size_t entry_padding = 4;  // entries read past the last (RunTest::lanes)
  void pairs_of_large();
  void emit(std::vector<PairKey>& out, std::uint32_t a, std::uint32_t b) const;
  void sort_pairs(std::size_t n, Workers& w);

  // Geometry.
  double x0_ = 0, y0_ = 0, cell_ = 1, inv_cell_ = 1;
  int nx_ = 1, ny_ = 1;
  double max_small_extent_ = 0;  // every box in the grid is at most this wide

  std::vector<std::uint32_t> cell_start_;  // entries of cell c: [cell_start_[c], cell_start_[c+1]), table_size() + 1
  std::vector<Entry> entries_;             // the small boxes, sorted by cell, then entry_padding more
  std::vector<std::uint32_t> cell_of_;     // scratch: cell of each small body
  std::vector<std::uint32_t> large_;       // indices of the large bodies
  std::vector<FloatBox> large_box_;            // their current boxes
  std::vector<std::int32_t> large_slot_;   // per body: position in large_, or -1
  std::vector<std::uint64_t> large_order_; // scratch: (min_x, l) keys, sorted
  std::vector<std::uint8_t> fixed_;        // per body, copied from build()
  // Scratch of build()'s passes on a team, per range but the first (whose
  // are the tables above): its large bodies, its counts in the counting
  // sorts, its pairs. One member: each costs bytes in every move of a grid,
  // which the browser's build, without a team, would carry for nothing.
  struct RangePart {
    std::vector<std::uint32_t> large, counts;
    std::vector<PairKey> found;
  };
  std::vector<RangePart> parts_;
  RangePart& part(int t, const Workers& w) { return part_of(parts_, t, w.threads()); }  // (not from a range's task)

  // Bodies moved after build(), per cell (linked lists, reset at each build).
  std::vector<std::int32_t> moved_head_;
  std::vector<std::uint32_t> moved_cells_;
  std::vector<Moved> moved_;
  std::size_t updated_ = 0;  // bodies given new boxes by update() since build()

  // Pairs, unsorted then sorted (counting sort on the first index).
  std::vector<PairKey> found_;
  std::vector<std::uint32_t> first_count_;
  std::vector<PairKey> pairs_;
};

#if defined(__SSE2__)
// One box a against four entries b at a time, the four comparisons of
// overlap() as one compare of a box per entry: (b.min_x, b.min_y, -b.max_x,
// -b.max_y) <= (a.max_x, a.max_y, -a.min_x, -a.min_y) in every lane (the
// signs flipped by their bits, exactly; the same results, NaN included), the
// four entries' lanes then packed into one mask. 22 instructions a group of
// four where a transposition of the boxes took 45 (SSE2 has no three-operand
// forms, so each shuffle needed a copy).
struct UniformGrid::RunTest {
  __m128 flip = _mm_castsi128_ps(_mm_set_epi32(INT32_MIN, INT32_MIN, 0, 0));  // the sign of the upper two lanes
  __m128 bound;  // (a.max_x, a.max_y, -a.min_x, -a.min_y)
  explicit RunTest(const FloatBox& a) : bound(_mm_set_ps(-a.min_y, -a.min_x, a.max_y, a.max_x)) {}
  // Bit k set when from[k] overlaps the box and k < live (the entries past
  // the first `live` are read, not reported). Branch-free. live is compared
  // as a signed integer: it is at most the grid's entries, < 2^31 (24 bytes
  // each: 48 GB).
  std::uint32_t lanes(const Entry* from, std::uint32_t live) const {
    const auto test = [&](int k) {
      return _mm_castps_si128(_mm_cmple_ps(_mm_xor_ps(_mm_loadu_ps(&from[k].box.min_x), flip), bound));
    };
    // Each entry's four lanes (-1 or 0) to four bytes of one lane, by
    // saturating packs; a lane of -1 (all four true) is an overlap.
    const __m128i packed = _mm_packs_epi16(_mm_packs_epi32(test(0), test(1)), _mm_packs_epi32(test(2), test(3)));
    const __m128i all = _mm_cmpeq_epi32(packed, _mm_set1_epi32(-1));
    // Compared as integers: min(live, 4) compiled to a mispredicted branch.
    const __m128i on = _mm_cmplt_epi32(_mm_set_epi32(3, 2, 1, 0), _mm_set1_epi32(static_cast<std::int32_t>(live)));
    return static_cast<std::uint32_t>(_mm_movemask_ps(_mm_castsi128_ps(_mm_and_si128(all, on))));
  }
};
#else
struct UniformGrid::RunTest {
  FloatBox box;
  explicit RunTest(const FloatBox& b) : box(b) {}
};
#endif

#if defined(__SSE2__)
// Both axes at once, branch-free: the two clamps of cell_x and cell_y are
// maxpd and minpd (the same results; NaN goes to 0). As scalar code they were
// four branches a body, which mispredict on bodies at the grid's edges.
inline std::size_t UniformGrid::corner_cell(const FloatBox& b) const {
  const __m128d corner = _mm_cvtps_pd(std::bit_cast<__m128>(b));  // (min_x, min_y)
  const __m128d t = _mm_mul_pd(_mm_sub_pd(corner, _mm_set_pd(y0_, x0_)), _mm_set1_pd(inv_cell_));
  const __m128d last = _mm_set_pd(ny_ - 1, nx_ - 1);
  const __m128i cells = _mm_cvttpd_epi32(_mm_min_pd(_mm_max_pd(t, _mm_setzero_pd()), last));
  const auto cx = static_cast<std::size_t>(_mm_cvtsi128_si32(cells));
  const auto cy = static_cast<std::size_t>(_mm_cvtsi128_si32(_mm_shuffle_epi32(cells, 1)));
  return cy * stride() + cx;
}
#else
inline std::size_t UniformGrid::corner_cell(const FloatBox& b) const {
  return cell_at(cell_x(b.min_x), cell_y(b.min_y));
}
#endif

template <class F>
void UniformGrid::query_grid(const FloatBox& box, F&& f) const {
  if (!box.valid()) return;
  // A stored box overlapping `box` has its lower corner at most
  // max_small_extent_ before box.min: scan from there. The small extra
  // subtraction covers the rounding of the subtraction itself.
  double lo_x = box.min_x - max_small_extent_;
  double lo_y = box.min_y - max_small_extent_;
  lo_x -= (lo_x < 0 ? -lo_x : lo_x) * 0x1p-40 + 0x1p-40;
  lo_y -= (lo_y < 0 ? -lo_y : lo_y) * 0x1p-40 + 0x1p-40;
  const int cx0 = cell_x(lo_x), cx1 = cell_x(box.max_x);
  const int cy0 = cell_y(lo_y), cy1 = cell_y(box.max_y);
  for (int cy = cy0; cy <= cy1; ++cy) {
    const std::size_t row = cell_at(0, cy);
    // The cells cx0..cx1 of a row are contiguous in entries_.
    const std::uint32_t end = cell_start_[row + static_cast<std::size_t>(cx1) + 1];
    for (std::uint32_t e = cell_start_[row + static_cast<std::size_t>(cx0)]; e < end; ++e)
      if (overlap(entries_[e].box, box)) f(entries_[e].index);
    if (moved_.empty()) continue;
    for (int cx = cx0; cx <= cx1; ++cx)
      for (std::int32_t m = moved_head_[row + static_cast<std::size_t>(cx)]; m >= 0;
           m = moved_[static_cast<std::size_t>(m)].next)
        if (overlap(moved_[static_cast<std::size_t>(m)].entry.box, box))
          f(moved_[static_cast<std::size_t>(m)].entry.index);
  }
}

}  // namespace physics
