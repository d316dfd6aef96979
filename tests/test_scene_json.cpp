// Scene files: the issue's format, the files in scenes/ reproducing the
// built-in scenes exactly, and one test per kind of bad file.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/builtin_scenes.hpp"
#include "app/dump.hpp"
#include "helpers.hpp"
#include "scene/scene_json.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_scene_json {

using namespace physics;

namespace {

// tests/ and scenes/ are siblings; __FILE__ is relative to the repository
// root, where `make test` runs.
std::string scene_file(const std::string& name) {
  return (std::filesystem::path(__FILE__).parent_path().parent_path() / "scenes" / (name + ".json")).string();
}

std::string state_after(const SceneSpec& s, int frames) {
  World w = make_world(s, false);
  for (int i = 0; i < frames; ++i) Game::step(w);
  std::ostringstream o;
  Dump::write_state(o, w);
  return o.str();
}

// The error a bad text gives: one line, naming the source.
std::string error_of(const std::string& text) {
  try {
    parse_scene(text, "bad.json");
  } catch (const SceneError& e) {
    const std::string msg = e.what();
    BOOST_TEST(msg.find('\n') == std::string::npos);
    BOOST_TEST(msg.rfind("bad.json", 0) == 0, msg);
    return msg;
  }
  BOOST_ERROR("no error for: " << text);
  return "";
}

using physics::test::has;

// A one-block scene with `block` as its block's members.
std::string with_block(const std::string& block) { return R"({"blocks": [{)" + block + "}]}"; }
const std::string ok_block = R"("pos": [100, 100], "size": [40, 40], "mass": 1)";

}  // namespace

BOOST_AUTO_TEST_SUITE(scene_files)

BOOST_AUTO_TEST_CASE(the_issues_example_reads_with_every_key) {
  const SceneSpec s = parse_scene(R"({ "name": "bounce",
    "world": { "width": 800, "height": 600, "dt": 16.666666666666668, "substeps": 1,
               "gravity": [0, 0], "restitution": 1.0, "walls": true,
               "systems": ["draw", "move", "forces", "collision"] },
    "blocks": [ { "pos": [100, 100], "size": [40, 40], "mass": 10, "velocity": [0.25, 0.25],
                  "force": [0, 0], "color": "#ff0000", "restitution": 1.0 },
                { "pos": [300, 300], "size": [80, 20], "mass": "inf" } ] })",
                                  "example.json");
  BOOST_TEST(s.name == "bounce");
  BOOST_TEST(s.params.dt == course_dt);
  BOOST_TEST(s.systems.to_string() == "draw,forces,move,collision");
  BOOST_TEST_REQUIRE(s.blocks.size() == 2u);
  const auto& red = std::get<BlockSpec>(s.blocks[0]);
  BOOST_TEST((red.color == Color{255, 0, 0, 255}));
  BOOST_TEST(red.velocity.x == 0.25);
  BOOST_TEST(std::get<BlockSpec>(s.blocks[1]).mass == infinity);
  BOOST_TEST(std::get<BlockSpec>(s.blocks[1]).width == 80);
}

BOOST_AUTO_TEST_CASE(every_key_but_pos_size_and_mass_has_a_default) {
  const SceneSpec s = parse_scene(with_block(ok_block), "dir/minimal.json");
  BOOST_TEST(s.name == "minimal");  // the file's name
  BOOST_TEST(s.width == 800);
  BOOST_TEST(s.height == 600);
  BOOST_TEST(s.params.dt == course_dt);
  BOOST_TEST(s.params.substeps == 1);
  BOOST_TEST(s.walls);
  BOOST_TEST(s.restitution == 1.0);
  BOOST_TEST(s.systems.to_string() == "draw,forces,move,collision");
  BOOST_TEST(!s.params.ccd);
  BOOST_TEST((s.params.solver == Solver::course));
  const World w = make_world(s, false);
  BOOST_TEST(w.components.size() == 5u);
  BOOST_TEST(w.components.restitution[4] == 1.0);
  BOOST_TEST((w.components.velocity[4] == Vector::zero()));
  const SceneSpec empty = parse_scene("{}", "e.json");
  BOOST_TEST(empty.blocks.empty());
}

