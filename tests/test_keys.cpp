// The key tables (src/scene/keys.hpp): the one description of each key of a
// scene file drives its reading, checking and writing, and docs/scenes.md's
// key tables are generated from it (tools/scene_keys.sh writes them).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "scene/keys.hpp"
#include "scene/scene_json.hpp"
#include "cli_helpers.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_keys {

using namespace physics;
using namespace physics::test;

namespace {

const std::string begin_mark = "<!-- begin key tables";
const std::string end_mark = "<!-- end key tables -->";

std::filesystem::path doc_path() {
  return std::filesystem::absolute(__FILE__).parent_path().parent_path() / "docs" / "scenes.md";
}

std::string error_of(const std::string& text) {
  try {
    expand(read_scene(text, "k.json"), "k.json");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

// A block with every key away from its default.
BlockSpec every_key() {
  BlockSpec b;
  b.pos = {100, 120};
  b.width = 30;
  b.height = 12;
  b.mass = 2.5;
  b.velocity = {0.1, -0.2};
  b.force = {0.001, 0};
  b.impulse = {0, 0.5};
  b.color = {10, 20, 30, 255};
  b.restitution = 0.25;
  b.contact.friction = 0.75;
  b.contact.rules = {6, 3, true, Face::left};
  b.tag = "platform";
  b.strength = 4;
  b.travel = 50;
  b.travel_from = Vector{90, 120};
  b.travel_dir = Vector{-1, 0};
  return b;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(scene_keys)

// SCENE_KEYS_WRITE=1 (tools/scene_keys.sh) writes them instead of checking.
BOOST_AUTO_TEST_CASE(the_docs_key_tables_are_the_generated_ones) {
  const std::string doc = read(doc_path().string());
  const auto from = doc.find(begin_mark), to = doc.find(end_mark);
  BOOST_TEST_REQUIRE((from != std::string::npos && to != std::string::npos && from < to), "no markers in scenes.md");
  const std::size_t start = doc.find('\n', from) + 1;
  const std::string generated = key_tables_markdown() + "\n";
  if (std::getenv("SCENE_KEYS_WRITE")) {
    std::ofstream(doc_path()) << doc.substr(0, start) + generated + doc.substr(to);
    return;
  }
  BOOST_TEST(doc.substr(start, to - start) == generated,
             "docs/scenes.md's key tables differ from src/scene/keys.cpp: run tools/scene_keys.sh");
}

// Each row of a block writes its key, and reads it back to the same value.
BOOST_AUTO_TEST_CASE(every_block_key_is_written_and_read_back) {
  SceneSpec s;
  s.blocks.push_back(every_key());
  s.blocks.push_back(GridSpec{every_key(), 2, 1, {40, 0}});
  const std::string text = to_json(s);
  for (const auto& k : scene_io::block_keys())
    BOOST_TEST(has(text, std::string("\"") + k.doc.name() + "\":"), k.doc.name());
  const SceneSpec back = read_scene(text, "back.json");
  BOOST_TEST((back.blocks == s.blocks));
  // A random entry's contact keys are the same rows.
  RandomSpec r;
  r.count = 2;
  r.width = r.height = IntSpec::fixed(5);
  r.mass = RealSpec::fixed(1);
  r.contact = every_key().contact;
  s.blocks = {r};
  BOOST_TEST((std::get<RandomSpec>(read_scene(to_json(s), "r.json").blocks[0]).contact == r.contact));
}

// The same for the world: every key written (the last two only when used) and read back.
BOOST_AUTO_TEST_CASE(every_world_key_is_written_and_read_back) {
  SceneSpec s;
  s.width = 640;
  s.height = 480;
  s.params.dt = 10;
  s.params.substeps = 3;
  s.params.gravity = {0, 0.002};
  s.restitution = 0.5;
  s.walls = false;
  s.systems = SystemSet{false, true, true, true};
  s.params.ccd = true;
  s.params.solver = Solver::stable;
  s.params.iterations = 12;
  s.friction = 0.3;
  s.params.integrator = Integrator::exact;
  const std::string text = to_json(s);
  for (const auto& k : scene_io::world_keys())
    BOOST_TEST(has(text, std::string("\"") + k.doc.name() + "\":"), k.doc.name());
  const SceneSpec back = read_scene(text, "back.json");
  BOOST_TEST(to_json(back) == text);
  BOOST_TEST(back.params.substeps == 3);
  BOOST_TEST(back.friction == 0.3);
  BOOST_TEST(!back.systems.draw);
}

// --save lost keys when it spelled them itself: every block key now goes
// into the world or the body's role and comes back from it, through its row.
BOOST_AUTO_TEST_CASE(every_block_key_is_saved_from_the_world_or_the_role) {
  // A key of the physics goes into the body and comes back from the world;
  // a key of the games goes into the body's role and comes back from it.
  for (const auto& k : scene_io::block_keys()) {
    const bool physics = k.to_body && k.from_world, game = k.to_role && k.from_role;
    BOOST_TEST(physics != game, k.doc.name());
    BOOST_TEST(!(physics && (k.to_role || k.from_role)), k.doc.name());
    BOOST_TEST(!(game && (k.to_body || k.from_world || k.to_def)), k.doc.name());
  }
  // A body made from the block with every key, saved before any step, is that block again
  // (its impulse folded into the pending force).
  SceneSpec s;
  s.walls = false;
  BlockSpec b = every_key();
  s.blocks.push_back(b);
  const std::vector<Body> bodies = expand(s, "k.json");
  const World w = make_world(s, bodies, false);
  const BlockSpec back = block_from_world(w.components, 0, s, roles_by_entity(s, bodies)[0]);
  b.force = w.components.sum_forces[0];
  b.impulse = {};
  b.travel_from = Vector{90, 120};  // not the position: kept
  b.travel_dir = Vector{-1, 0};     // not the velocity's direction: kept
  BOOST_TEST((back == b));
}

// The reader accepts the table's keys and no other; its hint lists them.
BOOST_AUTO_TEST_CASE(the_reader_takes_the_tables_keys_and_names_them) {
  const std::string msg = error_of(R"({"blocks": [{"pos": [100, 100], "size": [10, 10], "mass": 1, "tagg": "x"}]})");
  std::string list;
  for (const std::string_view n : scene_io::block_names()) list += (list.empty() ? "" : ", ") + std::string(n);
  BOOST_TEST(has(msg, "blocks[0].tagg: unknown key (did you mean \"tag\"?); expected one of: " + list), msg);
  const std::string world = error_of(R"({"world": {"frction": 1}})");
  BOOST_TEST(has(world, "world.frction: unknown key (did you mean \"friction\"?)"), world);
}

// The rows' checks run in validate(), with the key's path.
BOOST_AUTO_TEST_CASE(the_rows_check_their_keys) {
  const std::string block = R"({"blocks": [{"pos": [100, 100], "size": [90, 10], "mass": "inf", "tag": "platform",
                                "velocity": [0.1, 0], "travel": 40, )";
  BOOST_TEST(error_of(block + R"("travel_dir": [2, 0]}]})") ==
             "k.json: blocks[0].travel_dir: must be a unit vector (got [2, 0])");
  BOOST_TEST(error_of(block + R"("travel_from": [100, 100]}]})").empty());
  BOOST_TEST(error_of(R"({"blocks": [{"pos": [100, 100], "size": [9, 9], "mass": 1, "travel_from": [1, 1]}]})") ==
             "k.json: blocks[0].travel_from: only a block with a \"travel\" has one");
  BOOST_TEST(error_of(R"({"blocks": [{"random": {"count": 1, "side": 5, "mass": 1, "friction": -1}}]})") ==
             "k.json: blocks[0].random.friction: must be in [0, 1000] (got -1)");
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_keys
