// The broadphase: the grid finds exactly the overlapping boxes, and Collision
// with the broadphase resolves the same pairs in the same order with the same
// results as the sheet's all-pairs loop (the oracle), bit for bit.
#include <algorithm>
#include <cstring>
#include <limits>
#include <vector>

#include "course/game.hpp"
#include "helpers.hpp"
#include "engine/broadphase.hpp"
#include "engine/workers.hpp"
#include "course/utils/random.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_broadphase {

using namespace physics;

namespace {

// Every pair of overlapping boxes, not both fixed, by brute force.
std::vector<PairKey> brute_pairs(const std::vector<FloatBox>& boxes, const std::vector<std::uint8_t>& fixed) {
  std::vector<PairKey> out;
  for (std::uint32_t i = 0; i < boxes.size(); ++i)
    for (std::uint32_t j = i + 1; j < boxes.size(); ++j)
      if (boxes[i].valid() && boxes[j].valid() && overlap(boxes[i], boxes[j]) && !(fixed[i] && fixed[j]))
        out.push_back(pair_key(i, j));
  return out;
}

using physics::test::same_bits;

// Random boxes for the grid's tests: n boxes with corners in [lo, world)²
// and sides in [0.5, side), a share `walls` of them `world` wide and
// wall_height high (the large list), and about one in a hundred each with a
// NaN bound, an infinite one, or an earlier box's bounds; a fifth fixed.
struct BoxMix {
  double lo, world, side, walls, wall_height;
};
void random_boxes(Random& rng, int n, const BoxMix& mix, std::vector<FloatBox>& boxes, std::vector<std::uint8_t>& fixed) {
  for (int i = 0; i < n; ++i) {
    const double kind = rng.uniform(0, 1);
    double w = rng.uniform(0.5, mix.side), h = rng.uniform(0.5, mix.side);
    if (kind < mix.walls) w = mix.world, h = mix.wall_height;
    const Vector p{rng.uniform(mix.lo, mix.world), rng.uniform(mix.lo, mix.world)};
    FloatBox b{static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.x + w), static_cast<float>(p.y + h)};
    if (kind > 0.99) b.min_x = std::numeric_limits<float>::quiet_NaN();
    if (kind > 0.98 && kind <= 0.99) b.max_x = std::numeric_limits<float>::infinity();
    if (kind > 0.97 && kind <= 0.98 && !boxes.empty()) b = boxes[static_cast<std::size_t>(rng.uniform_int(0, i - 1))];
    boxes.push_back(b);
    fixed.push_back(rng.uniform(0, 1) < 0.2);
  }
}


// A random scene of `bodies` blocks in a walled region; `spread` < 1 packs
// them into the top-left part of it so they start overlapping.
struct Spec {
  int bodies = 300;
  int width = 800, height = 600;
  double spread = 1.0;
  int min_side = 4, max_side = 30;
  double speed = 0.3;           // px/ms, per axis
  double fixed_fraction = 0.0;  // small infinite-mass blocks among the others
  double big_fraction = 0.0;    // blocks 5-10 times larger (kept out of the grid)
  Vector gravity{};
  double margin = 1.0;
  bool shuffle = false;  // registration order differs from creation order
  std::uint64_t seed = 1;
};

