// Queries (engine/query.hpp): hand-computed rays, boxes and points, then the
// grid-accelerated answers against testing every body, on random scenes with
// the awkward cases (axis rays along edges, rays from inside or from a face,
// zero and huge distances, far origins, touching regions, NaN bodies).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

#include "engine/query.hpp"
#include "course/game.hpp"
#include "helpers.hpp"
#include "course/utils/random.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_query {

using namespace physics;

namespace {

using physics::test::same_bits;

bool same(const std::optional<RayHit>& a, const std::optional<RayHit>& b) {
  if (a.has_value() != b.has_value()) return false;
  return !a || (a->body == b->body && same_bits(a->point, b->point) && same_bits(a->normal, b->normal) &&
                same_bits(a->fraction, b->fraction));
}

// The definitions, testing every body.
std::optional<RayHit> brute_ray(const World& w, Vector o, Vector dir, double dist) {
  const Vector travel = ray_travel(o, dir, dist);
  std::optional<RayHit> best;
  for (const EntityId e : query_bodies(w)) {
    const auto hit = ray_hit(o, travel, e, w.components.position[e], w.components.box[e]);
    if (hit && (!best || hit->fraction < best->fraction || (hit->fraction == best->fraction && hit->body < best->body)))
      best = hit;
  }
  return best;
}

std::vector<EntityId> brute_box(const World& w, Vector lo, Vector hi) {
  std::vector<EntityId> out;
  for (const EntityId e : query_bodies(w))
    if (overlaps_region(w.components.position[e], w.components.box[e], lo, hi)) out.push_back(e);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<EntityId> brute_point(const World& w, Vector p) {
  std::vector<EntityId> out;
  for (const EntityId e : query_bodies(w))
    if (contains_point(w.components.position[e], w.components.box[e], p)) out.push_back(e);
  std::sort(out.begin(), out.end());
  return out;
}

// An 800x600 walled world with the given blocks (fixed, so nothing moves).
World walled(std::initializer_list<std::array<double, 4>> blocks) {
  World w = test::physics_world();
  Game::init_walls(w, 800, 600);
  for (const auto& [x, y, bw, bh] : blocks)
    Block::make(w, x, y, static_cast<int>(bw), static_cast<int>(bh), test::grey, infinity);
  return w;
}

// A random scene: blocks of 2-40 px (some 8x5 times larger), half of them on
// a 10 px lattice so that edges line up and touch, overlapping at will,
// registered in a shuffled order; `collision` false: no Collision system
// (queries then see every entity).
World random_scene(std::uint64_t seed, int bodies, bool collision = true) {
  World w(SystemSet{false, true, true, collision});
  Game::init_walls(w, 800, 600);
  Random rng(seed);
  for (int n = 0; n < bodies; ++n) {
    int bw = rng.uniform_int(2, 40), bh = rng.uniform_int(2, 40);
    if (rng.uniform(0, 1) < 0.05) bw *= 8, bh *= 5;
    double x = rng.uniform(40, 760 - bw), y = rng.uniform(40, 560 - bh);
    if (rng.uniform(0, 1) < 0.5) x = 10 * std::floor(x / 10), y = 10 * std::floor(y / 10), bw = bh = 10 * (1 + bw % 4);
    Block::make(w, x, y, bw, bh, test::grey, 1.0);
  }
  if (collision) {
    Systems systems(w);
    Collision& c = *systems.collision;
    for (EntityId e = 0; e < w.components.size(); ++e)
      if (rng.uniform(0, 1) < 0.3) c.unregister(e), c.register_entity(Block::t{e});
  }
  return w;
}

// A point of interest of a random body in view (not one set at NaN or far
// away): a corner, an edge's middle, its centre.
Vector feature(const World& w, Random& rng) {
  EntityId e;
  do {
    e = static_cast<EntityId>(rng.uniform_int(0, static_cast<int>(w.components.size()) - 1));
  } while (!(std::abs(w.components.position[e].x) < 1e6 && std::abs(w.components.position[e].y) < 1e6));
  const Vector p = w.components.position[e];
  const Rect r = w.components.box[e];
  const double fx[] = {0.0, 0.5, 1.0};
  return {p.x + fx[rng.uniform_int(0, 2)] * r.width, p.y + fx[rng.uniform_int(0, 2)] * r.height};
}

// One random ray of a mix of kinds; checks index, free function and brute
// force agree. Returns whether it hit.
bool check_ray(const World& w, const QueryIndex& index, Random& rng) {
  Vector o{rng.uniform(-100, 900), rng.uniform(-100, 700)};
  Vector d{rng.uniform(-1, 1), rng.uniform(-1, 1)};
  double dist = rng.uniform(0, 1200);
  const Vector axes[] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  switch (rng.uniform_int(0, 8)) {
    case 0: d = axes[rng.uniform_int(0, 3)]; break;                        // along an axis
    case 1: o = feature(w, rng), d = axes[rng.uniform_int(0, 3)]; break;   // along an edge, or from a face
    case 2: o = feature(w, rng); break;                                    // from inside or a corner
    case 3: dist = 0.0; break;
    case 4: o = {rng.uniform(-1e6, 1e6), rng.uniform(-1e6, 1e6)}, d = Vector{400, 300} - o, dist = 3e6; break;
    case 5: dist = 1e12; break;
    case 6: d = feature(w, rng) - o; break;                                // aimed at a corner or an edge
    case 7:                                                                // a hair beside one
      d = feature(w, rng) + Vector{rng.uniform(-1e-12, 1e-12), rng.uniform(-1e-12, 1e-12)} - o;
      dist = Vector::norm(d) * rng.uniform(0.999, 1.001);
      break;
    default: d = {d.x * 1e-200, d.y * 1e-200}; break;                      // tiny, not unit
  }
  const auto want = brute_ray(w, o, d, dist);
  const auto got = index.ray_cast(o, d, dist);
  BOOST_TEST(same(got, want), "ray from (" << o.x << ", " << o.y << ") along (" << d.x << ", " << d.y << ") over "
                                           << dist);
  if (want) {
    BOOST_TEST(want->fraction >= 0.0);
    BOOST_TEST(want->fraction <= 1.0);
  }
  return want.has_value();
}

}  // namespace

BOOST_AUTO_TEST_SUITE(query)

BOOST_AUTO_TEST_CASE(a_ray_straight_down_hits_the_floor) {
  const World w = walled({});
  const auto hit = ray_cast(w, {400, 100}, {0, 1}, 1000);
  BOOST_TEST_REQUIRE(hit.has_value());
  BOOST_TEST(hit->body == 1u);  // the bottom wall, whose top is y = 560
  BOOST_TEST(hit->point.x == 400.0);
  BOOST_TEST(hit->point.y == 560.0);
  BOOST_TEST((hit->normal == Vector{0, -1}));
  BOOST_TEST(hit->fraction == 0.46);  // 460 px of 1000
  // The direction need not be unit: (0, 5) is the same ray.
  BOOST_TEST(same(ray_cast(w, {400, 100}, {0, 5}, 1000), hit));
  // Too short to reach it.
  BOOST_TEST(!ray_cast(w, {400, 100}, {0, 1}, 459.5).has_value());
  // Exactly long enough: entered at fraction 1.
  BOOST_TEST(ray_cast(w, {400, 100}, {0, 1}, 460)->fraction == 1.0);
}

BOOST_AUTO_TEST_CASE(each_face_gives_its_outward_normal) {
  const World w = walled({{100, 100, 40, 40}});
  const EntityId b = 4;
  const auto left = ray_cast(w, {60, 120}, {2, 0}, 80);  // not unit
  BOOST_TEST_REQUIRE(left.has_value());
  BOOST_TEST(left->body == b);
  BOOST_TEST((left->point == Vector{100, 120}));
  BOOST_TEST((left->normal == Vector{-1, 0}));
  BOOST_TEST(left->fraction == 0.5);
  BOOST_TEST((ray_cast(w, {200, 130}, {-1, 0}, 100)->normal == Vector{1, 0}));
  BOOST_TEST((ray_cast(w, {200, 130}, {-1, 0}, 100)->point == Vector{140, 130}));
  BOOST_TEST((ray_cast(w, {110, 300}, {0, -1}, 400)->normal == Vector{0, 1}));
  BOOST_TEST((ray_cast(w, {110, 300}, {0, -1}, 400)->point == Vector{110, 140}));
  // Diagonal, entering exactly through the corner: x wins the tie, as in CCD.
  const auto corner = ray_cast(w, {50, 50}, {1, 1}, 100);
  BOOST_TEST_REQUIRE(corner.has_value());
  BOOST_TEST((corner->normal == Vector{-1, 0}));
  BOOST_TEST(corner->point.x == 100.0);  // on the face; along it, up to rounding
  BOOST_TEST(std::abs(corner->point.y - 100.0) < 1e-12);
  BOOST_TEST(std::abs(corner->fraction - std::sqrt(2.0) / 2.0) < 1e-15);
}

BOOST_AUTO_TEST_CASE(grazing_an_edge_or_a_corner_is_no_hit) {
  const World w = walled({{100, 100, 40, 40}});
  // Along the top edge y = 100, then along the left edge x = 100: open interiors, no hit.
  BOOST_TEST(ray_cast(w, {60, 100}, {1, 0}, 800)->body == 3u);  // the right wall, far behind
  BOOST_TEST(ray_cast(w, {100, 60}, {0, 1}, 600)->body == 1u);   // the floor
  // Through the corner (100, 100) without going in.
  BOOST_TEST(!ray_cast(w, {60, 140}, {1, -1}, 40 * std::sqrt(2.0) + 10).has_value());
}

BOOST_AUTO_TEST_CASE(a_ray_from_inside_a_body_ignores_it_and_from_its_face_enters_it) {
  const World w = walled({{100, 100, 40, 40}, {200, 100, 40, 40}});
  const auto out = ray_cast(w, {120, 120}, {1, 0}, 200);
  BOOST_TEST_REQUIRE(out.has_value());
  BOOST_TEST(out->body == 5u);  // the next one, not the one it starts in (as Box2D)
  BOOST_TEST(out->point.x == 200.0);
  // From a face, inwards: entered at once; outwards: not at all.
  const auto in = ray_cast(w, {120, 100}, {0, 1}, 10);
  BOOST_TEST_REQUIRE(in.has_value());
  BOOST_TEST(in->body == 4u);
  BOOST_TEST(in->fraction == 0.0);
  BOOST_TEST(!std::signbit(in->fraction));
  BOOST_TEST((in->normal == Vector{0, -1}));
  BOOST_TEST(!ray_cast(w, {120, 100}, {0, -1}, 50).has_value());
  // Zero distance or direction: nothing is entered.
  BOOST_TEST(!ray_cast(w, {120, 100}, {0, 1}, 0).has_value());
  BOOST_TEST(!ray_cast(w, {60, 120}, {0, 0}, 100).has_value());
}

BOOST_AUTO_TEST_CASE(ties_go_to_the_lowest_id) {
  // Two overlapping blocks with the same top, registered in the other order.
  World w = walled({{100, 100, 40, 40}, {110, 100, 20, 20}});
  Systems systems(w);
  Collision& c = *systems.collision;
  c.unregister(4);
  c.register_entity(Block::t{4});
  BOOST_TEST(c.entities().back() == 4u);
  const auto hit = ray_cast(w, {120, 50}, {0, 1}, 100);
  BOOST_TEST_REQUIRE(hit.has_value());
  BOOST_TEST(hit->body == 4u);
  BOOST_TEST(hit->fraction == 0.5);
}

BOOST_AUTO_TEST_CASE(boxes_and_points_count_open_interiors_in_id_order) {
  const World w = walled({{100, 100, 40, 40}, {140, 100, 40, 40}, {300, 300, 10, 10}});
  using Ids = std::vector<EntityId>;
  // Touching is not overlapping (as in Collision): a region beside a body misses it.
  BOOST_TEST((query_box(w, {180, 100}, {250, 140}) == Ids{}));
  BOOST_TEST((query_box(w, {179.5, 100}, {250, 140}) == Ids{5}));
  BOOST_TEST((query_box(w, {120, 120}, {320, 320}) == Ids{4, 5, 6}));
  BOOST_TEST((query_box(w, {0, 0}, {800, 600}) == Ids{0, 1, 2, 3, 4, 5, 6}));
  BOOST_TEST((query_box(w, {120, 120}, {120, 120}) == Ids{4}));  // a point
  BOOST_TEST((query_point(w, {120, 120}) == Ids{4}));
  BOOST_TEST((query_point(w, {140, 120}) == Ids{}));  // on the shared edge: in neither
  BOOST_TEST((query_point(w, {20, 20}) == Ids{0}));   // in the top wall
  BOOST_TEST((query_point(w, {400, 300}) == Ids{}));
}

BOOST_AUTO_TEST_CASE(bad_input_throws) {
  const World w = walled({});
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = infinity;
  BOOST_CHECK_THROW(ray_cast(w, {nan, 0}, {1, 0}, 10), std::invalid_argument);
  BOOST_CHECK_THROW(ray_cast(w, {0, 0}, {inf, 0}, 10), std::invalid_argument);
  BOOST_CHECK_THROW(ray_cast(w, {0, 0}, {1, 0}, -1), std::invalid_argument);
  BOOST_CHECK_THROW(ray_cast(w, {0, 0}, {1, 0}, inf), std::invalid_argument);
  BOOST_CHECK_THROW(query_box(w, {10, 0}, {0, 10}), std::invalid_argument);
  BOOST_CHECK_THROW(query_box(w, {0, 0}, {nan, 10}), std::invalid_argument);
  BOOST_CHECK_THROW(query_point(w, {0, inf}), std::invalid_argument);
  // A huge direction is fine: its length is not overflowed.
  BOOST_TEST(ray_cast(w, {400, 100}, {0, 1e308}, 1000)->fraction == 0.46);
  BOOST_TEST(same(ray_cast(w, {400, 300}, {1e308, 1e308}, 1000), ray_cast(w, {400, 300}, {1, 1}, 1000)));
}

BOOST_AUTO_TEST_CASE(the_index_answers_as_testing_every_body) {
  for (const std::uint64_t seed : {1u, 2u, 3u, 4u, 5u}) {
    const World w = random_scene(seed, seed == 5 ? 2000 : 150 + 50 * static_cast<int>(seed), seed != 4);
    const QueryIndex index(w);
    Random rng(seed * 7919);
    int hits = 0;
    for (int i = 0; i < 600; ++i) hits += check_ray(w, index, rng);
    BOOST_TEST(hits > 200);  // the rays do meet bodies
    std::size_t found = 0;
    for (int i = 0; i < 300; ++i) {
      Vector lo{rng.uniform(-50, 850), rng.uniform(-50, 650)};
      if (i % 3 == 0) lo = feature(w, rng);  // a region starting on a body's edge or corner
      const Vector size = i % 5 == 0 ? Vector{} : Vector{rng.uniform(0, 200), rng.uniform(0, 200)};
      const auto want = brute_box(w, lo, lo + size);
      found += want.size();
      BOOST_TEST((index.query_box(lo, lo + size) == want));
      const Vector p = i % 2 ? feature(w, rng) : lo;
      BOOST_TEST((index.query_point(p) == brute_point(w, p)));
    }
    BOOST_TEST(found > 300u);
  }
  // The free functions are the index's.
  const World w = random_scene(9, 200);
  BOOST_TEST(same(ray_cast(w, {50, 50}, {3, 2}, 900), QueryIndex(w).ray_cast({50, 50}, {3, 2}, 900)));
  BOOST_TEST((query_box(w, {100, 100}, {300, 200}) == brute_box(w, {100, 100}, {300, 200})));
  BOOST_TEST((query_point(w, {300, 300}) == brute_point(w, {300, 300})));
}

// Odd worlds: empty, a body at NaN (found by nothing), one beyond float range
// (rays then test every body), one far away (a long, thin grid).
BOOST_AUTO_TEST_CASE(odd_worlds_answer_as_testing_every_body) {
  const World empty = test::physics_world();
  BOOST_TEST(!ray_cast(empty, {0, 0}, {1, 1}, 100).has_value());
  BOOST_TEST(query_box(empty, {0, 0}, {10, 10}).empty());
  for (const double odd : {std::numeric_limits<double>::quiet_NaN(), 1e39, 5e6}) {
    World w = random_scene(11, 300);
    w.components.position[7] = {odd, 200};
    const QueryIndex index(w);
    Random rng(13);
    for (int i = 0; i < 300; ++i) check_ray(w, index, rng);
    for (int i = 0; i < 100; ++i) {
      const Vector p = feature(w, rng);
      BOOST_TEST((index.query_point(p) == brute_point(w, p)));
      BOOST_TEST((index.query_box(p - Vector{30, 30}, p) == brute_box(w, p - Vector{30, 30}, p)));
    }
    const auto far = index.ray_cast({0, 210}, {1, 0}, 1e7);
    BOOST_TEST(same(far, brute_ray(w, {0, 210}, {1, 0}, 1e7)));
  }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_query