BOOST_AUTO_TEST_CASE(the_numerics_keys_reach_the_worlds_params) {
  const SceneSpec s =
      parse_scene(R"({"world": {"ccd": true, "solver": "stable", "iterations": 12, "substeps": 4}})", "n.json");
  const World w = make_world(s, false);
  BOOST_TEST(w.params.ccd);
  BOOST_TEST((w.params.solver == Solver::stable));
  BOOST_TEST(w.params.iterations == 12);
  BOOST_TEST(w.params.substeps == 4);
  BOOST_TEST((w.params.integrator == Integrator::course));  // the sheet's unless asked
  const SceneSpec exact = parse_scene(R"({"world": {"integrator": "exact"}})", "x.json");
  BOOST_TEST((make_world(exact, false).params.integrator == Integrator::exact));
  // --print-scene and --save write the key, and it reads back.
  BOOST_TEST(has(to_json(exact), "\"integrator\": \"exact\""), to_json(exact));
  BOOST_TEST((parse_scene(to_json(exact), "back.json").params.integrator == Integrator::exact));
  BOOST_TEST(!has(to_json(s), "integrator"));  // beyond the sheet: written only when used, as friction
}

BOOST_AUTO_TEST_CASE(each_scene_file_reproduces_its_builtin_scene_exactly) {
  for (const SceneSpec& builtin : builtin_scenes()) {
    BOOST_TEST_CONTEXT(builtin.name) {
      const SceneSpec file = load_scene_file(scene_file(builtin.name));
      BOOST_TEST(file.name == builtin.name);
      BOOST_TEST(file.description == builtin.description);
      BOOST_TEST(file.systems.to_string() == builtin.systems.to_string());
      BOOST_TEST(state_after(file, 0) == state_after(builtin, 0));
      BOOST_TEST(state_after(file, 300) == state_after(builtin, 300));
    }
  }
}

BOOST_AUTO_TEST_CASE(print_scene_output_reads_back_to_the_same_scene) {
  for (const SceneSpec& builtin : builtin_scenes()) {
    BOOST_TEST_CONTEXT(builtin.name) {
      const SceneSpec back = parse_scene(to_json(builtin), builtin.name + ".json");
      BOOST_TEST((back.blocks == builtin.blocks));
      BOOST_TEST(state_after(back, 100) == state_after(builtin, 100));
    }
  }
}

// Short arrays of numbers or strings stay on one line; the rest is indented
// by two spaces per level, like the scene files.
BOOST_AUTO_TEST_CASE(print_scene_keeps_short_arrays_on_one_line) {
  const std::string j = to_json(*find_builtin("stack"));
  BOOST_TEST(j.find("\n    \"gravity\": [0.0, 0.001],\n") != std::string::npos, j);
  BOOST_TEST(j.find("\"systems\": [\"draw\", \"forces\", \"move\", \"collision\"]") != std::string::npos, j);
  BOOST_TEST(j.find("\n        \"pos\": [200.0, 520.0],\n") != std::string::npos, j);
  BOOST_TEST(j.find("\n  \"blocks\": [\n    {\n      \"grid\": {\n") != std::string::npos, j);
  BOOST_TEST(j.rfind("{\n  \"name\": \"stack\",", 0) == 0u);
  BOOST_TEST(j.ends_with("\n  ]\n}\n"));
  BOOST_TEST(std::count(j.begin(), j.end(), '\n') < 30);  // was 40 with one number a line
}

