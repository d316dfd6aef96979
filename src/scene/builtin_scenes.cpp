#include "scene/builtin_scenes.hpp"

#include <vector>

namespace physics {
namespace {

constexpr Color red{255, 0, 0, 255};

SystemSet systems(bool draw, bool forces, bool move, bool collision) { return {draw, forces, move, collision}; }

// The red square of questions 4 and 5: 40×40, mass 10, at (100, 100).
BlockSpec red_block() {
  BlockSpec b;
  b.pos = {100, 100};
  b.width = b.height = 40;
  b.mass = 10.0;
  b.color = red;
  return b;
}

SceneSpec base(const char* name, const char* description, SystemSet set) {
  SceneSpec s;
  s.name = name;
  s.description = description;
  s.systems = set;
  return s;
}

std::vector<SceneSpec> make_all() {
  std::vector<SceneSpec> all;

  all.push_back(base("walls", "Q1: the four walls, nothing moves (Draw only)", systems(true, false, false, false)));

  {
    SceneSpec s = base("drift", "Q4: the red block with velocity (0.25, 0.25) drifts through the walls (Draw+Move)",
                       systems(true, false, true, false));
    BlockSpec b = red_block();
    b.velocity = {0.25, 0.25};
    s.blocks.push_back(b);
    all.push_back(s);
  }
  {
    SceneSpec s = base("impulse", "Q5: a force (0.25, 0.25) on the first frame sets it moving, Δv = f·dt/m ≈ 0.42 px/ms (Draw+Move+Forces)",
                       systems(true, true, true, false));
    BlockSpec b = red_block();
    b.force = {0.25, 0.25};
    s.blocks.push_back(b);
    all.push_back(s);
  }
  {
    // The README's example file: the red block and a fixed platform.
    SceneSpec s = base("bounce", "Q8: the red block bounces off the walls and a fixed platform (all systems)",
                       systems(true, true, true, true));
    BlockSpec b = red_block();
    b.velocity = {0.25, 0.25};
    b.restitution = 1.0;
    s.blocks.push_back(b);
    BlockSpec platform;
    platform.pos = {300, 300};
    platform.width = 80;
    platform.height = 20;
    platform.mass = infinity;
    s.blocks.push_back(platform);
    all.push_back(s);
  }
  {
    // Q9, Game::init_scene: the red block set going by a force, and ten
    // squares of random side, mass and impulse on a 5×2 grid of cells.
    SceneSpec s = base("many", "Q9: the red block and ten random squares, varied masses and impulses (the default)",
                       systems(true, true, true, true));
    BlockSpec b = red_block();
    b.force = {0.25, 0.25};
    s.blocks.push_back(b);
    RandomSpec r;
    r.count = 10;
    r.seed = 42;
    r.side = IntSpec::uniform(20, 40);
    r.mass = RealSpec::uniform(1.0, 20.0);
    r.impulse = {RealSpec::uniform(0.0, 0.25), RealSpec::uniform(0.0, 0.25)};
    r.use_cells = true;
    r.origin = {180, 220};
    r.columns = 5;
    r.step = {110, 150};
    r.jitter = {50, 80};
    s.blocks.push_back(r);
    all.push_back(s);
  }
  {
    // Equal masses, e = 1: each impulse hands the whole velocity on.
    SceneSpec s = base("cradle", "a row of five touching equal blocks hit from the left by a sixth",
                       systems(true, true, true, true));
    BlockSpec striker;
    striker.pos = {150, 280};
    striker.width = striker.height = 40;
    striker.mass = 5.0;
    striker.velocity = {0.3, 0.0};
    striker.color = red;
    s.blocks.push_back(striker);
    GridSpec row;
    row.first.pos = {400, 280};
    row.first.width = row.first.height = 40;
    row.first.mass = 5.0;
    row.first.color = {70, 130, 180, 255};
    row.columns = 5;
    row.rows = 1;
    row.step = {40, 0};
    s.blocks.push_back(row);
    all.push_back(s);
  }
  {
    // 300 small blocks of random mass and velocity in cells of a 20×15 grid
    // (36×34 px cells, 8 px blocks, jitter keeps them apart), e = 1, no gravity:
    // the kinetic energy stays constant.
    SceneSpec s = base("gas", "300 small blocks, e = 1, no gravity: an ideal gas in a box", systems(true, true, true, true));
    RandomSpec r;
    r.count = 300;
    r.seed = 42;
    r.width = r.height = IntSpec::fixed(8);
    r.mass = RealSpec::uniform(1.0, 3.0);
    r.velocity = {RealSpec::uniform(-0.2, 0.2), RealSpec::uniform(-0.2, 0.2)};
    r.use_cells = true;
    r.origin = {44, 44};
    r.columns = 20;
    r.step = {36, 34};
    r.jitter = {24, 22};
    s.blocks.push_back(r);
    all.push_back(s);
  }
  {
    // Three towers of five touching blocks on the floor, under gravity;
    // e = 0 so that nothing bounces. With the course's one-pass solver the
    // towers settle by small position corrections; `--solver stable` is the
    // iterated solver meant for resting contact.
    SceneSpec s = base("stack", "three towers of five blocks resting on the floor under gravity (e = 0)",
                       systems(true, true, true, true));
    s.params.gravity = {0.0, 0.001};
    s.restitution = 0.0;
    GridSpec g;
    g.first.pos = {200, 520};
    g.first.width = g.first.height = 40;
    g.first.mass = 1.0;
    g.first.color = {205, 133, 63, 255};
    g.columns = 3;
    g.rows = 5;
    g.step = {180, -40};
    s.blocks.push_back(g);
    all.push_back(s);
  }
  return all;
}

}  // namespace

std::span<const SceneSpec> builtin_scenes() {
  // Built once, never changed: a constant table, not mutable global state.
  static const std::vector<SceneSpec> all = make_all();
  return all;
}

const SceneSpec* find_builtin(std::string_view name) {
  for (const SceneSpec& s : builtin_scenes())
    if (s.name == name) return &s;
  return nullptr;
}

}  // namespace physics
