// Determinism: the same scene gives the same bits, run after run and at every
// optimisation level (-ffp-contract=off pins the arithmetic; see Makefile).
#include <cstdint>
#include <cstring>

#include "game.hpp"
#include "helpers.hpp"
#include "utils/random.hpp"

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

}  // namespace

BOOST_AUTO_TEST_SUITE(determinism)

// The committed hash of the course solver's state after 1 000 frames. It
// changes only when the physics changes on purpose: update it in the same
// commit, and say why in the message.
constexpr std::uint64_t expected_hash = 0xdc7570f975dd5853;

BOOST_AUTO_TEST_CASE(thousand_bodies_thousand_frames_match_the_committed_hash) {
  World w = thousand_bodies();
  for (int f = 0; f < 1000; ++f) w.step();
  const std::uint64_t h = state_hash(w.components);
  BOOST_TEST_MESSAGE("state hash after 1000 frames: " << std::hex << h);
  BOOST_TEST(h == expected_hash, std::hex << "state hash 0x" << h << " != committed 0x" << expected_hash);
}

BOOST_AUTO_TEST_CASE(two_runs_in_one_process_are_identical) {
  World a = thousand_bodies(), b = thousand_bodies();
  for (int f = 0; f < 100; ++f) a.step(), b.step();
  BOOST_TEST(state_hash(a.components) == state_hash(b.components));
  BOOST_TEST(state_hash(a.components) != state_hash(thousand_bodies().components));  // it moved
}

BOOST_AUTO_TEST_SUITE_END()