BOOST_AUTO_TEST_CASE(a_ten_thousand_body_scene_is_a_few_lines) {
  const SceneSpec s = load_scene_file(scene_file("gas10k"));
  const World w = make_world(s, false);
  BOOST_TEST(w.components.size() == 10'004u);
  std::size_t lines = 0;
  std::ifstream in(scene_file("gas10k"));
  for (std::string l; std::getline(in, l);) ++lines;
  BOOST_TEST(lines < 12u);
}

BOOST_AUTO_TEST_CASE(comments_are_allowed) {
  BOOST_CHECK_NO_THROW(parse_scene("// a scene\n{ /* no blocks */ }", "c.json"));
}

BOOST_AUTO_TEST_CASE(generators_read_ranges_and_seeds) {
  const SceneSpec s = parse_scene(R"({"blocks": [
      {"random": {"count": 5, "size": [[4, 8], 6], "mass": [1, 2], "velocity": [[-1, 1], 0.5],
                  "restitution": [0.5, 1], "color": "#102030"}, "seed": 7},
      {"grid": {"pos": [100, 100], "size": [10, 10], "mass": "inf", "count": [3, 2]}}]})",
                                  "g.json");
  const auto& r = std::get<RandomSpec>(s.blocks[0]);
  BOOST_TEST(r.seed == 7u);
  BOOST_TEST((r.width == IntSpec::uniform(4, 8)));
  BOOST_TEST((r.height == IntSpec::fixed(6)));
  BOOST_TEST((r.velocity.y == RealSpec::fixed(0.5)));
  BOOST_TEST(!r.use_cells);  // default area: inside the walls
  BOOST_TEST(r.origin.x == 40.0);
  BOOST_TEST(r.extent.x == 720.0);
  const auto& g = std::get<GridSpec>(s.blocks[1]);
  BOOST_TEST(g.step.x == 10.0);  // default step: touching
  const World w = make_world(s, false);
  BOOST_TEST(w.components.size() == 4u + 5u + 6u);
  for (std::size_t e = 4; e < 9; ++e) {
    BOOST_TEST(w.components.restitution[e] >= 0.5);
    BOOST_TEST(w.components.velocity[e].y == 0.5);
  }
}

// A block's side may be an integer or a real with no fraction (4.0), which
// the parser gives as different kinds of numbers: the same block, bit for
// bit. (Plain blocks were once read by a fast path of their own; the one
// reader now reads them all, and this test keeps its cases.)
BOOST_AUTO_TEST_CASE(integer_and_real_sides_give_the_same_block) {
  const std::vector<std::string> members = {
      R"("pos": [100, 100], "mass": 1)",
      R"("mass": 2.5, "pos": [-3, 0.1], "velocity": [0.1, -0.2], "force": [1e300, -1e-300], "impulse": [5, 6])",
      R"("pos": [18446744073709551615, -9223372036854775808], "mass": "inf", "color": "#a0B1c2")",
      R"("pos": [0.30000000000000004, 1e-320], "mass": 9007199254740993, "restitution": 0.5)",
      R"("restitution": 0, "color": "#FFFFFF", "pos": [1, 2], "mass": -1)",
  };
  for (const std::string& m : members) {
    const SceneSpec fast = read_scene(with_block(m + R"(, "size": [4, 7])"), "p.json");
    const SceneSpec dom = read_scene(with_block(m + R"(, "size": [4.0, 7.0])"), "p.json");
    BOOST_TEST_REQUIRE(fast.blocks.size() == 1u);
    BOOST_TEST((fast.blocks == dom.blocks), m);
  }
  // Plain blocks and others, in their order.
  const SceneSpec s = read_scene(R"({"blocks": [
      {"pos": [1, 1], "size": [2, 2], "mass": 1},
      {"grid": {"pos": [100, 100], "size": [10, 10], "mass": "inf", "count": [3, 2]}},
      {"pos": [3, 3], "size": [2.0, 2], "mass": 1},
      {"pos": [4, 4], "size": [2, 2], "mass": 1}]})",
                                 "p.json");
  BOOST_TEST_REQUIRE(s.blocks.size() == 4u);
  BOOST_TEST(std::holds_alternative<GridSpec>(s.blocks[1]));
  for (const std::size_t i : {0u, 2u, 3u}) BOOST_TEST(std::get<BlockSpec>(s.blocks[i]).pos.x == (i == 0 ? 1.0 : i + 1.0));
}

BOOST_AUTO_TEST_SUITE_END()

// One case per kind of bad input the issue lists, and a few more.
BOOST_AUTO_TEST_SUITE(scene_file_errors)

