// Tile layers (engine/tiles.hpp; docs/game-physics.md, "Tile layers"): a
// box slides over a floor of 1000 tiles at every speed and in every solver
// as over one flat body, rests on tiles, passes one-way tiles from below and
// lands on them from above, and stops at a wall of tiles where it hits it.
// Each case against its closed form.
#include <malloc.h>

#include <string>

#include "helpers.hpp"
#include "engine/query.hpp"
#include "numerics/scenes.hpp"
#include "physics/physics.hpp"
#include "scene/scene_json.hpp"
#include "app/testbed.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_tiles {

using namespace physics;
using namespace physics::numerics;

namespace {

const Mode course{"course", 1, false, Solver::course, 8};
const Mode stable{"stable", 1, false, Solver::stable, 8};
const Mode automatic{"auto", 1, false, Solver::automatic, 8};
const Mode modes[] = {course, stable, automatic};

constexpr double g = 0.001;

// A grid of `columns` x `rows` cells of 16 px, all of kind t.
TileGrid filled(int columns, int rows, Tile t) {
  TileGrid grid{16, columns, rows, {}};
  grid.cells.assign(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows), static_cast<std::uint8_t>(t));
  return grid;
}

// The grid of rows like "#..=", '#' solid, '=' one-way, '.' empty.
TileGrid drawn(std::initializer_list<std::string> rows) {
  TileGrid grid{16, static_cast<int>(rows.begin()->size()), static_cast<int>(rows.size()), {}};
  for (const std::string& r : rows)
    for (const char ch : r)
      grid.cells.push_back(static_cast<std::uint8_t>(ch == '#' ? Tile::solid : ch == '=' ? Tile::one_way_up : Tile::empty));
  return grid;
}

