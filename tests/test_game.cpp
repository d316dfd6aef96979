// Q8-Q9: whole scenes, headless.
#include "app/headless.hpp"
#include "helpers.hpp"

using namespace physics;

namespace {

void check_inside_walls(const World& w) {
  const Components& c = w.components;
  for (std::size_t e = 0; e < c.size(); ++e) {
    if (!std::isfinite(c.mass[e])) continue;
    const Vector p = c.position[e];
    BOOST_TEST_REQUIRE(std::isfinite(p.x));
    BOOST_TEST_REQUIRE(std::isfinite(p.y));
    BOOST_TEST_REQUIRE(std::isfinite(c.velocity[e].x));
    BOOST_TEST_REQUIRE(std::isfinite(c.velocity[e].y));
    // The block's centre stays in the space the walls enclose.
    const double cx = p.x + c.box[e].width / 2.0, cy = p.y + c.box[e].height / 2.0;
    BOOST_TEST_REQUIRE(cx > 40.0);
    BOOST_TEST_REQUIRE(cx < 760.0);
    BOOST_TEST_REQUIRE(cy > 40.0);
    BOOST_TEST_REQUIRE(cy < 560.0);
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(q8_bounce)

BOOST_AUTO_TEST_CASE(the_red_block_bounces_off_the_walls_keeping_its_speed) {
  World w = test::physics_world();
  Game::init_walls(w);
  const auto red = Block::make(w, 100, 100, 40, 40, Color{255, 0, 0, 255}, 10.0);
  w.components.sum_forces[red.id] = {0.25, 0.25};
  Game::step(w);
  const double ke = w.kinetic_energy();
  int reversals = 0;
  double last_vx = w.components.velocity[red.id].x;
  for (int i = 0; i < 3000; ++i) {
    Game::step(w);
    if (w.components.velocity[red.id].x != last_vx) ++reversals;
    last_vx = w.components.velocity[red.id].x;
    check_inside_walls(w);
  }
  BOOST_TEST(reversals > 10);
  BOOST_TEST(w.kinetic_energy() == ke);  // wall reversals are exact
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(q9_scene)

BOOST_AUTO_TEST_CASE(the_default_scene_has_walls_and_varied_mobile_blocks) {
  World w;
  Game::init_scene(w);
  BOOST_TEST(w.components.size() == 15u);
  BOOST_TEST(w.finite_bodies() == 11u);
  // No overlap at start, varied masses and sizes.
  for (EntityId a = 0; a < w.components.size(); ++a)
    for (EntityId b = a + 1; b < w.components.size(); ++b) BOOST_TEST(!test::overlaps(w.components, a, b));
  double mmin = 1e9, mmax = 0;
  int smin = 1 << 30, smax = 0;
  for (EntityId e = 4; e < w.components.size(); ++e) {
    mmin = std::min(mmin, w.components.mass[e]);
    mmax = std::max(mmax, w.components.mass[e]);
    smin = std::min(smin, w.components.box[e].width);
    smax = std::max(smax, w.components.box[e].width);
    BOOST_TEST(!Vector::is_zero(w.components.sum_forces[e]));
  }
  BOOST_TEST(mmax - mmin > 5.0);
  BOOST_TEST(smax > smin);
}

BOOST_AUTO_TEST_CASE(ten_thousand_frames_stay_inside_the_walls_without_nan) {
  World w = test::physics_world();
  Game::init_scene(w);
  Game::step(w);
  const double ke0 = w.kinetic_energy();
  std::size_t contacts = 0;
  for (int i = 0; i < 10000; ++i) {
    Game::step(w);
    contacts += w.pass.contact_count;
    check_inside_walls(w);
  }
  BOOST_TEST(contacts > 100u);  // it really collides
  // e = 1 everywhere: every impulse keeps the kinetic energy.
  BOOST_TEST(std::abs(w.kinetic_energy() - ke0) <= 1e-9 * ke0);
}

BOOST_AUTO_TEST_CASE(the_scene_is_reproducible_for_a_seed) {
  World a = test::physics_world(), b = test::physics_world(), c = test::physics_world();
  Game::init_scene(a, 7);
  Game::init_scene(b, 7);
  Game::init_scene(c, 8);
  for (int i = 0; i < 500; ++i) Game::step(a), Game::step(b), Game::step(c);
  BOOST_TEST((a.components.position == b.components.position));
  BOOST_TEST((a.components.velocity == b.components.velocity));
  BOOST_TEST(!(a.components.position == c.components.position));
}

BOOST_AUTO_TEST_CASE(headless_summary_reports_the_run) {
  World w = test::physics_world();
  Game::init_scene(w);
  const auto s = Headless::run(w, 120);
  BOOST_TEST(s.frames == 120);
  BOOST_TEST(s.bodies == 15u);
  BOOST_TEST(s.mobile == 11u);
  BOOST_TEST(s.ke_start > 0.0);
  std::ostringstream out;
  Headless::print_summary(out, w, s, "test");
  BOOST_TEST(out.str().find("ran headless") != std::string::npos);
  BOOST_TEST(out.str().find("physics ms/step") != std::string::npos);
  BOOST_TEST(w.times.steps == 120);
}

BOOST_AUTO_TEST_SUITE_END()
