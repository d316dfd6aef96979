// A box falls on a floor; the program prints where it rests (docs/api.md).
#include <cstdio>
#include <physics/physics.hpp>

int main() {
  physics::WorldDef def = physics::default_world_def();
  def.gravity = {0.0, 0.001};  // px/ms², y grows downwards
  def.solver = physics::SolverKind::stable;
  const physics::WorldId world = physics::create_world(def);

  physics::BodyDef floor = physics::default_body_def();
  floor.position = {0, 560};  // top-left corner, px
  floor.size = {800, 40};
  floor.mass = physics::fixed_mass;
  physics::create_body(world, floor);

  physics::BodyDef box = physics::default_body_def();
  box.position = {380, 100};
  box.size = {40, 40};
  box.restitution = 0.0;
  const physics::BodyId body = physics::create_body(world, box);

  for (int frame = 0; frame < 600; ++frame) physics::step(world);  // 600 frames of 1000/60 ms
  const physics::Vec2 p = physics::position(body);
  std::printf("the box rests at (%.1f, %.1f)\n", p.x, p.y);
  physics::destroy_world(world);
}