World make_scene(const Spec& s) {
  World w = test::physics_world(Params{.gravity = s.gravity});
  Game::init_walls(w, s.width, s.height);
  Random rng(s.seed);
  for (int n = 0; n < s.bodies; ++n) {
    int side_x = rng.uniform_int(s.min_side, s.max_side), side_y = rng.uniform_int(s.min_side, s.max_side);
    if (rng.uniform(0, 1) < s.big_fraction) side_x *= 8, side_y *= 5;
    const double x = 40 + rng.uniform(0, (s.width - 80 - side_x) * s.spread);
    const double y = 40 + rng.uniform(0, (s.height - 80 - side_y) * s.spread);
    const bool fixed = rng.uniform(0, 1) < s.fixed_fraction;
    const auto b = Block::make(w, x, y, side_x, side_y, test::grey, fixed ? infinity : rng.uniform(0.5, 20.0),
                               rng.uniform(0, 1) < 0.5 ? 1.0 : rng.uniform(0, 1));
    w.components.velocity[b.id] = {rng.uniform(-s.speed, s.speed), rng.uniform(-s.speed, s.speed)};
  }
  if (s.shuffle) {
    Systems systems(w);
    Collision& c = *systems.collision;
    for (EntityId e = 0; e < w.components.size(); ++e)
      if (rng.uniform(0, 1) < 0.3) {
        c.unregister(e);
        c.register_entity(Block::t{e});
      }
  }
  w.broadphase.course_margin = s.margin;
  w.pass.record_contacts = true;
  return w;
}

// Runs the same scene with the broadphase and with the all-pairs loop, frame
// by frame, comparing the contacts of every pass and the final state.
struct Outcome {
  std::size_t contacts = 0, requeries = 0, by_rows = 0, bad_frames = 0, bad_bodies = 0;
};

Outcome compare_with_oracle(const Spec& s, int frames) {
  World fast = make_scene(s), oracle = make_scene(s);
  Outcome out;
  for (int f = 0; f < frames; ++f) {
    for (World* w : {&fast, &oracle}) {
      Systems(*w).forces->update(w->components, w->params.dt, w->params.gravity);
      Systems(*w).move->update(w->components, w->params.dt);
    }
    test::collide(fast);
    const test::AllPairs all = test::update_all_pairs(oracle);
    const auto& a = fast.pass.contacts;
    const auto& b = all.contacts;
    bool same = a.size() == b.size() && fast.pass.contact_count == all.count;
    for (std::size_t i = 0; same && i < a.size(); ++i)
      same = a[i].c == b[i].c && a[i].b == b[i].b && same_bits(a[i].penetration, b[i].penetration) &&
             same_bits(a[i].normal, b[i].normal) && a[i].approaching == b[i].approaching;
    out.bad_frames += !same;
    out.contacts += b.size();
    out.requeries += fast.broadphase.stats().requeries;
    out.by_rows += fast.broadphase.stats().by_rows;
  }
  for (EntityId e = 0; e < fast.components.size(); ++e)
    out.bad_bodies += !(same_bits(fast.components.position[e], oracle.components.position[e]) &&
                        same_bits(fast.components.velocity[e], oracle.components.velocity[e]));
  return out;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(broadphase)

BOOST_AUTO_TEST_CASE(boxes_are_rounded_outwards_and_contain_the_body) {
  const Rect r{7, 3};
  for (const double x : {0.0, 0.1, -0.1, 1.0 / 3.0, 123456.789, -9.87654321e6, 1e7 + 0.3, 3.3e20, -1e39}) {
    const Vector p{x, -x / 7};
    const FloatBox tight = FloatBox::around(p, r, 0.0);
    BOOST_TEST(tight.contains(p, r));
    BOOST_TEST(tight.min_x <= p.x);
    BOOST_TEST(static_cast<double>(tight.max_x) >= p.x + r.width);
    const FloatBox grown = FloatBox::around(p, r, 2.0);
    BOOST_TEST(grown.contains(p, r));
    BOOST_TEST(static_cast<double>(grown.min_x) <= p.x - 2.0);
    BOOST_TEST(static_cast<double>(grown.max_y) >= p.y + r.height + 2.0);
  }
  // Beyond float range the box becomes infinite rather than wrong.
  const FloatBox far = FloatBox::around({1e300, 0}, r, 1.0);
  BOOST_TEST(far.contains({1e300, 0}, r));
  BOOST_TEST(far.valid());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  BOOST_TEST(!FloatBox::around({nan, 0}, r, 1.0).valid());
}

BOOST_AUTO_TEST_CASE(a_box_around_a_body_is_its_bounds_rounded_outwards_to_float) {
  // around() and outward() (vectorised where SSE2 is there) against
  // outward_scalar() on the bounds they are defined by: the same values on
  // every kind of coordinate, including float overflow, infinities, NaN,
  // zeros and values just around a float.
  const auto same = [](float a, float b) { return a == b || (a != a && b != b); };
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> xs = {0.0, -0.0, 1e-320, -1e-320, 1e-50, -1e-50, 0.1, -0.1, 1.0 / 3.0, 16777217.0,
                            -16777217.0, 3.4028234663852886e38, 3.4028235677973366e38, 3.5e38, 1e39, -1e39, 1e300,
                            -1e300, inf, -inf, nan};
  Random rng(7);
  for (int i = 0; i < 2000; ++i) {
    const double x = rng.uniform(-1, 1) * std::pow(10.0, rng.uniform(-8, 9));
    xs.push_back(x);
    xs.push_back(static_cast<double>(static_cast<float>(x)));  // exactly a float
  }
  for (const double margin : {0.0, 1.0, 0.3}) {
    for (std::size_t i = 0; i < xs.size(); ++i) {
      const Vector p{xs[i], xs[(i * 7 + 3) % xs.size()]};
      const Rect r{static_cast<int>(i % 50), static_cast<int>(i % 17)};
      const double x0 = p.x - margin, y0 = p.y - margin, x1 = (p.x + r.width) + margin, y1 = (p.y + r.height) + margin;
      const FloatBox b = FloatBox::outward_scalar(x0, y0, x1, y1);
      for (const FloatBox& a : {FloatBox::around(p, r, margin), FloatBox::outward(x0, y0, x1, y1)})
        BOOST_TEST((same(a.min_x, b.min_x) && same(a.min_y, b.min_y) && same(a.max_x, b.max_x) &&
                    same(a.max_y, b.max_y)),
                   "p = (" << p.x << ", " << p.y << "), margin " << margin);
    }
  }
}

BOOST_AUTO_TEST_CASE(the_grid_finds_exactly_the_overlapping_pairs_in_loop_order) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    Random rng(seed);
    const int n = rng.uniform_int(0, 400);
    const double world = rng.uniform(50, 3000);
    std::vector<FloatBox> boxes;
    std::vector<std::uint8_t> fixed;
    random_boxes(rng, n, {-world / 2, world, 30, 0.03, 20}, boxes, fixed);
    UniformGrid grid;
    grid.build(boxes, fixed);
    const auto expected = brute_pairs(boxes, fixed);
    BOOST_TEST(grid.pairs() == expected, "seed " << seed << ": " << grid.pairs().size() << " pairs, brute force "
                                                 << expected.size());
    BOOST_TEST(std::is_sorted(grid.pairs().begin(), grid.pairs().end()));
  }
}