// Bodies the solvers see that are alive (the scene's), as a dump lists them.
std::size_t alive_count(const World& w) {
  std::size_t n = 0;
  for (EntityId e = 0; e < w.components.size(); ++e) n += w.alive(e);
  return n;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(tiles)

// A floor of 1000 cells, its top at y = 200, and a 20 x 20 box resting on it
// at x = 7 sliding at v: x = 7 + v t at every frame as on one body
// (frictionless), y = 180 throughout. Tiles of 16 px: at 10 px/ms the box crosses ten seams a frame.
BOOST_AUTO_TEST_CASE(a_box_slides_over_a_floor_of_1000_tiles_at_every_speed_in_every_solver) {
  for (const Mode& m : modes)
    for (const double v : {0.01, 0.1, 1.0, 10.0}) {
      World w = make_world(m, {0, g});
      w.add_tile_layer({0, 200}, filled(1000, 2, Tile::solid));
      const EntityId s = block(w, 7, 180, 20, 20, 1.0, {v, 0}, 0.0);
      const int frames = std::min(600, static_cast<int>(15000 / (v * course_dt)));
      double worst_x = 0, worst_y = 0;
      for (int f = 1; f <= frames; ++f) {
        Game::step(w);
        worst_x = std::max(worst_x, std::abs(w.components.position[s].x - (7 + v * course_dt * f)));
        worst_y = std::max(worst_y, std::abs(w.components.position[s].y - 180));
      }
      BOOST_TEST_CONTEXT(m.name << " at " << v << " px/ms, " << frames << " frames") {
        // Rounding only (measured: 6e-11 px at most); 1000 blocks of 16 px
        // instead catch the course pass's box at 0.01 px/ms by 1 px.
        BOOST_TEST(worst_x < 1e-6);
        BOOST_TEST(worst_y < 0.05);
        BOOST_TEST(w.components.velocity[s].x == v);
      }
    }
}

// Dropped from 40 px above, the box rests on the tiles: overlap below 1 px
// (the stable solver's slop, the course's g h² a step at most), at rest.
BOOST_AUTO_TEST_CASE(a_box_dropped_on_tiles_rests_on_them) {
  for (const Mode& m : modes) {
    World w = make_world(m, {0, g});
    w.add_tile_layer({0, 200}, filled(50, 3, Tile::solid));
    const EntityId s = block(w, 100, 140, 30, 20, 2.0, {}, 0.0);
    double deepest = 0;
    for (int f = 0; f < 300; ++f) {
      Game::step(w);
      if (f > 60) deepest = std::max(deepest, w.components.position[s].y + 20 - 200);
    }
    BOOST_TEST_CONTEXT(m.name) {
      BOOST_TEST(deepest < 1.0);
      BOOST_TEST(std::abs(w.components.position[s].y - 180) < 1.0);
      BOOST_TEST(std::abs(w.components.velocity[s].y) < 2 * g * course_dt);
      BOOST_TEST(w.components.position[s].x == 100);
    }
  }
}

// One-way cells: thrown up from below, the box passes through them, falls
// back and lands on their top; dropped from above, it stays on top.
BOOST_AUTO_TEST_CASE(one_way_tiles_pass_from_below_and_hold_from_above) {
  for (const Mode& m : modes) {
    for (const bool below : {true, false}) {
      World w = make_world(m, {0, g});
      w.add_tile_layer({0, 200}, filled(50, 1, Tile::one_way_up));
      const EntityId s = below ? block(w, 100, 260, 20, 20, 1.0, {0, -0.6}, 0.0) : block(w, 100, 120, 20, 20, 1.0, {}, 0.0);
      double highest = 1e9;
      for (int f = 0; f < 400; ++f) Game::step(w), highest = std::min(highest, w.components.position[s].y);
      BOOST_TEST_CONTEXT(m.name << (below ? " from below" : " from above")) {
        if (below) BOOST_TEST(highest < 180.0);  // it went through
        BOOST_TEST(std::abs(w.components.position[s].y - 180) < 1.0);
        BOOST_TEST(std::abs(w.components.velocity[s].y) < 2 * g * course_dt);
      }
    }
  }
}

// A wall of tiles, one column 40 cells high at x = 400: a box thrown at it
// across a seam between two of its cells (y = 108: rows 6 and 7) stops with
// its right side on the wall, y unchanged (no gravity: nothing else moves it).
BOOST_AUTO_TEST_CASE(a_wall_of_tiles_stops_a_box_without_pushing_it_along_the_seam) {
  for (const Mode& m : modes)
    for (const double v : {0.1, 1.0, 5.0}) {
      World w = make_world(m);
      w.add_tile_layer({400, 0}, filled(1, 40, Tile::solid));
      const EntityId s = block(w, 300, 108, 20, 20, 1.0, {v, 0}, 0.0);
      for (int f = 0; f < 120; ++f) Game::step(w);
      BOOST_TEST_CONTEXT(m.name << " at " << v << " px/ms") {
        BOOST_TEST(std::abs(w.components.position[s].x - 380) < 1.0);
        BOOST_TEST(w.components.position[s].y == 108);
        BOOST_TEST(w.components.velocity[s].y == 0);
        BOOST_TEST(w.components.velocity[s].x <= 1e-9);
      }
    }
}

// A box pushed along a floor into a wall of tiles standing on it (a corner)
// stops at the wall and stays on the floor.
BOOST_AUTO_TEST_CASE(a_box_slides_into_a_corner_of_tiles_and_stays_on_the_floor) {
  for (const Mode& m : modes) {
    World w = make_world(m, {0, g});
    w.add_tile_layer({0, 0}, drawn({"..........#", "..........#", "..........#", "###########", "###########"}));
    const EntityId s = block(w, 20, 28, 20, 20, 1.0, {0.5, 0}, 0.0);
    for (int f = 0; f < 200; ++f) Game::step(w);
    BOOST_TEST_CONTEXT(m.name) {
      BOOST_TEST(std::abs(w.components.position[s].x - 140) < 1.0);
      BOOST_TEST(std::abs(w.components.position[s].y - 28) < 0.05);
    }
  }
}

// Strips: a floor is one strip along its top; a platform one cell thick is
// one box for its top and bottom; a lone cell one box; one-way cells only
// their top, where nothing is above them.
BOOST_AUTO_TEST_CASE(strips_merge_runs_of_exposed_faces) {
  const TileLayer floor(0, filled(1000, 2, Tile::solid));
  BOOST_TEST(floor.strip_count() == 4u);  // top, bottom, the two ends (two cells high)
  const TileLayer lone(0, drawn({"...", ".#.", "..."}));
  BOOST_TEST(lone.strip_count() == 1u);
  BOOST_TEST(lone.runs() == 4u);  // its four faces, twins
  const TileLayer platform(0, drawn({"....", ".##.", "...."}));
  BOOST_TEST(platform.strip_count() == 3u);  // top and bottom (one box), the two ends
  const TileLayer one_way(0, drawn({"==", "=="}));
  BOOST_TEST(one_way.strip_count() == 1u);
  std::vector<Strip> found;
  one_way.near(0, 0, 32, 32, [&](std::uint32_t, const Strip& s) { found.push_back(s); });
  BOOST_TEST(found.size() == 1u);
  BOOST_TEST(found[0].one_way);
  BOOST_TEST(found[0].row == 0);
}

// A 1000 x 1000 map is its 1 MB of cells, and a box on it makes proxies for
// the few strips near it only: what a step costs does not grow with the map.
BOOST_AUTO_TEST_CASE(a_large_map_makes_proxies_only_near_the_bodies) {
  TileGrid grid = filled(1000, 1000, Tile::empty);
  for (int r = 0; r < 1000; r += 10)
    for (int c = 0; c < 1000; ++c) grid.cells[static_cast<std::size_t>(r) * 1000 + static_cast<std::size_t>(c)] = 1;
  World w = make_world(stable, {0, g});
  w.add_tile_layer({0, 0}, grid);
  BOOST_TEST(w.tiles.layers()[0].grid().cells.size() == 1'000'000u);
  const EntityId s = block(w, 5000, 120, 20, 20, 1.0, {0.3, 0}, 0.0);
  for (int f = 0; f < 120; ++f) Game::step(w);
  BOOST_TEST(w.tiles.proxy_count() <= 4u);
  BOOST_TEST(std::abs(w.components.position[s].y - 140) < 0.05);
  BOOST_TEST(alive_count(w) == 2u);  // the layer and the box: proxies are not bodies
}

// What a map costs beyond its cells: 8 bytes a run (the bench's map of
// 2 500 walled rooms, as bench/scenes.cpp draws it), proxies made only where
// bodies go. The heap is glibc's count (mallinfo2); a sanitizer's allocator
// reports none, and then only the counts are checked.
BOOST_AUTO_TEST_CASE(a_map_costs_its_cells_and_8_bytes_a_run) {
  TileGrid grid = filled(1000, 1000, Tile::empty);
  for (int r = 0; r < 1000; ++r)
    for (int c = 0; c < 1000; ++c) {
      const int rr = r % 20, cc = c % 20;
      const bool wall = rr == 0 || rr == 19 || cc == 0 || cc == 19, ledge = rr == 12 && cc >= 6 && cc < 14;
      grid.cells[static_cast<std::size_t>(r) * 1000 + static_cast<std::size_t>(c)] = wall || ledge;
    }
  const auto heap = [] { const struct mallinfo2 m = mallinfo2(); return m.uordblks + m.hblkhd; };
  const std::size_t before = heap();
  const TileLayer layer(0, std::move(grid));
  const std::size_t grown = heap() - before;
  BOOST_TEST(layer.strip_count() == 17'504u);
  BOOST_TEST(layer.runs() <= 1.25 * layer.strip_count());  // twins: the ledges' tops and bottoms
  // The runs, 4 lines of offsets a side, a page pointer per 256 runs.
  BOOST_TEST(grown <= 8 * layer.runs() + 4 * 4 * 1001 + 24 * (layer.runs() / 256 + 1) + 4096);
}

// A layer may cover the walls: neither its body nor its proxies count as
// bodies that escaped the space the walls enclose.
BOOST_AUTO_TEST_CASE(tiles_never_count_as_escaped) {
  World w = make_world(course, {0, g});
  w.health.watch(40, 40, 760, 560, 0);
  w.add_tile_layer({0, 560}, filled(50, 2, Tile::solid));  // under the bottom wall's top
  const EntityId s = block(w, 100, 500, 20, 20, 1.0, {}, 0.0);
  for (int f = 0; f < 30 * Health::escape_period; ++f) Game::step(w);
  w.health.count_escapes(w.components, w.frame);
  BOOST_TEST(w.tiles.proxy_count() >= 1u);
  BOOST_TEST(std::abs(w.components.position[s].y - 540) < 0.05);
  BOOST_TEST(w.health.escaped == 0);
}

// Random maps of solid and one-way cells, 60 random boxes thrown in (random
// sizes, masses, restitutions, velocities): after 600 frames every value is
// finite, and with the stable solver (alone or in auto) no box lies in a
// solid cell deeper than its slop (the course pass lets piles sink, as on blocks).
BOOST_AUTO_TEST_CASE(random_maps_hold_random_boxes) {
  for (const Mode& m : modes)
    for (std::uint64_t seed = 100; seed < 105; ++seed) {
      Random rng(seed);
      World w = make_world(m, {0, g});
      TileGrid grid = filled(50, 40, Tile::empty);
      for (int r = 0; r < 40; ++r)
        for (int c = 0; c < 50; ++c) {
          const bool border = r == 39 || c == 0 || c == 49;
          const bool cell = border || (r > 5 && rng.next() % 7 == 0);
          if (cell) grid.cells[static_cast<std::size_t>(r * 50 + c)] = static_cast<std::uint8_t>(!border && rng.next() % 3 == 0 ? 2 : 1);
        }
      w.add_tile_layer({0, 0}, grid);
      std::vector<EntityId> boxes;
      for (int i = 0; i < 60; ++i) {
        const double x = rng.uniform(20, 760), y = rng.uniform(0, 80);
        const int bw = rng.uniform_int(6, 19), bh = rng.uniform_int(6, 19);
        const double mass = rng.uniform(1, 5), e = rng.uniform(0, 1);
        boxes.push_back(block(w, x, y, bw, bh, mass, {rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5)}, e));
      }
      for (int f = 0; f < 600; ++f) Game::step(w);
      BOOST_TEST_CONTEXT(m.name << ", seed " << seed) {
        BOOST_TEST(all_finite(w));
        const QueryIndex q(w);
        double deepest = 0;
        for (const EntityId b : boxes) {
          const Vector p = w.components.position[b];
          const Vector size{double(w.components.box[b].width), double(w.components.box[b].height)};
          for (const TileCellHit& h : q.cells_meeting(p, p + size)) {
            if (h.cell.kind != Tile::solid) continue;
            const double x0 = 16.0 * h.cell.column, y0 = 16.0 * h.cell.row;
            const double ox = std::min(p.x + size.x, x0 + 16) - std::max(p.x, x0);
            const double oy = std::min(p.y + size.y, y0 + 16) - std::max(p.y, y0);
            deepest = std::max(deepest, std::min(ox, oy));
          }
        }
        if (m.solver != Solver::course) BOOST_TEST(deepest < 0.0101);
      }
    }
}

// The testbed: a click over a layer's empty cells spawns (the layer's box is
// not what collides), one on a solid cell does not; the ray names the cell.
BOOST_AUTO_TEST_CASE(the_testbed_spawns_over_tiles_and_its_ray_names_the_cell) {
  const SceneSpec s = parse_scene(R"({ "world": { "walls": false },
      "tiles": [ { "pos": [0, 200], "cell": 40, "rows": ["....", "####"] } ] })", "t.json");
  Testbed tb({s}, 0, {}, {});
  const std::size_t n = tb.world().components.size();
  BOOST_TEST(tb.spawn({60, 220}, {}));  // in the layer's box, over an empty cell
  BOOST_TEST(tb.world().components.size() == n + 1);
  BOOST_TEST(!tb.spawn({100, 260}, {}));  // on a solid cell
  tb.handle(InputEvent{InputEvent::Kind::mouse_down, 0, 130, 100, 3});
  tb.handle(InputEvent{InputEvent::Kind::mouse_move, 0, 130, 300, 0});
  const View v = tb.view(60, 0);
  const auto line = [](const std::string& l) { return l.starts_with("ray: body 0 cell (3, 1) at (130.0, 240.0)"); };
  BOOST_TEST(std::count_if(v.hud.begin(), v.hud.end(), line) == 1);
}

