// Determinism: the same scene gives the same bits, run after run and at every
// optimisation level (-ffp-contract=off pins the arithmetic; see Makefile).
#include <cstdint>

#include "determinism_world.hpp"
#include "helpers.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_determinism {

using namespace physics;
using namespace physics::determinism;

BOOST_AUTO_TEST_SUITE(determinism)

// Every mode of the step, pinned: the course/engine refactors keep each of
// these bit for bit (each changes only when the physics changes on purpose:
// the stable gas with the exact solve of small free islands, engine/island_solve.hpp).
BOOST_AUTO_TEST_CASE(every_mode_matches_its_committed_hash) {
  const std::uint64_t gas_expected[] = {0x5f248445610fae3a, 0x0c55b02b12fe19f9, 0x17b938cfe7291bb3,
                                        0xb04375a73ce64273, 0x580261c5525decd7};
  const std::uint64_t pyramid_expected[] = {0x3e9fe4fbc824f79b, 0x577198b89071b8ed, 0xe1df9e9c6fdb7a94,
                                            0x6931aeb91119510b, 0x6931aeb91119510b};
  for (std::size_t m = 0; m < std::size(modes); ++m) {
    const Params p = modes[m].params();
    World gas = thousand_bodies(p);
    for (int f = 0; f < gas_frames; ++f) Game::step(gas);
    World pile = pyramid(p, pyramid_base);
    for (int f = 0; f < pyramid_frames; ++f) Game::step(pile);
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
  for (int f = 0; f < long_frames; ++f) Game::step(w);
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

}  // namespace test_determinism
