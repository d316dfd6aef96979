// Maps from the level editors people use, Tiled (.tmj, tiled.hpp) and LDtk
// (.ldtk, ldtk.hpp), read as scenes (docs/scenes.md, "Maps from Tiled and
// LDtk"). A map is not read into a SceneSpec directly: each loader turns it
// into the scene file's document (a tile layer into an entry of "tiles", an
// object or entity into a block, the map's properties into "world" keys) and
// that document goes through the scene file reader and the validator, so
// every key is read and checked by its one row of the key table (keys.hpp).
// What this header shares between the two loaders: the parse, the property
// values by the key rows' types, and the finish that names the map's object
// in an error about the block it became.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scene/json_reader.hpp"
#include "scene/scene.hpp"

namespace physics {

// The map's scene, read and validated (tiled.hpp, ldtk.hpp by the name).
// Throws SceneError "path: problem", one line.
SceneSpec read_map(std::string_view text, const std::string& path);

}  // namespace physics

namespace physics::map_io {

using scene_io::json;

// The scene a map becomes, as the scene file's document, with where each of
// its blocks and tile layers came from ("layer \"objects\" object 7
// \"crate\""), to name them in errors.
struct MapScene {
  json doc = json::object();
  std::vector<std::string> blocks, tiles;
};

// The map file's JSON (strict: duplicate keys are errors; comments allowed).
json parse(std::string_view text, const std::string& source);

// An editor's custom property `name` of `type` ("string", "int", "float",
// "bool", "color") with `value`, set as a key of the scene document: a string
// by the key's type as the command line reads it ("0,0.001" for [x, y], by
// value_of_text), a colour "#aarrggbb" as "#rrggbb", a number or a boolean as
// it is; the key is then read by the scene reader, which refuses an unknown
// one. `where` names the property in an error (a type it does not take).
// A map property `name` into the scene document: "name", "description",
// "style" at the top level, "game.KEY" (or "game_KEY") into "game", any other
// into "world" (width and height are the map's: refused).
void set_scene_property(MapScene& m, const std::string& name, std::string_view type, const json& value,
                        const std::string& where);
// An object's (or entity's) property into its block's object, a tile
// layer's into its entry of "tiles" (pos, size, cell and rows are the map's
// geometry: refused).
void set_block_property(json& block, const std::string& name, std::string_view type, const json& value,
                        const std::string& where);
void set_tile_property(json& tiles, const std::string& name, std::string_view type, const json& value,
                       const std::string& where);

// "source: what: problem" as a SceneError, the loaders' one error.
[[noreturn]] void fail(const std::string& source, const std::string& what, const std::string& problem);
// A member the format requires, or the error "missing field".
const json& need(const json& obj, const char* key, const std::string& source, const std::string& what);
// A value read by the scene reader's rules (scene_io::Reader), its error
// naming the map file and `what`.
std::int64_t integer(const std::string& source, const json& v, const std::string& what, std::int64_t lo,
                     std::int64_t hi);
double number(const std::string& source, const json& v, const std::string& what);
std::string text(const std::string& source, const json& v, const std::string& what);

// The document read as a scene file and validated; an error about blocks[i]
// or tiles[i] names the map's object or layer instead. Throws SceneError.
SceneSpec finish(const MapScene& m, const std::string& source);

// Tile layer rows: a cell kind's character ('#', '=', '.': TileSpec).
inline constexpr char solid_cell = '#', one_way_cell = '=', empty_cell = '.';

}  // namespace physics::map_io
