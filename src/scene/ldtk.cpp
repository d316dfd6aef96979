#include "scene/ldtk.hpp"

// An LDtk project's first level into the scene file's document (map.hpp):
// every IntGrid layer an entry of "tiles", every entity a block, the level's
// fields the world's keys.
#include <cstdint>

#include "scene/map.hpp"

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

struct Project {
  const std::string& source;
  const json& defs;  // "defs": the layers' IntGrid values
};

double offset(const Project& p, const json& layer, const char* key, const std::string& what) {
  const auto it = layer.find(key);
  return it == layer.end() ? 0.0 : number(p.source, *it, what + "." + key);
}

// An LDtk field type as the map properties' ("string", "int", ...); enums
// are their value's name. Anything else is not supported.
std::string field_type(const Project& p, const std::string& type, const std::string& where) {
  if (type == "Int") return "int";
  if (type == "Float") return "float";
  if (type == "Bool") return "bool";
  if (type == "Color") return "color";
  if (type == "String" || type == "Multilines" || type.starts_with("LocalEnum.") || type.starts_with("ExternEnum."))
    return "string";
  fail(p.source, where, "field type \"" + type + "\" is not supported (Int, Float, Bool, String, Color or an enum)");
}

// f(name, type, value, where) for each field of obj ("fieldInstances") that
// has a value (a null one keeps the key's default).
template <class F>
void each_field(const Project& p, const json& obj, const std::string& what, F&& f) {
  const auto it = obj.find("fieldInstances");
  if (it == obj.end()) return;
  if (!it->is_array()) fail(p.source, what, "\"fieldInstances\" must be an array");
  for (const json& field : *it) {
    const std::string name = text(p.source, need(field, "__identifier", p.source, what + ", a field"), what + ", a field's __identifier");
    const std::string at = what + ", field \"" + name + "\"";
    const json& value = need(field, "__value", p.source, at);
    const std::string type = text(p.source, need(field, "__type", p.source, at), at + ".__type");
    if (!value.is_null()) f(name, field_type(p, type, at), value, p.source + ": " + at);
  }
}

// The cell an IntGrid value makes: by its identifier "solid" or "one_way",
// else 1 solid and 2 one-way; 0 is empty, any other value an error.
char cell_kind(const Project& p, const json& values, std::int64_t v, const std::string& what) {
  if (v == 0) return map_io::empty_cell;
  std::string id;
  if (values.is_array())
    for (const json& def : values)
      if (def.is_object() && def.value("value", json()) == v && def.value("identifier", json()).is_string())
        id = def["identifier"].get<std::string>();
  if (id == "solid" || (id != "one_way" && v == 1)) return map_io::solid_cell;
  if (id == "one_way" || v == 2) return map_io::one_way_cell;
  fail(p.source, what, "IntGrid value " + std::to_string(v) + (id.empty() ? "" : " (\"" + id + "\")") +
                           " is neither solid (1, or identifier solid) nor one-way (2, or identifier one_way)");
}

// The IntGrid values of the layer definition `uid` (defs.layers[].intGridValues).
json values_of(const Project& p, const json& layer) {
  const auto uid = layer.find("layerDefUid");
  const auto layers = p.defs.find("layers");
  if (uid == layer.end() || layers == p.defs.end() || !layers->is_array()) return json();
  for (const json& def : *layers)
    if (def.is_object() && def.value("uid", json()) == *uid) return def.value("intGridValues", json());
  return json();
}

void intgrid_layer(const Project& p, const json& layer, const std::string& what, MapScene& m) {
  const std::int64_t w = integer(p.source, need(layer, "__cWid", p.source, what), what + ".__cWid", 1, max_side);
  const std::int64_t h = integer(p.source, need(layer, "__cHei", p.source, what), what + ".__cHei", 1, max_side);
  const std::int64_t cell = integer(p.source, need(layer, "__gridSize", p.source, what), what + ".__gridSize", 1, max_side);
  const json& csv = need(layer, "intGridCsv", p.source, what);
  if (!csv.is_array() || static_cast<std::int64_t>(csv.size()) != w * h)
    fail(p.source, what + ".intGridCsv", "must be an array of " + std::to_string(w) + " x " + std::to_string(h) + " values");
  const json values = values_of(p, layer);
  std::vector<std::string> rows(static_cast<std::size_t>(h), std::string(static_cast<std::size_t>(w), map_io::empty_cell));
  for (std::size_t i = 0; i < csv.size(); ++i) {
    const std::string at = csv[i].is_number_integer() ? what : what + ".intGridCsv[" + std::to_string(i) + "]";
    const std::int64_t v = integer(p.source, csv[i], at, 0, std::int64_t{1} << 31);
    rows[i / static_cast<std::size_t>(w)][i % static_cast<std::size_t>(w)] = cell_kind(p, values, v, what);
  }
  json tiles = {{"pos", {offset(p, layer, "__pxTotalOffsetX", what), offset(p, layer, "__pxTotalOffsetY", what)}},
                {"cell", cell},
                {"rows", std::move(rows)}};
  m.doc["tiles"].push_back(std::move(tiles));
  m.tiles.push_back(what);
}