// The grid tests an entry against four others at a time: boxes that only
// touch (closed test), on both sides of zero (-0 and +0 corners), and runs of
// every length from 0 to past 8 entries (stacks of up to 9 boxes on one
// spot) must give the pairs of the all-pairs loop, no more and no fewer.
BOOST_AUTO_TEST_CASE(touching_boxes_and_crowded_cells_find_the_same_pairs_as_all_pairs) {
  Random rng(5);
  std::vector<FloatBox> boxes;
  std::vector<std::uint8_t> fixed;
  for (int y = -6; y <= 6; ++y)
    for (int x = -6; x <= 6; ++x) {
      const int stack = rng.uniform_int(0, 9);
      for (int k = 0; k < stack; ++k) {
        const float x0 = x == 0 && k % 2 ? -0.0f : static_cast<float>(x), y0 = y == 0 && k % 2 ? -0.0f : static_cast<float>(y);
        boxes.push_back(FloatBox{x0, y0, x0 + 1.0f, y0 + 1.0f});  // touches its 8 neighbours' boxes
        fixed.push_back(rng.uniform(0, 1) < 0.1);
      }
    }
  UniformGrid grid;
  grid.build(boxes, fixed);
  const auto expected = brute_pairs(boxes, fixed);
  BOOST_TEST(grid.pairs().size() == expected.size());
  BOOST_TEST(grid.pairs() == expected);
}

