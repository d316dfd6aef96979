// The determinism scenes and their state hash, shared by tests/test_determinism.cpp
// (which holds the committed hashes) and the WebAssembly build's check
// (web/main.cpp, `make web-test`: the same bits under Node and in a browser).
// Physics systems only, no Draw, as a headless run has.
#pragma once

#include <cstdint>
#include <cstring>

#include "course/game.hpp"
#include "course/system_defs.hpp"
#include "course/utils/random.hpp"

namespace physics::determinism {

inline constexpr Color grey{128, 128, 128, 255};

// 1 000 blocks of 10 px on a 40×25 grid in a 1200×900 walled box, random
// masses and velocities (seed 2026), e = 1 for half of them and 0.5 for the others.
inline World thousand_bodies() {
  World w(SystemSet{false, true, true, true}, Params{});
  Game::init_walls(w, 1200, 900);
  Random rng(2026);
  for (int i = 0; i < 1000; ++i) {
    const double x = 60 + 27.0 * (i % 40) + rng.uniform(0, 8);
    const double y = 60 + 31.0 * (i / 40) + rng.uniform(0, 8);
    const auto b = Block::make(w, x, y, 10, 10, grey, rng.uniform(1, 5), i % 2 ? 1.0 : 0.5);
    w.components.velocity[b.id] = {rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3)};
  }
  return w;
}

// FNV-1a over the bytes of every position and velocity, in entity order.
inline std::uint64_t state_hash(const Components& c) {
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
inline World pyramid(Params p, int base) {
  p.gravity = {0.0, 0.001};
  World w(SystemSet{false, true, true, true}, p);
  Game::init_walls(w, 800, 600, 0.0);
  for (int i = 0; i < base; ++i)
    for (int j = i; j < base; ++j)
      Block::make(w, 400 - 10.0 * base + 10.0 * i + 20.0 * (j - i), 560 - 20.0 * (i + 1), 20, 20, grey,
                  1.0 + (i % 8), 0.0);
  return w;
}

// The thousand bodies, with every numerics mode.
inline World thousand_bodies(Params p) {
  World w = thousand_bodies();
  w.params = p;
  return w;
}

// Every mode of the step, pinned (test_determinism.cpp: the committed hashes
// in this order): 200 frames of the gas, 300 of a pyramid of base 12.
struct Mode {
  const char* name;
  bool ccd;
  Solver solver;
  int substeps;
  Params params() const {
    Params p;
    p.ccd = ccd;
    p.solver = solver;
    p.substeps = substeps;
    return p;
  }
};
inline constexpr Mode modes[] = {{"course", false, Solver::course, 1},
                                 {"substeps4", false, Solver::course, 4},
                                 {"ccd", true, Solver::course, 1},
                                 {"stable", false, Solver::stable, 1},
                                 {"stable+ccd", true, Solver::stable, 2}};
inline constexpr int gas_frames = 200, pyramid_frames = 300, pyramid_base = 12;
// The course solver's state after 1 000 frames of the gas (thousand_bodies()).
inline constexpr int long_frames = 1000;

}  // namespace physics::determinism
