#include "course/game.hpp"

#include "course/system_defs.hpp"
#include "course/utils/random.hpp"
#include "engine/step.hpp"

namespace physics::Game {

void init_walls(World& w, int width, int height, double e) {
  // Q1 begin
  // Q1 stub: // TODO Q1: create four walls (Block::make), one on each edge of the width x height screen:
  // Q1 stub: // the horizontal ones blue (wall_blue) and as long as the screen, the vertical ones black
  // Q1 stub: // (wall_black) between them, all wall_thickness (40 px) thick, not overlapping, of mass
  // Q1 stub: // `infinity` (Q2) and restitution e.
  // Q1 stub: (void)w, (void)width, (void)height, (void)e;
  const int t = wall_thickness;
  Block::make(w, 0, 0, width, t, wall_blue, infinity, e);                    // top
  Block::make(w, 0, height - t, width, t, wall_blue, infinity, e);           // bottom
  Block::make(w, 0, t, t, height - 2 * t, wall_black, infinity, e);          // left
  Block::make(w, width - t, t, t, height - 2 * t, wall_black, infinity, e);  // right
  // Q1 end
}

Block::t red_block(World& w) { return Block::make(w, 100, 100, 40, 40, red, 10.0); }

Block::t red_block_with_velocity(World& w) {
  const Block::t b = red_block(w);
  // Q4 begin
  // Q4 stub: // TODO Q4: give the red block b the velocity (0.25, 0.25) (component velocity).
  w.components.velocity[b.id] = {0.25, 0.25};
  // Q4 end
  return b;
}

Block::t red_block_with_force(World& w) {
  const Block::t b = red_block(w);
  // Q5 begin
  // Q5 stub: // TODO Q5: instead of a velocity, apply to the red block b the force (0.25, 0.25)
  // Q5 stub: // (component sum_forces): Forces turns it into the same velocity on the first frame.
  w.components.sum_forces[b.id] = {0.25, 0.25};
  // Q5 end
  return b;
}

void init_scene(World& w, std::uint64_t seed) {
  w.components.reserve(w.components.size() + 15);
  init_walls(w);
  red_block_with_force(w);
  // Q9 begin
  // Q9 stub: // TODO Q9: add other mobile blocks with different initial conditions: ten squares
  // Q9 stub: // with a random side in [20, 40], a random mass in [1, 20) and a random first
  // Q9 stub: // force in [0, 0.25) per axis (use Random rng(seed), utils/random.hpp), placed so
  // Q9 stub: // that no two blocks overlap, and check that the collisions are right.
  // Q9 stub: (void)seed;
  // Ten squares on a 5×2 grid of 110×150 px cells, each at a random place in
  // its cell, with a random side, mass, colour and first impulse J (the
  // force J/dt on the first frame changes the velocity by J/m).
  Random rng(seed);
  for (int i = 0; i < 10; ++i) {
    const int side = rng.uniform_int(20, 40);
    const double mass = rng.uniform(1.0, 20.0);
    const double jx = rng.uniform(0.0, 0.25);
    const double jy = rng.uniform(0.0, 0.25);
    Color color;
    color.r = static_cast<std::uint8_t>(rng.uniform_int(40, 220));
    color.g = static_cast<std::uint8_t>(rng.uniform_int(40, 220));
    color.b = static_cast<std::uint8_t>(rng.uniform_int(40, 220));
    double x = 180.0 + 110.0 * (i % 5), y = 220.0 + 150.0 * (i / 5);
    x = x + rng.uniform(0.0, 50.0);
    y = y + rng.uniform(0.0, 80.0);
    const Block::t b = Block::make(w, x, y, side, side, away_from_walls(color), mass);
    w.components.sum_forces[b.id] = Vector::mult(1.0 / w.params.dt, {jx, jy});
  }
  // Q9 end
}

// The engine's frame (engine/step.hpp: the substeps, the numerics stages,
// events, health) with the course's systems as its stages.
void step(World& w) {
  Systems s(w);
  run_frame(
      w, [&](double h) { s.forces->update(w.components, h, w.params.gravity); },
      [&](double h) { s.move->update(w.components, h); },
      [&] { s.collision->update(w.components, w.course_pairs()); });
}

void draw(const World& w, Canvas& canvas) {
  if (const auto* bodies = w.stage(SystemId::draw)) Draw(*bodies).update(w.components, canvas);
}

}  // namespace physics::Game