BOOST_AUTO_TEST_CASE(unreadable_file) {
  try {
    load_scene_file("/nonexistent/scene.json");
    BOOST_ERROR("no error");
  } catch (const SceneError& e) {
    BOOST_TEST(has(e.what(), "/nonexistent/scene.json: cannot read"));
  }
  const auto dir = std::filesystem::temp_directory_path();
  try {
    load_scene_file(dir.string());
    BOOST_ERROR("no error");
  } catch (const SceneError& e) {
    BOOST_TEST(has(e.what(), "directory"));
  }
}

BOOST_AUTO_TEST_CASE(invalid_json_gives_line_and_column) {
  // The bad token `x` is on line 3, column 11.
  const std::string msg = error_of("{\n  \"world\": {},\n  \"name\": x\n}");
  BOOST_TEST(has(msg, "bad.json:3:11: invalid JSON"), msg);
  BOOST_TEST(error_of("").find("bad.json:1:1: invalid JSON") == 0u);
  BOOST_TEST(has(error_of("{\n\"blocks\": [\n"), "bad.json:3:1: invalid JSON"));
  BOOST_TEST(has(error_of("{\"name\": \"a\",}"), "bad.json:1:14"));
  BOOST_TEST(has(error_of("[1, 2]"), "must hold one JSON object"));
}

BOOST_AUTO_TEST_CASE(line_column_counts_from_one) {
  BOOST_TEST(line_column("abc", 1).line == 1u);
  BOOST_TEST(line_column("abc", 3).column == 3u);
  BOOST_TEST(line_column("a\nbc", 4).line == 2u);
  BOOST_TEST(line_column("a\nbc", 4).column == 2u);
  BOOST_TEST(line_column("a\n", 99).line == 2u);  // past the end: clamped
}

BOOST_AUTO_TEST_CASE(unknown_keys_are_errors_with_a_hint) {
  const std::string msg = error_of(R"({"world": {"gravty": [0, 1]}})");
  BOOST_TEST(has(msg, "world.gravty: unknown key (did you mean \"gravity\"?)"), msg);
  BOOST_TEST(has(error_of(R"({"nmae": "x"})"), "\"nmae\": unknown key (did you mean \"name\"?)"));
  BOOST_TEST(has(error_of(with_block(ok_block + R"(, "mas": 3)")), "blocks[0].mas: unknown key"));
  BOOST_TEST(has(error_of(R"({"blocks": [{"grid": {"pos": [50, 50], "size": [1, 1], "mass": 1, "count": [1, 1],
                                                    "colour": "#000000"}}]})"),
                 "blocks[0].grid.colour: unknown key (did you mean \"color\"?)"));
  BOOST_TEST(has(error_of(R"({"blocks": [{"random": {"count": 1, "side": 5, "mass": 1}, "sed": 1}]})"),
                 "blocks[0].sed: unknown key"));
}