BOOST_AUTO_TEST_CASE(bad_grids_are_refused_with_one_line) {
  World w = make_world(course);
  TileGrid bad = filled(4, 2, Tile::solid);
  bad.cells[5] = 7;
  BOOST_CHECK_EXCEPTION(w.add_tile_layer({}, bad), std::invalid_argument, [](const std::invalid_argument& e) {
    return std::string(e.what()) == "unknown tile kind 7 at column 1, row 1 (0 empty, 1 solid, 2 one-way up)";
  });
  TileGrid small = filled(4, 2, Tile::solid);
  small.cells.pop_back();
  BOOST_CHECK_THROW(w.add_tile_layer({}, small), std::invalid_argument);
  BOOST_CHECK_THROW(w.add_tile_layer({}, filled(70000, 1, Tile::solid)), std::invalid_argument);
  TileGrid zero = filled(4, 2, Tile::solid);
  zero.cell = 0;
  BOOST_CHECK_THROW(w.add_tile_layer({}, zero), std::invalid_argument);
  BOOST_TEST(w.components.size() == 0u);
}

// Swept against tiles with no code of its own: a box falling at 3 px/ms (50
// px a frame) onto a floor one cell (16 px) thick goes through it without
// CCD and lands on it with CCD, in the course pass and in auto.
BOOST_AUTO_TEST_CASE(ccd_sweeps_bodies_against_tiles) {
  const Mode course_ccd{"course+ccd", 1, true, Solver::course, 8};
  for (const Mode& m : {course, course_ccd, automatic}) {
    World w = make_world(m);
    w.add_tile_layer({0, 400}, filled(40, 1, Tile::solid));
    const EntityId s = block(w, 100, 355, 10, 10, 1.0, {0, 3.0}, 0.0);
    for (int f = 0; f < 30; ++f) Game::step(w);
    BOOST_TEST_CONTEXT(m.name) {
      if (m.ccd || m.solver == Solver::automatic) BOOST_TEST(std::abs(w.components.position[s].y - 390) < 0.05);
      else BOOST_TEST(w.components.position[s].y > 416);  // through it
    }
  }
}

