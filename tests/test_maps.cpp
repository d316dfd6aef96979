// Maps from the level editors (scene/map.hpp, tiled.hpp, ldtk.hpp;
// docs/scenes.md, "Maps from Tiled and LDtk"): each sample map loads and runs
// headless, its tile layers' cells are its data's, its objects' properties
// land on their blocks and its own on the world; --print-scene gives a scene
// file that reads back to the same scene; each unsupported case is one line,
// exit 2.
#include <cmath>
#include <functional>
#include <sys/stat.h>

#include <nlohmann/json.hpp>

#include "cli_helpers.hpp"
#include "scene/scene_json.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_maps {

using namespace physics;
using namespace physics::test;
using nlohmann::json;

namespace {

std::string map_path(const std::string& name) { return (repo_root() / "scenes" / "maps" / name).string(); }
json map_json(const std::string& name) { return json::parse(read(map_path(name))); }

const BlockSpec& block(const SceneSpec& s, std::size_t i) { return std::get<BlockSpec>(s.blocks.at(i)); }

// The sample `name` changed by `edit`, written beside a copy of the samples'
// external tileset; the command line's one-line error must contain `part`.
void expect_map_error(const std::string& name, const std::function<void(json&)>& edit, const std::string& part) {
  const TempDir dir;
  dir.file("props.tsj", read(map_path("props.tsj")));
  json m = map_json(name);
  edit(m);
  const std::string file = dir.file(name, m.dump());
  expect_bad({"--scene", file, "--headless", "--frames", "1"}, part);
  expect_bad({"--scene", file, "--headless", "--frames", "1"}, file + ": ");  // names the file
}

json& tiled_layer(json& m, const std::string& name) {
  for (json& l : m["layers"])
    if (l["name"] == name) return l;
  throw std::runtime_error("no layer " + name);
}
json& tiled_object(json& m, const std::string& name) {
  for (json& o : tiled_layer(m, "objects")["objects"])
    if (o["name"] == name) return o;
  throw std::runtime_error("no object " + name);
}
json& ldtk_layer(json& m, const std::string& type) {
  for (json& l : m["levels"][0]["layerInstances"])
    if (l["__type"] == type) return l;
  throw std::runtime_error("no layer " + type);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(maps)

BOOST_AUTO_TEST_CASE(each_sample_loads_and_runs_headless) {
  for (const char* name : {"platform.tmj", "level.ldtk"}) {
    const TempDir dir;
    const Ran r = program(dir, no_display, {"--scene", map_path(name), "--headless", "--frames", "60"});
    BOOST_TEST(r.code == 0, name << ": " << r.err);
    BOOST_TEST(has(r.out, "frames:          60"), r.out);
  }
}

// The rule: gid 0 empty; a tileset tile with one_way true one-way, with solid
// false empty, any other solid; flip bits ignored; a layer with collision
// false left out.
BOOST_AUTO_TEST_CASE(a_tiled_tile_layer_holds_the_map_s_cells) {
  const SceneSpec s = load_scene_file(map_path("platform.tmj"));
  json m = map_json("platform.tmj");
  BOOST_TEST_REQUIRE(s.tiles.size() == 1u);  // "background" has collision false
  const TileSpec& t = s.tiles[0];
  BOOST_TEST(t.cell == 20);
  BOOST_TEST(t.pos.x == 0.0);
  BOOST_TEST(t.pos.y == 0.0);
  BOOST_TEST((t.friction == std::optional<double>(0.5)));  // the layer's property
  const json& data = tiled_layer(m, "ground")["data"];
  BOOST_TEST_REQUIRE(t.rows.size() == 15u);
  std::size_t kinds[3] = {};
  for (std::size_t i = 0; i < data.size(); ++i) {
    const std::uint32_t gid = data[i].get<std::uint32_t>() & 0x0FFFFFFFu;
    const char expected = gid == 0 || gid == 4 ? '.' : gid == 2 || gid == 6 ? '=' : '#';
    const char got = t.rows.at(i / 30).at(i % 30);
    BOOST_TEST(got == expected, "cell " << i << " gid " << gid);
    kinds[expected == '#' ? 0 : expected == '=' ? 1 : 2]++;
  }
  BOOST_TEST(kinds[0] > 60u);  // the case tests each kind
  BOOST_TEST(kinds[1] == 7u);
}

BOOST_AUTO_TEST_CASE(tiled_object_properties_land_on_the_blocks) {
  const SceneSpec s = load_scene_file(map_path("platform.tmj"));
  BOOST_TEST_REQUIRE(s.blocks.size() == 5u);
  const BlockSpec& player = block(s, 0);
  BOOST_TEST(player.tag == "player");
  BOOST_TEST(player.mass == 1.0);
  BOOST_TEST(player.pos.x == 60.0);
  BOOST_TEST(player.pos.y == 240.0);
  BOOST_TEST(player.width == 20);
  BOOST_TEST(player.velocity.x == 0.1);  // the string "0.1,0"
  BOOST_TEST(player.velocity.y == 0.0);
  BOOST_TEST((player.contact.friction == std::optional<double>(0.5)));
  const BlockSpec& crate = block(s, 1);
  BOOST_TEST(crate.mass == 2.0);
  BOOST_TEST((crate.color == Color{0x8b, 0x45, 0x13, 255}));  // "#ff8b4513": the alpha dropped
  BOOST_TEST((crate.restitution == std::optional<double>(0.0)));
  const BlockSpec& lift = block(s, 2);
  BOOST_TEST(std::isinf(lift.mass));  // no mass property: fixed
  BOOST_TEST((lift.travel == std::optional<double>(100.0)));
  BOOST_TEST(block(s, 3).contact.rules.sensor);
  BOOST_TEST(block(s, 3).tag == "coin");
  BOOST_TEST(std::isinf(block(s, 4).mass));
}

BOOST_AUTO_TEST_CASE(tiled_map_properties_set_the_world) {
  const SceneSpec s = load_scene_file(map_path("platform.tmj"));
  BOOST_TEST(s.width == 600);  // 30 x 20 px
  BOOST_TEST(s.height == 300);
  BOOST_TEST(s.params.gravity.x == 0.0);
  BOOST_TEST(s.params.gravity.y == 0.001);
  BOOST_TEST(!s.walls);
  BOOST_TEST((s.params.solver == Solver::stable));
  BOOST_TEST(s.restitution == 0.0);
  BOOST_TEST(s.name == "platform");
  BOOST_TEST(has(s.description, "a Tiled map"));
}

BOOST_AUTO_TEST_CASE(an_ldtk_level_becomes_tiles_blocks_and_world_keys) {
  const SceneSpec s = load_scene_file(map_path("level.ldtk"));
  json m = map_json("level.ldtk");
  BOOST_TEST(s.width == 320);
  BOOST_TEST(s.height == 192);
  BOOST_TEST(s.params.gravity.y == 0.001);
  BOOST_TEST(!s.walls);
  BOOST_TEST((s.params.solver == Solver::stable));
  BOOST_TEST_REQUIRE(s.tiles.size() == 1u);
  BOOST_TEST(s.tiles[0].cell == 16);
  const json& csv = ldtk_layer(m, "IntGrid")["intGridCsv"];
  for (std::size_t i = 0; i < csv.size(); ++i) {
    const int v = csv[i].get<int>();
    BOOST_TEST(s.tiles[0].rows.at(i / 20).at(i % 20) == (v == 1 ? '#' : v == 2 ? '=' : '.'), "cell " << i);
  }
  BOOST_TEST_REQUIRE(s.blocks.size() == 2u);
  const BlockSpec& player = block(s, 0);  // px [40, 160], pivot [0.5, 1], 16 x 16
  BOOST_TEST(player.pos.x == 32.0);
  BOOST_TEST(player.pos.y == 144.0);
  BOOST_TEST(player.tag == "player");
  BOOST_TEST(player.mass == 1.0);
  BOOST_TEST(player.velocity.x == 0.08);
  const BlockSpec& crate = block(s, 1);
  BOOST_TEST(crate.pos.x == 144.0);
  BOOST_TEST(crate.mass == 2.0);
  BOOST_TEST((crate.color == Color{0x8b, 0x45, 0x13, 255}));
  BOOST_TEST(!crate.contact.friction);  // a null field keeps the default
}

// The printed scene file reads back to the same scene, and runs the same.
BOOST_AUTO_TEST_CASE(print_scene_of_a_map_is_its_scene_file) {
  for (const char* name : {"platform.tmj", "level.ldtk"}) {
    const Ran printed = cli({"--scene", map_path(name), "--print-scene"});
    BOOST_TEST_REQUIRE(printed.code == 0, printed.err);
    const SceneSpec back = parse_scene(printed.out, "printed.json");
    BOOST_TEST(to_json(back) == to_json(load_scene_file(map_path(name))));
    const TempDir dir;
    const std::string file = dir.file("printed.json", printed.out);
    const Ran a = cli({"--scene", map_path(name), "--headless", "--frames", "60", "--dump", dir.file("a.csv")});
    const Ran b = cli({"--scene", file, "--headless", "--frames", "60", "--dump", dir.file("b.csv")});
    BOOST_TEST_REQUIRE(a.code == 0);
    BOOST_TEST_REQUIRE(b.code == 0);
    BOOST_TEST(read(dir.file("a.csv")) == read(dir.file("b.csv")));
  }
}

// A tile object (a gid) is anchored at its bottom-left corner; a group's
// offset moves the layers in it.
BOOST_AUTO_TEST_CASE(tile_objects_and_group_offsets_place_the_blocks_as_tiled_draws_them) {
  const TempDir dir;
  dir.file("props.tsj", read(map_path("props.tsj")));
  json m = map_json("platform.tmj");
  tiled_object(m, "crate")["gid"] = 1;
  json objects = tiled_layer(m, "objects");
  m["layers"].erase(2);
  m["layers"].push_back({{"name", "group"}, {"type", "group"}, {"offsetx", 10}, {"offsety", -4},
                         {"layers", json::array({objects})}});
  const SceneSpec s = load_scene_file(dir.file("moved.tmj", m.dump()));
  BOOST_TEST(block(s, 0).pos.x == 70.0);   // 60 + 10
  BOOST_TEST(block(s, 0).pos.y == 236.0);  // 240 - 4
  BOOST_TEST(block(s, 1).pos.x == 210.0);
  BOOST_TEST(block(s, 1).pos.y == 236.0 - 24 - 4);  // y is the bottom: 236 - height, then the offset
}

// A map named without a folder is a file (the command line's check for a scene
// name), and one that is not there says so.
BOOST_AUTO_TEST_CASE(a_map_in_the_current_folder_is_found_by_its_name) {
  const TempDir dir;
  dir.file("props.tsj", read(map_path("props.tsj")));
  dir.file("platform.tmj", read(map_path("platform.tmj")));
  const Ran r = program(dir, no_display, {"--scene", "platform.tmj", "--headless", "--frames", "10"});
  BOOST_TEST(r.code == 0, r.err);
  const Ran missing = program(dir, no_display, {"--scene", "nope.ldtk", "--headless"});
  BOOST_TEST(missing.code == 2);
  BOOST_TEST(has(missing.err, "nope.ldtk: cannot read the scene file"), missing.err);
}

BOOST_AUTO_TEST_CASE(tiled_maps_it_does_not_take_are_one_line_errors) {
  const auto set = [](const char* key, json v) { return [key, v](json& m) { m[key] = v; }; };
  expect_map_error("platform.tmj", set("infinite", true), "infinite maps are not supported");
  expect_map_error("platform.tmj", set("orientation", "isometric"), "orientation \"isometric\" is not supported");
  expect_map_error("platform.tmj", set("tileheight", 10), "tiles of 20 x 10 px are not supported");
  expect_map_error("platform.tmj", [](json& m) { m["tilesets"][0]["tilewidth"] = 32; }, "tiles of 32 x 20 px on a map of 20 px tiles");
  expect_map_error("platform.tmj", [](json& m) { m["tilesets"][1]["source"] = "props.tsx"; }, "is not JSON: save it as .tsj");
  expect_map_error("platform.tmj", [](json& m) { tiled_layer(m, "ground")["data"] = "AAAA"; }, "base64 layer data is not supported");
  expect_map_error("platform.tmj", [](json& m) { tiled_layer(m, "ground")["encoding"] = "base64"; }, "base64 layer data is not supported");
  expect_map_error("platform.tmj", [](json& m) { tiled_layer(m, "ground")["compression"] = "zlib"; }, "compressed layer data is not supported");
  expect_map_error("platform.tmj", [](json& m) { tiled_layer(m, "ground")["data"][3] = 99; }, "layers[0] \"ground\".data[3]: gid 99 is in no tileset");
  expect_map_error("platform.tmj", [](json& m) { tiled_layer(m, "ground")["data"].erase(0); }, "449 gids for a layer of 30 x 15 tiles");
  expect_map_error("platform.tmj", [](json& m) { tiled_object(m, "crate")["ellipse"] = true; }, "object 2 \"crate\": ellipse objects are not supported");
  expect_map_error("platform.tmj", [](json& m) { tiled_object(m, "crate")["point"] = true; }, "point objects are not supported");
  expect_map_error("platform.tmj", [](json& m) { tiled_object(m, "crate")["polygon"] = json::array(); }, "polygon objects are not supported");
  expect_map_error("platform.tmj", [](json& m) { tiled_object(m, "crate")["rotation"] = 30; }, "rotated objects are not supported (rotation 30)");
  expect_map_error("platform.tmj", [](json& m) { tiled_object(m, "crate").erase("width"); }, "object 2 \"crate\": missing field \"width\"");
  expect_map_error("platform.tmj", [](json& m) { m.erase("tilewidth"); }, "missing field \"tilewidth\"");
  expect_map_error("platform.tmj", [](json& m) { tiled_object(m, "crate")["properties"][0]["type"] = "file"; },
                   "property \"color\": property type \"file\" is not supported");
  // A property's value goes through the scene file's key rows: the same names, ranges and hints.
  expect_map_error("platform.tmj", [](json& m) { tiled_object(m, "crate")["properties"][1]["value"] = -2; },
                   "layers[2] \"objects\", object 2 \"crate\", key mass: must be > 0");
  expect_map_error("platform.tmj", [](json& m) { tiled_object(m, "crate")["properties"][1]["name"] = "mas"; },
                   "unknown key (did you mean \"mass\"?)");
  expect_map_error("platform.tmj", [](json& m) { m["properties"][1]["value"] = "0;0.001"; }, "world.gravity: must be an array of two numbers");
  expect_map_error("platform.tmj", [](json& m) { m["properties"][0]["name"] = "width"; }, "the world's size is the map's");
  expect_map_error("platform.tmj", [](json& m) { m["tilesets"][1]["source"] = "gone.tsj"; }, "gone.tsj: cannot read the tileset");
  expect_map_error("platform.tmj", [](json& m) { m["tilesets"][0]["tiles"][0]["properties"][0]["value"] = "yes"; },
                   "tilesets[0] \"terrain\", tile 1, property \"one_way\": must be a bool property");
  expect_map_error("platform.tmj", [](json& m) { tiled_layer(m, "ground")["type"] = "tiles"; }, "layer type \"tiles\" is not a Tiled layer");
  // Found by make fuzz's map loaders (and by hand): a tile listed in a tileset
  // of none read as "an integer in [0, -1]"; a tileset that is a pipe blocked the load.
  expect_map_error("platform.tmj", [](json& m) { m["tilesets"][0]["tilecount"] = 0; },
                   "tilesets[0] \"terrain\": lists tiles but has none (tilecount 0)");
  // A tile listed twice has two kinds, or the same one twice: which wins would be a guess.
  expect_map_error("platform.tmj", [](json& m) { m["tilesets"][0]["tiles"].push_back(m["tilesets"][0]["tiles"][0]); },
                   "tilesets[0] \"terrain\": lists tile 1 twice");
  {
    const TempDir fifo_dir;
    const std::string fifo = (fifo_dir.path / "pipe.tsj").string();
    BOOST_TEST_REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    json m = map_json("platform.tmj");
    m["tilesets"][1]["source"] = "pipe.tsj";
    const std::string file = fifo_dir.file("platform.tmj", m.dump());
    expect_bad({"--scene", file, "--headless", "--frames", "1"}, fifo + ": cannot read the tileset: not a regular file");
  }
  // Bad JSON: line and column.
  const TempDir dir;
  const std::string bad = dir.file("bad.tmj", "{\n  \"orientation\": \"orthogonal\",\n  oops\n}");
  expect_bad({"--scene", bad, "--headless"}, bad + ":3:3: invalid JSON");
  expect_bad({"--scene", dir.file("missing.tmj"), "--headless"}, "cannot read");
}

BOOST_AUTO_TEST_CASE(ldtk_projects_it_does_not_take_are_one_line_errors) {
  expect_map_error("level.ldtk", [](json& m) { m["externalLevels"] = true; }, "external levels (.ldtkl files) are not supported");
  expect_map_error("level.ldtk", [](json& m) { m["levels"] = json::array(); }, "the project has no level");
  expect_map_error("level.ldtk", [](json& m) { m.erase("levels"); m.erase("worlds"); }, "missing field \"levels\"");
  expect_map_error("level.ldtk", [](json& m) { m["levels"][0]["layerInstances"] = nullptr; }, "no layerInstances");
  expect_map_error("level.ldtk", [](json& m) { ldtk_layer(m, "IntGrid")["intGridCsv"][5] = 3; },
                   "IntGrid value 3 is neither solid");
  expect_map_error("level.ldtk", [](json& m) { ldtk_layer(m, "IntGrid")["intGridCsv"].erase(0); },
                   "intGridCsv: must be an array of 20 x 12 values");
  expect_map_error("level.ldtk", [](json& m) { ldtk_layer(m, "Entities")["entityInstances"][0]["fieldInstances"][0]["__type"] = "Point"; },
                   "entity 0 \"Player\", field \"tag\": field type \"Point\" is not supported");
  expect_map_error("level.ldtk", [](json& m) { ldtk_layer(m, "Entities")["entityInstances"][1]["fieldInstances"][0]["__value"] = "x"; },
                   "field \"mass\": a int property whose value is not a number");
  expect_map_error("level.ldtk", [](json& m) { ldtk_layer(m, "Entities")["entityInstances"][0].erase("px"); },
                   "entity 0 \"Player\": missing field \"px\"");
  expect_map_error("level.ldtk", [](json& m) { m["levels"][0]["fieldInstances"][3]["__value"] = "often"; },
                   "field \"walls\": a bool property whose value is not true or false");
  expect_map_error("level.ldtk", [](json& m) { m["levels"][0]["fieldInstances"][2]["__value"] = "fast"; }, "world.solver: ");
  const TempDir dir;
  const std::string bad = dir.file("bad.ldtk", "{\"levels\": [1, 2,]}");
  expect_bad({"--scene", bad, "--headless"}, bad + ":1:18: invalid JSON");
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_maps