// Errors in a block after plain ones: the document's messages, path and
// index included, and a syntax error further on still comes first.
BOOST_AUTO_TEST_CASE(errors_after_plain_blocks) {
  const std::string two = R"({"blocks": [{"pos": [1, 1], "size": [2, 2], "mass": 1}, {)";
  BOOST_TEST(has(error_of(two + R"("pos": [1, 1], "mass": 1, "size": [2, 2], "mass": 3}]})"),
                 "bad.json: blocks[1]: duplicate key \"mass\""));
  BOOST_TEST(has(error_of(two + R"("pos": [1, 1], "size": [0, 2], "mass": 1}]})"), "bad.json: blocks[1].size[0]: must be > 0"));
  BOOST_TEST(has(error_of(two + R"("pos": [1, 1, 1], "size": [2, 2], "mass": 1}]})"), "bad.json: blocks[1].pos: must be"));
  BOOST_TEST(has(error_of(two + R"("pos": {"x": 1}, "size": [2, 2], "mass": 1}]})"), "bad.json: blocks[1].pos: must be"));
  BOOST_TEST(has(error_of(two + R"("pos": [[1], 1], "size": [2, 2], "mass": 1}]})"), "bad.json: blocks[1].pos[0]: must be"));
  BOOST_TEST(has(error_of(two + R"("pos": [1, 1], "size": [2, 2], "mass": 1, "colour": "#000000"}]})"),
                 "bad.json: blocks[1].colour: unknown key (did you mean \"color\"?)"));
  BOOST_TEST(has(error_of(two + R"("pos": [1, 1], "size": [2, 2], "mass": 1, "color": "#00000g"}]})"),
                 "bad.json: blocks[1].color: must be a colour"));
  BOOST_TEST(has(error_of(two + R"("pos": [1, 1], "size": [0, 2], "mass": 1}], "x": })"), "bad.json:1:"));
}

BOOST_AUTO_TEST_CASE(duplicate_keys_are_errors) {
  const std::string msg = error_of(with_block(ok_block + R"(, "mass": 3)"));
  BOOST_TEST(has(msg, "blocks[0]: duplicate key \"mass\""), msg);
}

BOOST_AUTO_TEST_CASE(wrong_types) {
  BOOST_TEST(has(error_of(with_block(R"("pos": [100, 100], "size": [40, 40], "mass": "heavy")")),
                 "blocks[0].mass: must be a number > 0 or \"inf\" (got the string \"heavy\")"));
  BOOST_TEST(has(error_of(R"({"world": {"walls": 1}})"), "world.walls: must be true or false (got 1)"));
  BOOST_TEST(has(error_of(with_block(R"("pos": [100, 100], "size": "big", "mass": 1)")), "blocks[0].size: must be"));
  BOOST_TEST(has(error_of(with_block(R"("pos": [100, "a"], "size": [4, 4], "mass": 1)")),
                 "blocks[0].pos[1]: must be a number"));
  BOOST_TEST(has(error_of(with_block(R"("pos": [100, 100, 3], "size": [4, 4], "mass": 1)")), "blocks[0].pos"));
  BOOST_TEST(has(error_of(with_block(R"("pos": [100, 100], "size": [4.5, 4], "mass": 1)")),
                 "blocks[0].size[0]: must be an integer"));
  BOOST_TEST(has(error_of(R"({"blocks": {}})"), "blocks: must be an array"));
  BOOST_TEST(has(error_of(R"({"world": {"substeps": "2"}})"), "world.substeps: must be an integer"));
  BOOST_TEST(has(error_of(R"({"world": {"systems": ["draw", "gravity"]}})"), "world.systems[1]: unknown system"));
  BOOST_TEST(has(error_of(R"({"world": {"systems": ["move", "move"]}})"), "listed twice"));
  BOOST_TEST(has(error_of(R"({"world": {"solver": "fast"}})"), "world.solver: must be \"course\", \"stable\" or \"auto\""));
  BOOST_TEST(has(error_of(R"({"world": {"integrator": "rk4"}})"),
                 "bad.json: world.integrator: must be \"course\" or \"exact\" (got the string \"rk4\")"));
  BOOST_TEST(has(error_of(R"({"world": {"integrator": 1}})"), "world.integrator"));
  BOOST_TEST(has(error_of(with_block(ok_block + R"(, "color": "red")")), "blocks[0].color: must be a colour"));
  BOOST_TEST(has(error_of(R"({"name": 3})"), "name: must be a string"));
}

BOOST_AUTO_TEST_CASE(missing_required_keys) {
  BOOST_TEST(has(error_of(with_block(R"("size": [4, 4], "mass": 1)")), "blocks[0]: missing key \"pos\""));
  BOOST_TEST(has(error_of(with_block(R"("pos": [100, 100], "mass": 1)")), "blocks[0]: missing key \"size\""));
  BOOST_TEST(has(error_of(with_block(R"("pos": [100, 100], "size": [4, 4])")), "blocks[0]: missing key \"mass\""));
}

BOOST_AUTO_TEST_CASE(nan_and_inf_where_finite_is_needed) {
  // JSON has no NaN or Infinity: an overflowing number is a syntax error, and
  // the strings are the wrong type.
  BOOST_TEST(has(error_of(with_block(R"("pos": [1e400, 100], "size": [4, 4], "mass": 1)")), "bad.json:1:"));
  BOOST_TEST(has(error_of(with_block(R"("pos": [100, 100], "size": [4, 4], "mass": 1e400)")), "number overflow"));
  BOOST_TEST(has(error_of(R"({"world": {"dt": "NaN"}})"), "world.dt: must be a number (got the string \"NaN\")"));
  BOOST_TEST(has(error_of(R"({"world": {"gravity": [0, NaN]}})"), "invalid JSON"));
  BOOST_TEST(has(error_of(with_block(R"("pos": [100, 100], "size": [4, 4], "mass": "Infinity")")),
                 "blocks[0].mass"));
}

BOOST_AUTO_TEST_CASE(mass_must_be_positive_or_inf) {
  BOOST_TEST(has(error_of(with_block(R"("pos": [100, 100], "size": [4, 4], "mass": 0)")),
                 "blocks[0].mass: must be > 0 or \"inf\" (got 0)"));
  BOOST_TEST(has(error_of(with_block(R"("pos": [100, 100], "size": [4, 4], "mass": -2)")), "blocks[0].mass"));
  BOOST_TEST(has(error_of(R"({"blocks": [{"random": {"count": 2, "side": 4, "mass": [0, 2]}}]})"),
                 "blocks[0].random.mass: range must be > 0"));
  BOOST_CHECK_NO_THROW(parse_scene(with_block(R"("pos": [100, 100], "size": [4, 4], "mass": "inf")"), "ok.json"));
}

BOOST_AUTO_TEST_CASE(size_must_be_positive) {
  BOOST_TEST(has(error_of(with_block(R"("pos": [100, 100], "size": [0, 4], "mass": 1)")),
                 "blocks[0].size[0]: must be > 0 (got 0)"));
  BOOST_TEST(has(error_of(with_block(R"("pos": [100, 100], "size": [4, -3], "mass": 1)")), "blocks[0].size[1]"));
  BOOST_TEST(has(error_of(R"({"blocks": [{"random": {"count": 2, "side": [0, 5], "mass": 1}}]})"),
                 "blocks[0].random.side[0]: must be > 0"));
  BOOST_TEST(has(error_of(R"({"blocks": [{"random": {"count": 2, "side": [9, 5], "mass": 1}}]})"),
                 "blocks[0].random.side: range [9, 5] is empty"));
}

BOOST_AUTO_TEST_CASE(dt_must_be_positive) {
  BOOST_TEST(has(error_of(R"({"world": {"dt": 0}})"), "world.dt: must be > 0 (got 0)"));
  BOOST_TEST(has(error_of(R"({"world": {"dt": -16}})"), "world.dt"));
}

BOOST_AUTO_TEST_CASE(substeps_and_iterations_at_least_one) {
  BOOST_TEST(has(error_of(R"({"world": {"substeps": 0}})"), "world.substeps: must be an integer in [1, 1000] (got 0)"));
  BOOST_TEST(has(error_of(R"({"world": {"substeps": 1.5}})"), "world.substeps: must be an integer"));
  BOOST_TEST(has(error_of(R"({"world": {"iterations": 0}})"), "world.iterations"));
}

BOOST_AUTO_TEST_CASE(restitution_in_zero_one) {
  BOOST_TEST(has(error_of(R"({"world": {"restitution": 1.5}})"), "world.restitution: must be in [0, 1] (got 1.5)"));
  BOOST_TEST(has(error_of(with_block(ok_block + R"(, "restitution": -0.1)")), "blocks[0].restitution"));
  BOOST_TEST(has(error_of(R"({"blocks": [{"random": {"count": 2, "side": 4, "mass": 1, "restitution": [0.5, 2]}}]})"),
                 "blocks[0].random.restitution"));
}

BOOST_AUTO_TEST_CASE(blocks_overlapping_walls_or_outside_the_world) {
  BOOST_TEST(has(error_of(with_block(R"("pos": [20, 100], "size": [40, 40], "mass": 1)")),
                 "blocks[0]: block at (20, 100) of size 40x40 overlaps the left wall"));
  BOOST_TEST(has(error_of(R"({"world": {"walls": false}, "blocks": [{"pos": [-1, 100], "size": [4, 4], "mass": 1}]})"),
                 "blocks[0]: block at (-1, 100) of size 4x4 lies outside the 800x600 world"));
  BOOST_TEST(has(error_of(R"({"blocks": [{"grid": {"pos": [700, 100], "size": [20, 20], "mass": 1, "count": [5, 1]}}]})"),
                 "blocks[0] (grid body 3)"));
  BOOST_TEST(has(error_of(R"({"blocks": [{"random": {"count": 3, "side": 30, "mass": 1,
                              "cells": {"pos": [700, 100], "columns": 3, "step": [40, 40]}}}]})"),
                 "blocks[0] (random body 1)"));
}

