#include "scene/tiled.hpp"

// A Tiled map into the scene file's document (map.hpp): every tile layer an
// entry of "tiles", every object layer's rectangle a block, the map's
// properties the world's keys.
#include <algorithm>
#include <cstdint>
#include <filesystem>

#include "scene/map.hpp"
#include "scene/scene_json.hpp"

namespace physics {
namespace {

using map_io::fail;
using map_io::json;
using map_io::MapScene;
using map_io::need;
using map_io::integer;
using map_io::number;
using map_io::text;

constexpr std::int64_t max_side = std::int64_t{1} << 20;
constexpr std::uint64_t gid_flags = 0xF0000000u;  // flips and rotation: a flipped tile collides as it is

// A tileset: its gids [first, first + count), the kind of each tile whose
// properties make it other than solid.
struct Tileset {
  std::int64_t first = 1, count = 0;
  // The listed tiles, id << 8 | kind, sorted (a binary search per cell; a
  // hash table would add its code to the web build for this alone). A tile
  // not listed is solid.
  std::vector<std::uint64_t> kinds;
};

// What the readers of one map share: the file, its folder, its tile size, its tilesets.
struct Map {
  const std::string& source;
  std::filesystem::path folder;
  std::int64_t tile = 0;
  std::vector<Tileset> sets;
};

bool flag(const json& obj, const char* key) {
  const auto it = obj.find(key);
  return it != obj.end() && it->is_boolean() && it->get<bool>();
}
// " \"name\"" for an object or layer with a name, else "".
std::string named(const json& obj) {
  const auto it = obj.find("name");
  return it != obj.end() && it->is_string() && !it->get_ref<const std::string&>().empty()
             ? " \"" + it->get<std::string>() + "\""
             : "";
}

// f(name, type, value, where) for each of obj's custom properties
// ([{"name", "type", "value"}], type "string" when absent).
template <class F>
void each_property(const Map& c, const json& obj, const std::string& what, F&& f) {
  const auto it = obj.find("properties");
  if (it == obj.end()) return;
  if (!it->is_array()) fail(c.source, what, "\"properties\" must be an array");
  for (const json& p : *it) {
    const std::string name = text(c.source, need(p, "name", c.source, what + ", a property"), what + ", a property's name");
    const std::string where = c.source + ": " + what + ", property \"" + name + "\"";
    const auto type = p.find("type");
    const std::string t = type == p.end() ? "string" : text(c.source, *type, what + ", property \"" + name + "\" type");
    f(name, t, need(p, "value", c.source, what + ", property \"" + name + "\""), where);
  }
}

// A tileset's tile: one-way if its property one_way is true, empty if its
// property solid is false, else solid (other properties are the game's).
char tile_kind(const Map& c, const json& tile, const std::string& what) {
  bool one_way = false, solid = true;
  each_property(c, tile, what, [&](const std::string& name, const std::string&, const json& v, const std::string& where) {
    if (name != "one_way" && name != "solid") return;
    if (!v.is_boolean()) throw SceneError(where + ": must be a bool property");
    (name == "one_way" ? one_way : solid) = v.get<bool>();
  });
  return !solid ? map_io::empty_cell : one_way ? map_io::one_way_cell : map_io::solid_cell;
}

// An embedded tileset, or the external one (.tsj) it names.
Tileset read_tileset(const Map& c, const json& ref, const std::string& at) {
  Tileset t;
  t.first = integer(c.source, need(ref, "firstgid", c.source, at), at + ".firstgid", 1, std::int64_t{1} << 28);
  json external;
  const json* set = &ref;
  std::string what = at;
  if (const auto src = ref.find("source"); src != ref.end()) {
    const std::string file = text(c.source, *src, at + ".source");
    if (!file.ends_with(".tsj") && !file.ends_with(".json"))
      fail(c.source, at, "tileset \"" + file + "\" is not JSON: save it as .tsj (XML tilesets are not supported)");
    const std::string path = (c.folder / file).string();
    // A file Tiled wrote: a pipe or a device (a map naming one, as a .tsj
    // link to /dev/stdin) would block the load or read on without end.
    std::error_code ec;
    if (const auto st = std::filesystem::status(path, ec);
        !ec && std::filesystem::exists(st) && !std::filesystem::is_regular_file(st) && !std::filesystem::is_directory(st))
      fail(c.source, at, path + ": cannot read the tileset: not a regular file");
    try {
      external = map_io::parse(read_input_file(path, "tileset"), path);
    } catch (const SceneError& e) {
      fail(c.source, at, e.what());  // the map's error: its tileset's file names the problem
    }
    set = &external;
    what = at + " (" + file + ")";
  }
  what += named(*set);
  const std::int64_t w = integer(c.source, need(*set, "tilewidth", c.source, what), what + ".tilewidth", 1, max_side);
  const std::int64_t h = integer(c.source, need(*set, "tileheight", c.source, what), what + ".tileheight", 1, max_side);
  if (w != c.tile || h != c.tile)
    fail(c.source, what, "tiles of " + std::to_string(w) + " x " + std::to_string(h) + " px on a map of " +
                             std::to_string(c.tile) + " px tiles: a tileset's tiles must be the map's size");
  t.count = integer(c.source, need(*set, "tilecount", c.source, what), what + ".tilecount", 0, std::int64_t{1} << 28);
  if (const auto tiles = set->find("tiles"); tiles != set->end() && tiles->is_array())
    for (const json& tile : *tiles) {
      if (t.count == 0) fail(c.source, what, "lists tiles but has none (tilecount 0)");
      const std::int64_t id = integer(c.source, need(tile, "id", c.source, what + ", a tile"), what + ", a tile's id", 0, t.count - 1);
      const char k = tile_kind(c, tile, what + ", tile " + std::to_string(id));
      t.kinds.push_back(std::uint64_t(id) << 8 | static_cast<unsigned char>(k));
    }
  std::sort(t.kinds.begin(), t.kinds.end());
  for (std::size_t i = 1; i < t.kinds.size(); ++i)
    if (t.kinds[i] >> 8 == t.kinds[i - 1] >> 8)
      fail(c.source, what, "lists tile " + std::to_string(t.kinds[i] >> 8) + " twice");
  return t;
}

std::vector<Tileset> read_tilesets(const Map& c, const json& map) {
  std::vector<Tileset> out;
  const auto it = map.find("tilesets");
  if (it == map.end()) return out;
  if (!it->is_array()) fail(c.source, "tilesets", "must be an array");
  for (std::size_t i = 0; i < it->size(); ++i) out.push_back(read_tileset(c, (*it)[i], "tilesets[" + std::to_string(i) + "]"));
  std::sort(out.begin(), out.end(), [](const Tileset& a, const Tileset& b) { return a.first < b.first; });
  return out;
}

// The cell a gid makes: 0 empty, else its tile's kind.
char cell_of(const Map& c, std::uint64_t raw, const std::string& what, std::size_t index) {
  const auto gid = static_cast<std::int64_t>(raw & ~gid_flags);
  if (gid == 0) return map_io::empty_cell;
  auto set = std::upper_bound(c.sets.begin(), c.sets.end(), gid, [](std::int64_t g, const Tileset& t) { return g < t.first; });
  if (set == c.sets.begin() || gid - (--set)->first >= set->count)
    fail(c.source, what + ".data[" + std::to_string(index) + "]", "gid " + std::to_string(gid) + " is in no tileset");
  const std::uint64_t id = static_cast<std::uint64_t>(gid - set->first);
  const auto k = std::lower_bound(set->kinds.begin(), set->kinds.end(), id << 8);
  return k != set->kinds.end() && *k >> 8 == id ? static_cast<char>(*k & 0xff) : map_io::solid_cell;
}

// A tile layer (CSV data: an array of gids, row by row) as an entry of "tiles".
void tile_layer(const Map& c, const json& layer, Vector offset, const std::string& what, MapScene& m) {
  if (layer.contains("chunks")) fail(c.source, what, "chunked layer data (an infinite map) is not supported");
  const auto enc = layer.find("encoding");
  const auto zip = layer.find("compression");
  const json& data = need(layer, "data", c.source, what);
  if ((zip != layer.end() && !(zip->is_string() && zip->get_ref<const std::string&>().empty())))
    fail(c.source, what, "compressed layer data is not supported: save the map with the tile layer format CSV");
  if ((enc != layer.end() && *enc != "csv") || data.is_string())
    fail(c.source, what, "base64 layer data is not supported: save the map with the tile layer format CSV");
  if (!data.is_array()) fail(c.source, what + ".data", "must be an array of gids");
  const std::int64_t w = integer(c.source, need(layer, "width", c.source, what), what + ".width", 1, max_side);
  const std::int64_t h = integer(c.source, need(layer, "height", c.source, what), what + ".height", 1, max_side);
  if (static_cast<std::int64_t>(data.size()) != w * h)
    fail(c.source, what + ".data", std::to_string(data.size()) + " gids for a layer of " + std::to_string(w) + " x " +
                                       std::to_string(h) + " tiles");
  json tiles = json::object();
  bool collides = true;
  each_property(c, layer, what, [&](const std::string& name, const std::string& type, const json& v, const std::string& where) {
    if (name != "collision") return map_io::set_tile_property(tiles, name, type, v, where);
    if (!v.is_boolean()) throw SceneError(where + ": must be a bool property");
    collides = v.get<bool>();
  });
  if (!collides) return;
  std::vector<std::string> rows(static_cast<std::size_t>(h), std::string(static_cast<std::size_t>(w), map_io::empty_cell));
  for (std::size_t i = 0; i < data.size(); ++i) {
    if (!data[i].is_number_unsigned() || data[i].get<std::uint64_t>() > 0xFFFFFFFFu)
      fail(c.source, what + ".data[" + std::to_string(i) + "]", "must be a gid, an integer in [0, 2^32 - 1]");
    rows[i / static_cast<std::size_t>(w)][i % static_cast<std::size_t>(w)] = cell_of(c, data[i].get<std::uint64_t>(), what, i);
  }
  tiles["pos"] = {offset.x, offset.y};
  tiles["cell"] = c.tile;
  tiles["rows"] = std::move(rows);
  m.doc["tiles"].push_back(std::move(tiles));
  m.tiles.push_back(what);
}

// An object: a rectangle (a tile object too, anchored at its bottom-left
// corner as Tiled draws it) as a block, fixed unless its properties give a mass.
void object(const Map& c, const json& obj, Vector offset, const std::string& what, MapScene& m) {
  for (const char* shape : {"ellipse", "point"})
    if (flag(obj, shape)) fail(c.source, what, std::string(shape) + " objects are not supported: only rectangles");
  for (const char* shape : {"polygon", "polyline", "text"})
    if (obj.contains(shape)) fail(c.source, what, std::string(shape) + " objects are not supported: only rectangles");
  if (obj.contains("template")) fail(c.source, what, "template instances are not supported: detach the template");
  if (const auto r = obj.find("rotation"); r != obj.end() && number(c.source, *r, what + ".rotation") != 0)
    fail(c.source, what, "rotated objects are not supported (rotation " + r->dump() + "): blocks are axis-aligned");
  const double x = number(c.source, need(obj, "x", c.source, what), what + ".x");
  double y = number(c.source, need(obj, "y", c.source, what), what + ".y");
  const json& w = need(obj, "width", c.source, what);
  const json& h = need(obj, "height", c.source, what);
  if (obj.contains("gid")) y -= number(c.source, h, what + ".height");
  json block = {{"pos", {x + offset.x, y + offset.y}}, {"size", {w, h}}};
  each_property(c, obj, what, [&](const std::string& name, const std::string& type, const json& v, const std::string& where) {
    map_io::set_block_property(block, name, type, v, where);
  });
  if (!block.contains("mass")) block["mass"] = "inf";
  m.doc["blocks"].push_back(std::move(block));
  m.blocks.push_back(what);
}

void layers(const Map& c, const json& list, Vector offset, const std::string& at, MapScene& m) {
  if (!list.is_array()) fail(c.source, at, "must be an array of layers");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const json& layer = list[i];
    const std::string what = at + "[" + std::to_string(i) + "]" + named(layer);
    const std::string type = text(c.source, need(layer, "type", c.source, what), what + ".type");
    Vector off = offset;
    if (const auto ox = layer.find("offsetx"); ox != layer.end()) off.x += number(c.source, *ox, what + ".offsetx");
    if (const auto oy = layer.find("offsety"); oy != layer.end()) off.y += number(c.source, *oy, what + ".offsety");
    if (type == "tilelayer") {
      tile_layer(c, layer, off, what, m);
    } else if (type == "objectgroup") {
      const json& objects = need(layer, "objects", c.source, what);
      if (!objects.is_array()) fail(c.source, what + ".objects", "must be an array");
      for (const json& obj : objects) {
        const auto id = obj.find("id");
        object(c, obj, off, what + ", object " + (id == obj.end() ? std::string("?") : id->dump()) + named(obj), m);
      }
    } else if (type == "group") {
      layers(c, need(layer, "layers", c.source, what), off, what + ".layers", m);
    } else if (type != "imagelayer") {  // an image collides with nothing
      fail(c.source, what, "layer type \"" + type + "\" is not a Tiled layer (tilelayer, objectgroup, group, imagelayer)");
    }
  }
}

}  // namespace

