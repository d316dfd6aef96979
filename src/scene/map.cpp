#include "scene/map.hpp"

// What the Tiled and LDtk loaders share: the parse, the properties as scene
// keys by the key table's rows, and the finish through the scene reader.
#include <algorithm>
#include <charconv>

#include "scene/json_parse.hpp"
#include "scene/keys.hpp"
#include "scene/ldtk.hpp"
#include "scene/scene_json.hpp"
#include "scene/tiled.hpp"

namespace physics {

bool is_map_file(std::string_view path) { return path.ends_with(".tmj") || path.ends_with(".ldtk"); }

SceneSpec read_map(std::string_view text, const std::string& path) {
  return path.ends_with(".ldtk") ? read_ldtk(text, path) : read_tiled(text, path);
}

}  // namespace physics

namespace physics::map_io {

using scene_io::KeyDoc;

namespace {

// The doc of the key `name` among rows (Key<Spec> rows or KeyDocs), or null.
template <class Rows>
const KeyDoc* doc_of(const Rows& rows, std::string_view name) {
  for (const auto& row : rows) {
    const KeyDoc* d = nullptr;
    if constexpr (std::is_same_v<std::decay_t<decltype(row)>, KeyDoc>) d = &row;
    else d = &row.doc;
    if (name == d->name()) return d;
  }
  return nullptr;
}

// The property's value as the JSON the key's row reads (doc: the key's, null
// for a key the table does not have: the reader then names it unknown).
json value_for(const KeyDoc* doc, std::string_view type, const json& value, const std::string& where) {
  const auto wrong = [&](const char* what) {
    throw SceneError(where + ": a " + std::string(type) + " property whose value is not " + what);
  };
  if (type == "string") {
    if (!value.is_string()) wrong("a string");
    if (doc)
      if (std::optional<json> v = scene_io::value_of_text(*doc, value.get_ref<const std::string&>())) return *v;
    return value;
  }
  if (type == "int" || type == "float") {
    if (!value.is_number()) wrong("a number");
    return value;
  }
  if (type == "bool") {
    if (!value.is_boolean()) wrong("true or false");
    return value;
  }
  if (type == "color") {
    if (!value.is_string()) wrong("a colour string");
    const std::string& c = value.get_ref<const std::string&>();
    return c.size() == 9 && c[0] == '#' ? json("#" + c.substr(3)) : value;  // #aarrggbb: the alpha dropped
  }
  throw SceneError(where + ": property type \"" + std::string(type) +
                   "\" is not supported (string, int, float, bool or color)");
}

void set_once(json& obj, const std::string& key, json value, const std::string& where) {
  if (obj.contains(key)) throw SceneError(where + ": \"" + key + "\" is set twice");
  obj[key] = std::move(value);
}

template <class Rows>
void set_key(json& obj, const Rows& rows, const std::string& name, std::string_view type, const json& value,
             const std::string& where, std::initializer_list<std::string_view> geometry) {
  if (std::find(geometry.begin(), geometry.end(), name) != geometry.end())
    throw SceneError(where + ": \"" + name + "\" is the map's geometry, not a property");
  set_once(obj, name, value_for(doc_of(rows, name), type, value, where), where);
}

// "blocks[12]..." in a message: 12 and what follows "]", or none.
std::optional<std::pair<std::size_t, std::string>> indexed(const std::string& rest, std::string_view list) {
  if (!rest.starts_with(list) || rest.size() <= list.size() || rest[list.size()] != '[') return std::nullopt;
  std::size_t i = 0;
  const char* first = rest.data() + list.size() + 1;
  const auto [end, ec] = std::from_chars(first, rest.data() + rest.size(), i);
  if (ec != std::errc{} || *end != ']') return std::nullopt;
  return std::pair{i, std::string(end + 1)};
}

// The scene reader's message about blocks[i] or tiles[i], naming the map's
// object or layer instead: "map.tmj: blocks[3].mass: ..." becomes
// "map.tmj: layer "objects" object 7 "crate", key mass: ...".
std::string renamed(const std::string& message, const MapScene& m, const std::string& source) {
  const std::string prefix = source + ": ";
  if (!message.starts_with(prefix)) return message;
  const std::string rest = message.substr(prefix.size());
  for (const auto& [list, names] : {std::pair{"blocks", &m.blocks}, std::pair{"tiles", &m.tiles}}) {
    const auto at = indexed(rest, list);
    if (!at || at->first >= names->size()) continue;
    const std::string& tail = at->second;
    return prefix + (*names)[at->first] + (tail.starts_with(".") ? ", key " + tail.substr(1) : tail);
  }
  return message;
}

}  // namespace

json parse(std::string_view text, const std::string& source) {
  scene_io::StrictDom dom;
  scene_io::parse_strict(text, source, dom);
  if (!dom.root.is_object()) throw SceneError(source + ": a map file must hold one JSON object {...}");
  return std::move(dom.root);
}

void set_scene_property(MapScene& m, const std::string& name, std::string_view type, const json& value,
                        const std::string& where) {
  if (name == "width" || name == "height")
    throw SceneError(where + ": \"" + name + "\": the world's size is the map's");
  if (name == "name" || name == "description" || name == "style") {
    set_once(m.doc, name, value_for(doc_of(scene_io::scene_keys(), name), type, value, where), where);
  } else if (name.starts_with("game.") || name.starts_with("game_")) {
    const std::string key = name.substr(5);
    set_key(m.doc["game"], scene_io::game_keys(), key, type, value, where, {});
  } else {
    set_key(m.doc["world"], scene_io::world_keys(), name, type, value, where, {});
  }
}

void set_block_property(json& block, const std::string& name, std::string_view type, const json& value,
                        const std::string& where) {
  set_key(block, scene_io::block_keys(), name, type, value, where, {"pos", "size"});
}

void set_tile_property(json& tiles, const std::string& name, std::string_view type, const json& value,
                       const std::string& where) {
  set_key(tiles, scene_io::tile_keys(), name, type, value, where, {"pos", "cell", "rows"});
}

void fail(const std::string& source, const std::string& what, const std::string& problem) {
  throw SceneError(source + ": " + (what.empty() ? "" : what + ": ") + problem);
}

const json& need(const json& obj, const char* key, const std::string& source, const std::string& what) {
  if (!obj.is_object()) fail(source, what, "must be an object {...}");
  const auto it = obj.find(key);
  if (it == obj.end()) fail(source, what, std::string("missing field \"") + key + "\"");
  return *it;
}

std::int64_t integer(const std::string& source, const json& v, const std::string& what, std::int64_t lo,
                     std::int64_t hi) {
  return scene_io::Reader(source).integer(v, what.c_str(), lo, hi);
}
double number(const std::string& source, const json& v, const std::string& what) {
  return scene_io::Reader(source).number(v, what.c_str());
}
std::string text(const std::string& source, const json& v, const std::string& what) {
  return scene_io::Reader(source).text(v, what.c_str());
}

SceneSpec finish(const MapScene& m, const std::string& source) {
  try {
    SceneSpec s = read_scene(m.doc.dump(), source);
    expand(s, source);  // every check, placement included: the errors name the map's objects
    return s;
  } catch (const SceneError& e) {
    throw SceneError(renamed(e.what(), m, source));
  }
}

}  // namespace physics::map_io