BOOST_AUTO_TEST_CASE(generator_shape_errors) {
  BOOST_TEST(has(error_of(R"({"blocks": [{"grid": {}, "random": {}}]})"), "not both"));
  BOOST_TEST(has(error_of(R"({"blocks": [{"random": {"side": 4, "mass": 1}}]})"), "missing key \"count\""));
  BOOST_TEST(has(error_of(R"({"blocks": [{"random": {"count": 1, "mass": 1}}]})"), "missing key \"size\""));
  BOOST_TEST(has(error_of(R"({"blocks": [{"random": {"count": 0, "side": 4, "mass": 1}}]})"),
                 "blocks[0].random.count: must be an integer in [1, 1000000]"));
  BOOST_TEST(has(error_of(R"({"blocks": [{"random": {"count": 1, "side": 4, "mass": 1}, "seed": -1}]})"),
                 "blocks[0].seed"));
  BOOST_TEST(has(error_of(R"({"blocks": [{"random": {"count": 1, "side": 40, "mass": 1,
                                                     "area": {"pos": [100, 100], "size": [10, 10]}}}]})"),
                 "blocks[0].random.area.size"));
  BOOST_TEST(has(error_of(R"({"blocks": [{"grid": {"pos": [50, 50], "size": [1, 1], "mass": 1,
                                                   "count": [1000000, 1000000]}}]})"),
                 "too many bodies"));
}

