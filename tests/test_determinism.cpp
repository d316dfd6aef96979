// Determinism: the same scene gives the same bits, run after run and at every
// optimisation level (-ffp-contract=off pins the arithmetic; see Makefile).
#include <cstdint>
#include <cstring>

#include "course/game.hpp"
#include "helpers.hpp"
#include "course/utils/random.hpp"

using namespace physics;

namespace {

// 1 000 blocks of 10 px on a 40×25 grid in a 1200×900 walled box, random
// masses and velocities (seed 2026), e = 1 for half of them and 0.5 for the others.
World thousand_bodies() {
  World w = test::physics_world();
  Game::init_walls(w, 1200, 900);
  Random rng(2026);
  for (int i = 0; i < 1000; ++i) {
    const double x = 60 + 27.0 * (i % 40) + rng.uniform(0, 8);
    const double y = 60 + 31.0 * (i / 40) + rng.uniform(0, 8);
    const auto b = Block::make(w, x, y, 10, 10, test::grey, rng.uniform(1, 5), i % 2 ? 1.0 : 0.5);
    w.components.velocity[b.id] = {rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3)};
  }
  return w;
}

// FNV-1a over the bytes of every position and velocity, in entity order.
std::uint64_t state_hash(const Components& c) {
  std::uint64_t h = 1469598103934665603ULL;
  const auto eat = [&](double d) {
    std::uint64_t bits;
    std::memcpy(&bits, &d, sizeof bits);
    for (int k = 0; k < 8; ++k) {
      h ^= (bits >> (8 * k)) & 0xff;
      h *= 1099511628211ULL;
    }
  };
  for (std::size_t e = 0; e < c.size(); ++e) {
    eat(c.position[e].x), eat(c.position[e].y);
    eat(c.velocity[e].x), eat(c.velocity[e].y);
  }
  return h;
}

// A pyramid of `base` blocks of 20 px (rows resting on the row below), on the
// floor of an 800x600 walled box, under gravity, e = 0; masses vary from row to
// row (1 to 8) so that the solvers' inverse-mass arithmetic is exercised.
World pyramid(Params p, int base) {
  p.gravity = {0.0, 0.001};
  World w = test::physics_world(p);
  Game::init_walls(w, 800, 600, 0.0);
  for (int i = 0; i < base; ++i)
    for (int j = i; j < base; ++j)
      Block::make(w, 400 - 10.0 * base + 10.0 * i + 20.0 * (j - i), 560 - 20.0 * (i + 1), 20, 20, test::grey,
                  1.0 + (i % 8), 0.0);
  return w;
}

// The thousand bodies, with every numerics mode.
World thousand_bodies(Params p) {
  World w = thousand_bodies();
  w.params = p;
  return w;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(determinism)

// Every mode of the step, pinned: the course/engine refactors keep each of
// these bit for bit (each changes only when the physics changes on purpose).
BOOST_AUTO_TEST_CASE(every_mode_matches_its_committed_hash) {
  struct Mode {
    const char* name;
    bool ccd;
    Solver solver;
    int substeps;
  };
  const Mode modes[] = {{"course", false, Solver::course, 1},
                        {"substeps4", false, Solver::course, 4},
                        {"ccd", true, Solver::course, 1},
                        {"stable", false, Solver::stable, 1},
                        {"stable+ccd", true, Solver::stable, 2}};
  const std::uint64_t gas_expected[] = {0x5f248445610fae3a, 0x0c55b02b12fe19f9, 0x17b938cfe7291bb3,
                                        0xbfde053c475ab5ee, 0x580261c5525decd7};
  const std::uint64_t pyramid_expected[] = {0x3e9fe4fbc824f79b, 0x577198b89071b8ed, 0x74b5f444c4b1585f,
                                            0x6931aeb91119510b, 0x6931aeb91119510b};
  for (std::size_t m = 0; m < std::size(modes); ++m) {
    Params p;
    p.ccd = modes[m].ccd;
    p.solver = modes[m].solver;
    p.substeps = modes[m].substeps;
    World gas = thousand_bodies(p);
    for (int f = 0; f < 200; ++f) Game::step(gas);
    World pile = pyramid(p, 12);
    for (int f = 0; f < 300; ++f) Game::step(pile);
    const std::uint64_t hg = state_hash(gas.components), hp = state_hash(pile.components);
    BOOST_TEST_MESSAGE(modes[m].name << std::hex << " gas 0x" << hg << " pyramid 0x" << hp);
    BOOST_TEST(hg == gas_expected[m], modes[m].name << std::hex << ": gas hash 0x" << hg);
    BOOST_TEST(hp == pyramid_expected[m], modes[m].name << std::hex << ": pyramid hash 0x" << hp);
  }
}


// The committed hash of the course solver's state after 1 000 frames. It
// changes only when the physics changes on purpose: update it in the same
// commit, and say why in the message.
constexpr std::uint64_t expected_hash = 0xdc7570f975dd5853;

BOOST_AUTO_TEST_CASE(thousand_bodies_thousand_frames_match_the_committed_hash) {
  World w = thousand_bodies();
  for (int f = 0; f < 1000; ++f) Game::step(w);
  const std::uint64_t h = state_hash(w.components);
  BOOST_TEST_MESSAGE("state hash after 1000 frames: " << std::hex << h);
  BOOST_TEST(h == expected_hash, std::hex << "state hash 0x" << h << " != committed 0x" << expected_hash);
}

BOOST_AUTO_TEST_CASE(two_runs_in_one_process_are_identical) {
  World a = thousand_bodies(), b = thousand_bodies();
  for (int f = 0; f < 100; ++f) Game::step(a), Game::step(b);
  BOOST_TEST(state_hash(a.components) == state_hash(b.components));
  BOOST_TEST(state_hash(a.components) != state_hash(thousand_bodies().components));  // it moved
}

BOOST_AUTO_TEST_SUITE_END()