// An entity: its box (px is its pivot's place in the layer) as a block,
// fixed unless its fields give a mass.
void entity(const Project& p, const json& e, Vector off, const std::string& what, MapScene& m) {
  const json& px = need(e, "px", p.source, what);
  if (!px.is_array() || px.size() != 2) fail(p.source, what + ".px", "must be [x, y]");
  const json& w = need(e, "width", p.source, what);
  const json& h = need(e, "height", p.source, what);
  Vector pivot{0, 0};
  if (const auto pv = e.find("__pivot"); pv != e.end()) {
    if (!pv->is_array() || pv->size() != 2) fail(p.source, what + ".__pivot", "must be [x, y]");
    pivot = {number(p.source, (*pv)[0], what + ".__pivot[0]"), number(p.source, (*pv)[1], what + ".__pivot[1]")};
  }
  const double x = number(p.source, px[0], what + ".px[0]") - pivot.x * number(p.source, w, what + ".width");
  const double y = number(p.source, px[1], what + ".px[1]") - pivot.y * number(p.source, h, what + ".height");
  json block = {{"pos", {x + off.x, y + off.y}}, {"size", {w, h}}};
  each_field(p, e, what, [&](const std::string& name, const std::string& type, const json& v, const std::string& where) {
    map_io::set_block_property(block, name, type, v, where);
  });
  if (!block.contains("mass")) block["mass"] = "inf";
  m.doc["blocks"].push_back(std::move(block));
  m.blocks.push_back(what);
}

void layer(const Project& p, const json& l, const std::string& what, MapScene& m) {
  const std::string type = text(p.source, need(l, "__type", p.source, what), what + ".__type");
  if (type == "IntGrid") return intgrid_layer(p, l, what, m);
  if (type != "Entities") return;  // Tiles and AutoLayer: pictures, no collision
  const json& list = need(l, "entityInstances", p.source, what);
  if (!list.is_array()) fail(p.source, what + ".entityInstances", "must be an array");
  const Vector off{offset(p, l, "__pxTotalOffsetX", what), offset(p, l, "__pxTotalOffsetY", what)};
  for (std::size_t i = 0; i < list.size(); ++i) {
    const auto id = list[i].find("__identifier");
    const std::string name = id != list[i].end() && id->is_string() ? " \"" + id->get<std::string>() + "\"" : "";
    entity(p, list[i], off, what + ", entity " + std::to_string(i) + name, m);
  }
}

// The first level: the root's levels, or the first world's (a multi-world project).
const json& first_level(const std::string& source, const json& root) {
  const auto levels = root.find("levels");
  if (levels != root.end() && levels->is_array() && !levels->empty()) return (*levels)[0];
  if (const auto worlds = root.find("worlds"); worlds != root.end() && worlds->is_array() && !worlds->empty()) {
    const json& list = need((*worlds)[0], "levels", source, "worlds[0]");
    if (list.is_array() && !list.empty()) return list[0];
  }
  if (levels == root.end() && !root.contains("worlds")) fail(source, "", "missing field \"levels\"");
  fail(source, "", "the project has no level");
}

}  // namespace

SceneSpec read_ldtk(std::string_view text_in, const std::string& path) {
  const json root = map_io::parse(text_in, path);
  if (const auto ext = root.find("externalLevels"); ext != root.end() && ext->is_boolean() && ext->get<bool>())
    fail(path, "", "external levels (.ldtkl files) are not supported: turn off \"Save levels to separate files\"");
  const json no_defs = json::object();
  const auto defs = root.find("defs");
  const Project p{path, defs != root.end() && defs->is_object() ? *defs : no_defs};
  const json& level = first_level(path, root);
  const auto id = level.is_object() ? level.find("identifier") : level.end();
  const std::string what = "level" + (id != level.end() && id->is_string() ? " \"" + id->get<std::string>() + "\"" : std::string(" 0"));
  MapScene m;
  m.doc["world"] = {{"width", integer(p.source, need(level, "pxWid", path, what), what + ".pxWid", 1, max_side)},
                    {"height", integer(p.source, need(level, "pxHei", path, what), what + ".pxHei", 1, max_side)}};
  m.doc["blocks"] = json::array();
  m.doc["tiles"] = json::array();
  each_field(p, level, what, [&](const std::string& name, const std::string& type, const json& v, const std::string& where) {
    map_io::set_scene_property(m, name, type, v, where);
  });
  const json& list = need(level, "layerInstances", path, what);
  if (list.is_null()) fail(path, what, "no layerInstances: the level is saved in a separate file (not supported)");
  if (!list.is_array()) fail(path, what + ".layerInstances", "must be an array");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const auto lid = list[i].is_object() ? list[i].find("__identifier") : list[i].end();
    const std::string name = lid != list[i].end() && lid->is_string() ? " \"" + lid->get<std::string>() + "\"" : "";
    layer(p, list[i], what + ", layer " + std::to_string(i) + name, m);
  }
  return map_io::finish(m, path);
}

}  // namespace physics