SceneSpec read_tiled(std::string_view text_in, const std::string& path) {
  const json map = map_io::parse(text_in, path);
  Map c{path, std::filesystem::path(path).parent_path(), 0, {}};
  const std::string orientation = text(c.source, need(map, "orientation", path, ""), "orientation");
  if (orientation != "orthogonal")
    fail(path, "", "orientation \"" + orientation + "\" is not supported: only orthogonal maps");
  if (flag(map, "infinite")) fail(path, "", "infinite maps are not supported: give the map a fixed size (Map Properties, Infinite off)");
  const std::int64_t w = integer(c.source, need(map, "width", path, ""), "width", 1, max_side);
  const std::int64_t h = integer(c.source, need(map, "height", path, ""), "height", 1, max_side);
  const std::int64_t tw = integer(c.source, need(map, "tilewidth", path, ""), "tilewidth", 1, max_side);
  const std::int64_t th = integer(c.source, need(map, "tileheight", path, ""), "tileheight", 1, max_side);
  if (tw != th)
    fail(path, "", "tiles of " + std::to_string(tw) + " x " + std::to_string(th) +
                       " px are not supported: a tile layer's cells are square");
  c.tile = tw;
  c.sets = read_tilesets(c, map);
  MapScene m;
  m.doc["world"] = {{"width", w * tw}, {"height", h * th}};
  m.doc["blocks"] = json::array();
  m.doc["tiles"] = json::array();
  each_property(c, map, "map", [&](const std::string& name, const std::string& type, const json& v, const std::string& where) {
    map_io::set_scene_property(m, name, type, v, where);
  });
  layers(c, need(map, "layers", path, ""), {0, 0}, "layers", m);
  return map_io::finish(m, path);
}

}  // namespace physics