BOOST_AUTO_TEST_CASE(deep_nesting_is_refused_without_recursion) {
  const std::string deep = "{\"name\": " + std::string(100000, '[') + std::string(100000, ']') + "}";
  BOOST_TEST(has(error_of(deep), "nesting deeper than 64 levels"));
}

// One place validates: the reader converts (types, keys, fits), validate()
// judges. A file's out-of-range values read fine and are refused by the
// validation parse_scene (and the command line) runs once, with the same
// message as a built-in scene would get.
BOOST_AUTO_TEST_CASE(the_reader_converts_the_validator_judges) {
  const std::string text = R"({"world": {"dt": -1, "restitution": 2},
    "blocks": [{"pos": [100, 100], "size": [4, 4], "mass": -1, "restitution": 3}]})";
  const SceneSpec s = read_scene(text, "r.json");
  BOOST_TEST(s.params.dt == -1.0);
  BOOST_TEST(std::get<BlockSpec>(s.blocks[0]).mass == -1.0);
  const std::int64_t before = validation_count();
  BOOST_TEST(error_of(text) == "bad.json: world.dt: must be > 0 (got -1)");
  BOOST_TEST(validation_count() - before == 1);
  // The blocks are read as the parser completes them, but a block's error
  // still comes after the world's, as if the file were read whole first.
  BOOST_TEST(has(error_of(R"({"blocks": [{"pos": [1, 1], "size": [4, 4], "mass": 1, "x": 1}],
                              "world": {"walls": 3}})"), "world.walls: must be true or false"));
  // Default random area: the world's, even when "world" comes after "blocks".
  const SceneSpec late = parse_scene(R"({"blocks": [{"random": {"count": 3, "side": 4, "mass": 1}}],
                                         "world": {"width": 2000, "walls": false}})", "late.json");
  BOOST_TEST(std::get<RandomSpec>(late.blocks[0]).extent.x == 2000.0);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_scene_json