// Contact events name the layer's body, once per touch of the layer, never a proxy.
BOOST_AUTO_TEST_CASE(contact_events_name_the_layer) {
  for (const Mode& m : modes) {
    World w = make_world(m, {0, g});
    w.enable_events();
    const EntityId s = block(w, 30, 150, 20, 20, 1.0, {}, 0.0);
    const EntityId layer = w.add_tile_layer({0, 200}, drawn({"...#", "####"}));
    int begins = 0;
    for (int f = 0; f < 120; ++f) {
      Game::step(w);
      for (const ContactEvent& e : w.events.events()) {
        BOOST_TEST(e.a == s);
        BOOST_TEST(e.b == layer);
        begins += e.kind == EventKind::begin;
      }
    }
    BOOST_TEST_CONTEXT(m.name) {
      BOOST_TEST(begins == 1);
      BOOST_TEST(w.events.touching().size() == 1u);
    }
  }
}

// A scene file's "tiles": the layer is made after the blocks, the blocks
// land on it, and bad rows, sizes and characters give one line each.
BOOST_AUTO_TEST_CASE(a_scene_file_with_tiles_loads_and_bad_rows_give_one_line) {
  const auto scene = [](const std::string& tiles) {
    return R"({ "world": { "walls": false, "gravity": [0, 0.001], "restitution": 0 },
                "blocks": [ { "pos": [40, 100], "size": [20, 20], "mass": 1 } ],
                "tiles": [ )" + tiles + " ] }";
  };
  const SceneSpec s = parse_scene(scene(R"({ "pos": [0, 300], "cell": 20, "rows": ["....", "#=##"] })"), "t.json");
  World w = make_world(s, false);
  BOOST_TEST(w.tiles.layers().size() == 1u);
  BOOST_TEST(w.tiles.layers()[0].body() == 1u);
  BOOST_TEST(w.components.box[1].width == 80);
  for (int f = 0; f < 200; ++f) Game::step(w);
  BOOST_TEST(std::abs(w.components.position[0].y - 300) < 0.05);  // on the one-way cell of the second row
  const std::pair<std::string, std::string> bad[] = {
      {R"({ "pos": [0, 0], "rows": ["#x."] })", "t.json: tiles[0].rows[0]: unknown tile 'x' at column 1 ('#' solid, '=' one-way up, '.' empty)"},
      {R"({ "pos": [0, 0], "rows": ["##", "###"] })", "t.json: tiles[0].rows[1]: has 3 cells, rows[0] 2 (every row the same length)"},
      {R"({ "pos": [0, 0], "rows": [] })", "t.json: tiles[0].rows: must be a non-empty array of strings (got an array)"},
      {R"({ "pos": [0, 0], "cell": 0, "rows": ["#"] })", "t.json: tiles[0].cell: must be > 0 (got 0)"},
      {R"({ "pos": [700, 0], "cell": 40, "rows": ["####"] })",
       "t.json: tiles[0]: the layer (160 x 40 px at [700, 0]) must lie inside the world (800 x 600)"},
      {R"({ "rows": ["#"] })", "t.json: tiles[0]: missing key \"pos\" ([x, y], px)"},
  };
  for (const auto& [tiles, message] : bad) {
    std::string got;
    try {
      parse_scene(scene(tiles), "t.json");
    } catch (const SceneError& e) {
      got = e.what();
    }
    BOOST_TEST(got == message);
  }
}

// The public API: a layer is a body (listed, fixed, its size the grid's),
// its cells readable; proxies are never listed; a bad def is refused.
BOOST_AUTO_TEST_CASE(the_api_makes_tile_layers) {
  WorldDef def = default_world_def();
  def.gravity = {0, g};
  def.solver = SolverKind::stable;
  const WorldId world = create_world(def);
  TileLayerDef t;
  t.position = {0, 200};
  t.columns = 3, t.rows = 1;
  t.cells = {TileKind::solid, TileKind::one_way_up, TileKind::solid};
  const BodyId layer = create_tile_layer(world, t);
  BodyDef b = default_body_def();
  b.position = {5, 150};
  b.restitution = 0;
  const BodyId box = create_body(world, b);
  for (int f = 0; f < 120; ++f) step(world);
  BOOST_TEST(std::abs(position(box).y - 190) < 0.05);
  BOOST_TEST(bodies(world).size() == 2u);
  BOOST_TEST(is_tile_layer(layer));
  BOOST_TEST(!is_tile_layer(box));
  BOOST_TEST(size(layer).x == 48);
  BOOST_TEST(mass(layer) == fixed_mass);
  BOOST_TEST((tile_at(layer, 1, 0) == TileKind::one_way_up));
  BOOST_TEST((tile_at(layer, 5, 0) == TileKind::empty));
  BOOST_CHECK_THROW(tile_at(box, 0, 0), Error);
  BOOST_CHECK_THROW(set_size(layer, {10, 10}), Error);
  // Saved and restored with the world: the run from the state repeats.
  const WorldState saved = save_state(world);
  for (int f = 0; f < 30; ++f) step(world);
  const Vec2 after = position(box);
  restore_state(world, saved);
  for (int f = 0; f < 30; ++f) step(world);
  BOOST_TEST((position(box) == after));
  const auto hit = ray_cast(world, {20, 0}, {0, 1}, 400);  // past the box, onto the one-way cell
  BOOST_TEST_REQUIRE(hit.has_value());
  BOOST_TEST((hit->body == layer));
  BOOST_TEST(hit->column == 1);
  BOOST_TEST(query_tiles(world, {{0, 199}, {40, 201}}).size() == 3u);
  destroy_body(layer);  // its cells go with it: the box falls
  for (int f = 0; f < 30; ++f) step(world);
  BOOST_TEST(position(box).y > 200);
  BOOST_TEST(bodies(world).size() == 1u);
  t.cells.pop_back();
  BOOST_CHECK_EXCEPTION(create_tile_layer(world, t), Error, [](const Error& e) {
    return std::string(e.what()) == "bad TileLayerDef: a tile layer of 3 x 1 cells needs 3 cells (got 2)";
  });
  destroy_world(world);
}

// Rays against a layer give, from outside its solid cells, exactly what rays
// against one block per solid cell give (the same sweep), and name the cell;
// one-way cells stop rays coming down only; box and point queries meet
// open cells. Random layers and rays, against the blocks' answers.
BOOST_AUTO_TEST_CASE(queries_hit_tiles_and_name_the_cell) {
  Random rng(7);
  for (int round = 0; round < 40; ++round) {
    TileGrid grid = filled(12, 9, Tile::empty);
    for (auto& c : grid.cells) c = rng.next() % 3 == 0 ? 1 : 0;
    World tiles = make_world(course), blocks = make_world(course);
    const Vector o{37, 21};
    const EntityId layer = tiles.add_tile_layer(o, grid);
    for (int r = 0; r < grid.rows; ++r)
      for (int c = 0; c < grid.columns; ++c)
        if (grid.at(c, r) == Tile::solid) block(blocks, o.x + 16 * c, o.y + 16 * r, 16, 16, infinity);
    const QueryIndex ti(tiles), bi(blocks);
    for (int k = 0; k < 50; ++k) {
      const auto coord = [&](double span) { return rng.uniform(0, span); };
      const Vector from{coord(260), coord(200)}, dir{coord(2) - 1, coord(2) - 1};
      if (!ti.query_point(from).empty() || !bi.query_point(from).empty()) continue;  // from outside the solid
      const auto a = ti.ray_cast(from, dir, 300), b = bi.ray_cast(from, dir, 300);
      BOOST_TEST_INFO("from (" << from.x << ", " << from.y << ") dir (" << dir.x << ", " << dir.y << ") round " << round << " k " << k << (b ? " blocks hit " + std::to_string(b->fraction) : std::string()));
      BOOST_TEST_REQUIRE(a.has_value() == b.has_value());
      if (!a) continue;
      BOOST_TEST(a->body == layer);
      BOOST_TEST(a->fraction == b->fraction);
      BOOST_TEST((a->normal == b->normal));
      BOOST_TEST((a->point == b->point));
      const Vector cell = blocks.components.position[b->body];
      BOOST_TEST(a->column == static_cast<int>((cell.x - o.x) / 16));
      BOOST_TEST(a->row == static_cast<int>((cell.y - o.y) / 16));
    }
  }
  World w = make_world(course);
  const EntityId layer = w.add_tile_layer({0, 100}, drawn({"#..=", "####"}));
  const QueryIndex q(w);
  const auto down = q.ray_cast({56, 0}, {0, 1}, 500);  // onto the one-way cell's top
  BOOST_TEST_REQUIRE(down.has_value());
  BOOST_TEST(down->column == 3);
  BOOST_TEST(down->row == 0);
  BOOST_TEST(down->point.y == 100);
  const auto up = q.ray_cast({56, 200}, {0, -1}, 500);  // from below: stops at the bottom row, not the one-way cell
  BOOST_TEST_REQUIRE(up.has_value());
  BOOST_TEST(up->row == 1);
  const auto up_past = q.ray_cast({56, 115}, {0, -1}, 500);  // from inside the one-way cell: through it
  BOOST_TEST(!up_past.has_value());
  const auto out_of_wall = q.ray_cast({8, 124}, {0, 1}, 50);  // from inside the solid: its cells ignored
  BOOST_TEST(!out_of_wall.has_value());
  BOOST_TEST(q.query_point({8, 108}) == std::vector<EntityId>{layer});
  BOOST_TEST(q.query_point({16, 108}).empty());  // on a cell's edge
  BOOST_TEST(q.query_point({24, 108}).empty());  // an empty cell
  const auto cells = q.cells_meeting({10, 110}, {40, 120});  // rows 0 and 1, columns 0 to 2
  BOOST_TEST(cells.size() == 4u);  // (0, 0), and (0, 1) (1, 1) (2, 1)
  BOOST_TEST(cells[0].cell.column == 0);
  BOOST_TEST(cells[0].cell.row == 0);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_tiles