// The large boxes' own pairs come from a sweep over them sorted by min_x as
// integer keys: negative, zero (both signs) and positive corners, ties
// included, must give the same pairs as testing every pair.
BOOST_AUTO_TEST_CASE(large_boxes_on_both_sides_of_zero_find_the_same_pairs_as_all_pairs) {
  Random rng(11);
  std::vector<FloatBox> boxes;
  std::vector<std::uint8_t> fixed;
  for (int i = 0; i < 2000; ++i) {  // tiny ones: the mean size that makes the others large
    const auto x = static_cast<float>(rng.uniform(-600, 600)), y = static_cast<float>(rng.uniform(-600, 600));
    boxes.push_back({x, y, x + 0.5f, y + 0.5f});
    fixed.push_back(0);
  }
  const float corners[] = {-0.0f, 0.0f, -1e-30f, 1e-30f, -250.0f, 250.0f};
  for (int i = 0; i < 300; ++i) {
    const float x = i < 60 ? corners[i % 6] : static_cast<float>(rng.uniform(-500, 500));
    const auto y = static_cast<float>(rng.uniform(-500, 500));
    boxes.push_back({x, y, x + static_cast<float>(rng.uniform(60, 120)), y + static_cast<float>(rng.uniform(60, 120))});
    fixed.push_back(rng.uniform(0, 1) < 0.2);
  }
  UniformGrid grid;
  grid.build(boxes, fixed);
  const auto expected = brute_pairs(boxes, fixed);
  BOOST_TEST(grid.large_count() >= 300u);
  BOOST_TEST(expected.size() > 1000u);
  BOOST_TEST((grid.pairs() == expected), grid.pairs().size() << " pairs, brute force " << expected.size());
}

