#include "app/course_world.hpp"

#include <algorithm>
#include <array>

namespace physics::CourseWorld {

namespace {

// The seed of the scene's random entry (many's ten squares; --seed moves it).
std::uint64_t seed_of(const SceneSpec& s) {
  for (const BlockEntry& e : s.blocks)
    if (const auto* r = std::get_if<RandomSpec>(&e)) return r->seed;
  return 42;
}

// What the sheet's main program calls for each scene, in the sheet's order.
void build(World& w, const SceneSpec& s) {
  const std::string_view name = s.name;
  if (name == "many") return Game::init_scene(w, seed_of(s));  // walls included (Q9)
  Game::init_walls(w, s.width, s.height, s.restitution);        // Q1
  if (name == "drift") Game::red_block_with_velocity(w);        // Q4
  if (name == "impulse") Game::red_block_with_force(w);         // Q5
  if (name == "bounce") {                                        // Q8's test: a platform in the red block's way
    Game::red_block_with_velocity(w);
    Block::make(w, 300, 300, 80, 20, default_block_color, infinity);
  }
}

}  // namespace

std::span<const std::string_view> scenes() {
  static constexpr std::array<std::string_view, 5> names{"walls", "drift", "impulse", "bounce", "many"};
  return names;
}

bool builds(std::string_view scene) { return std::ranges::find(scenes(), scene) != scenes().end(); }

World make(const SceneSpec& s, const std::vector<Body>& bodies, bool with_draw) {
  if (!builds(s.name)) return make_world(s, bodies, with_draw);
  World w = empty_world(s, with_draw);
  build(w, s);
  watch(w, s, Game::wall_count);
  return w;
}

}  // namespace physics::CourseWorld