// The grid's passes on a team (more boxes than min_parallel_items, so that
// each pass splits into ranges, of unequal lengths): the same pairs in the
// same order as on one thread and as testing every pair, the same large
// bodies and cells, and the same answers to queries after moves, one of them
// over the whole world (every cell's bodies, in their order). Crowded boxes
// with walls (the pairs' counting sort) and sparse small ones (their
// comparison sort); each grid built twice (the second time on the ranges'
// scratch of the first).
BOOST_AUTO_TEST_CASE(the_grid_on_a_team_finds_the_pairs_of_one_thread) {
  for (const bool crowded : {true, false}) {
    Random rng(crowded ? 3 : 4);
    const double world = crowded ? 600 : 4000;
    std::vector<FloatBox> boxes;
    std::vector<std::uint8_t> fixed;
    random_boxes(rng, 6007, {0, world, crowded ? 20.0 : 3.0, crowded ? 0.03 : 0.0, 10}, boxes, fixed);
    UniformGrid one;
    one.build(boxes, fixed);
    const auto expected = brute_pairs(boxes, fixed);
    BOOST_TEST_REQUIRE((one.pairs() == expected));
    BOOST_TEST((crowded ? expected.size() > 3 * boxes.size() : expected.size() * 32 < boxes.size()),
               expected.size() << " pairs");
    for (const int threads : {2, 3}) {
      Workers team(threads);
      UniformGrid grid;
      for (int build = 0; build < 2; ++build) {
        grid.build(boxes, fixed, &team);
        BOOST_TEST((grid.pairs() == expected), threads << " threads, build " << build << ": " << grid.pairs().size()
                                                       << " pairs, " << expected.size() << " expected");
        BOOST_TEST(grid.large_count() == one.large_count());
        BOOST_TEST(grid.cells() == one.cells());
        BOOST_TEST(same_bits(grid.cell_size(), one.cell_size()));
      }
      // Moves (a large body's box too), then queries: the same bodies reported.
      UniformGrid moved = one;
      for (std::uint32_t i = 0; i < boxes.size(); i += 97) {
        const auto x = static_cast<float>(rng.uniform(0, world)), y = static_cast<float>(rng.uniform(0, world));
        const FloatBox b{x, y, x + 2.0f, y + 2.0f};
        moved.move(i, b), grid.move(i, b);
      }
      for (int q = 0; q <= 200; ++q) {
        const auto x = static_cast<float>(rng.uniform(0, world)), y = static_cast<float>(rng.uniform(0, world));
        const auto whole = static_cast<float>(world);
        const FloatBox box = q == 200 ? FloatBox{0.0f, 0.0f, whole, whole} : FloatBox{x, y, x + 40.0f, y + 40.0f};
        std::vector<std::uint32_t> a, b;
        moved.query(box, [&](std::uint32_t j) { a.push_back(j); });
        grid.query(box, [&](std::uint32_t j) { b.push_back(j); });
        BOOST_TEST_REQUIRE((a == b), "query " << q << ": " << a.size() << " against " << b.size());
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(a_query_after_moves_reports_every_overlapping_box) {
  Random rng(7);
  std::vector<FloatBox> boxes;
  std::vector<std::uint8_t> fixed;
  for (int i = 0; i < 500; ++i) {
    const Vector p{rng.uniform(0, 1000), rng.uniform(0, 1000)};
    boxes.push_back(FloatBox::around(p, {rng.uniform_int(1, 20), rng.uniform_int(1, 20)}, 0.5));
    fixed.push_back(0);
  }
  boxes.push_back(FloatBox::around({0, 0}, {1000, 10}, 0.5));  // a large one
  fixed.push_back(1);
  UniformGrid grid;
  grid.build(boxes, fixed);
  // Move a third of the bodies anywhere, even far outside the grid.
  for (std::uint32_t i = 0; i < boxes.size(); i += 3) {
    const Vector p{rng.uniform(-2000, 3000), rng.uniform(-2000, 3000)};
    boxes[i] = FloatBox::around(p, {rng.uniform_int(1, 20), rng.uniform_int(1, 20)}, 0.5);
    grid.move(i, boxes[i]);
  }
  std::size_t missed = 0, checked = 0;
  for (int q = 0; q < 2000; ++q) {
    const double reach = q % 2 ? 3100 : 1000;  // half of them where most boxes are
    const FloatBox box = FloatBox::around({rng.uniform(-reach + 900, reach), rng.uniform(-reach + 900, reach)},
                                  {rng.uniform_int(1, 150), rng.uniform_int(1, 150)}, 0.5);
    std::vector<std::uint32_t> seen;
    grid.query(box, [&](std::uint32_t j) { seen.push_back(j); });
    for (std::uint32_t j = 0; j < boxes.size(); ++j)
      if (overlap(boxes[j], box)) {
        ++checked;
        missed += std::find(seen.begin(), seen.end(), j) == seen.end();
      }
  }
  BOOST_TEST(checked > 500u);
  BOOST_TEST(missed == 0u);
}

BOOST_AUTO_TEST_CASE(many_large_bodies_find_the_same_pairs_as_all_pairs) {
  // A hundred bodies far above the mean size among a thousand tiny ones:
  // they all leave the grid for the large list, whose own pairs come from a
  // sweep on x (testing them all pairwise was quadratic).
  World w = test::physics_world();
  Game::init_walls(w);
  Random rng(5);
  for (int i = 0; i < 1000; ++i) Block::make(w, rng.uniform(40, 750), rng.uniform(40, 550), 2, 2, test::grey, 1.0);
  for (int i = 0; i < 100; ++i) Block::make(w, rng.uniform(40, 700), rng.uniform(40, 500), 60, 60, test::grey, 1.0);
  const auto pairs = test::course_candidates(w, 1.0);
  std::vector<Pair> expected;
  const auto ids = w.bodies(SystemId::collision);
  const Components& k = w.components;
  for (std::size_t i = 0; i < ids.size(); ++i)
    for (std::size_t j = i + 1; j < ids.size(); ++j) {
      if (!std::isfinite(k.mass[ids[i]]) && !std::isfinite(k.mass[ids[j]])) continue;
      if (overlap(FloatBox::around(k.position[ids[i]], k.box[ids[i]], 1.0), FloatBox::around(k.position[ids[j]], k.box[ids[j]], 1.0)))
        expected.push_back({ids[i], ids[j]});
    }
  BOOST_TEST(w.broadphase.grid().large_count() >= 100u);
  BOOST_TEST(expected.size() > 500u);
  BOOST_TEST((pairs == expected));
}

BOOST_AUTO_TEST_CASE(candidate_pairs_are_the_overlapping_grown_boxes_never_two_infinite_masses) {
  for (const double margin : {0.0, 1.0, 7.5}) {
    World w = make_scene(Spec{.bodies = 300, .fixed_fraction = 0.2, .big_fraction = 0.05, .shuffle = true});
    Systems systems(w);
    const Collision& c = *systems.collision;
    const auto pairs = test::course_candidates(w, margin);
    // Brute force over the registration order, with the same boxes.
    std::vector<Pair> expected;
    const auto ids = c.entities();
    for (std::size_t i = 0; i < ids.size(); ++i)
      for (std::size_t j = i + 1; j < ids.size(); ++j) {
        const Components& k = w.components;
        if (!std::isfinite(k.mass[ids[i]]) && !std::isfinite(k.mass[ids[j]])) continue;
        if (overlap(FloatBox::around(k.position[ids[i]], k.box[ids[i]], margin),
                    FloatBox::around(k.position[ids[j]], k.box[ids[j]], margin)))
          expected.push_back({ids[i], ids[j]});
      }
    BOOST_TEST(pairs.size() == expected.size());
    BOOST_TEST((pairs == expected));
    std::size_t both_fixed = 0;
    for (const auto& [a, b] : pairs) both_fixed += !std::isfinite(w.components.mass[a]) && !std::isfinite(w.components.mass[b]);
    BOOST_TEST(both_fixed == 0u);
  }
  // The walls touch at their corners; they never make a pair.
  World walls = test::physics_world();
  Game::init_walls(walls);
  BOOST_TEST(test::course_candidates(walls, 5.0).empty());
}

BOOST_AUTO_TEST_CASE(sparse_gas_matches_the_all_pairs_loop_bit_for_bit) {
  const Outcome o = compare_with_oracle(Spec{.bodies = 300, .seed = 11}, 300);
  BOOST_TEST(o.contacts > 1000u);  // the comparison is not vacuous
  BOOST_TEST(o.bad_frames == 0u);
  BOOST_TEST(o.bad_bodies == 0u);
}

BOOST_AUTO_TEST_CASE(a_crowded_overlapping_start_matches_the_all_pairs_loop) {
  // 400 blocks thrown into a quarter of the box: corrections push bodies far
  // out of their boxes during the pass, which must be found again.
  for (const double margin : {0.0, 1.0, 4.0}) {
    const Outcome o = compare_with_oracle(
        Spec{.bodies = 400, .spread = 0.25, .speed = 0.1, .margin = margin, .seed = 21}, 150);
    BOOST_TEST(o.requeries > 100u, "margin " << margin << ": the in-pass path ran " << o.requeries << " times");
    BOOST_TEST(o.bad_frames == 0u, "margin " << margin);
    BOOST_TEST(o.bad_bodies == 0u, "margin " << margin);
  }
}

BOOST_AUTO_TEST_CASE(everything_on_one_spot_goes_row_by_row_and_still_matches) {
  // 500 blocks on a 10 px square: most leave their box on the first pass.
  const Outcome o = compare_with_oracle(Spec{.bodies = 500, .spread = 0.01, .speed = 0.0, .seed = 5}, 40);
  BOOST_TEST(o.by_rows > 0u);
  BOOST_TEST(o.bad_frames == 0u);
  BOOST_TEST(o.bad_bodies == 0u);
}

BOOST_AUTO_TEST_CASE(row_by_row_matches_with_fixed_big_moving_and_shuffled_bodies) {
  // Every kind of body the grid treats apart, piled on one spot, so that the
  // pass goes row by row in its first frames: fixed blocks (never a pair of
  // two), big ones (kept out of the grid's cells), moving ones (the first
  // body of a pair is pushed too and its row looked up again), shuffled
  // registration, and margins 0 and 4.
  const Spec specs[] = {
      Spec{.bodies = 400, .spread = 0.02, .speed = 0.5, .fixed_fraction = 0.1, .shuffle = true, .seed = 41},
      Spec{.bodies = 350, .spread = 0.03, .min_side = 2, .max_side = 9, .speed = 1.0, .big_fraction = 0.05,
           .gravity = {0.0, 0.001}, .margin = 0.0, .seed = 42},
      Spec{.bodies = 300, .spread = 0.0, .min_side = 20, .max_side = 20, .speed = 0.0, .margin = 4.0, .seed = 43},
  };
  for (const Spec& s : specs) {
    const Outcome o = compare_with_oracle(s, 60);
    BOOST_TEST(o.by_rows > 0u, "seed " << s.seed);
    BOOST_TEST(o.contacts > 1000u, "seed " << s.seed);
    BOOST_TEST(o.bad_frames == 0u, "seed " << s.seed);
    BOOST_TEST(o.bad_bodies == 0u, "seed " << s.seed);
  }
}

BOOST_AUTO_TEST_CASE(gravity_static_blocks_big_blocks_and_shuffled_registration_match) {
  const Vector g{0.0, 0.001};
  const Spec specs[] = {
      Spec{.bodies = 300, .spread = 0.6, .gravity = g, .seed = 31},
      Spec{.bodies = 250, .spread = 0.5, .fixed_fraction = 0.15, .gravity = g, .shuffle = true, .seed = 32},
      Spec{.bodies = 200, .spread = 0.7, .min_side = 1, .max_side = 12, .speed = 1.0, .big_fraction = 0.04,
           .gravity = g, .margin = 0.25, .shuffle = true, .seed = 33},
      Spec{.bodies = 300, .spread = 1.0, .min_side = 2, .max_side = 6, .speed = 3.0, .seed = 34},  // fast, tunnels
  };
  for (const Spec& s : specs) {
    const Outcome o = compare_with_oracle(s, 200);
    BOOST_TEST(o.contacts > 500u, "seed " << s.seed);
    BOOST_TEST(o.bad_frames == 0u, "seed " << s.seed);
    BOOST_TEST(o.bad_bodies == 0u, "seed " << s.seed);
  }
}

BOOST_AUTO_TEST_CASE(changes_between_passes_are_seen) {
  // A body teleported, resized or made fixed between two passes: the
  // broadphase keeps no state across passes, so it sees them.
  World w = test::physics_world();
  const auto a = Block::make(w, 100, 100, 20, 20, test::grey, 1.0);
  const auto b = Block::make(w, 500, 500, 20, 20, test::grey, 1.0);
  test::collide(w);
  BOOST_TEST(w.pass.contact_count == 0u);
  w.components.position[b.id] = {110, 110};
  test::collide(w);
  BOOST_TEST(w.pass.contact_count == 1u);
  w.components.position[b.id] = {125, 100};
  w.components.box[a.id] = {30, 20};
  test::collide(w);
  BOOST_TEST(w.pass.contact_count == 1u);
  w.components.mass[a.id] = w.components.mass[b.id] = infinity;
  w.components.position[b.id] = {110, 100};
  BOOST_TEST(test::course_candidates(w, 0.0).empty());
  test::collide(w);
  BOOST_TEST(w.pass.contact_count == 0u);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_broadphase
