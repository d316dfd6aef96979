// The keys of a scene file, one row each: its name, type, range, default and
// doc line; for a block's (and a grid's), the world's and the game's keys also
// how it is read, checked and written, and for a block's how it goes into the
// body and the world (or a game's role) and comes back from them. So one row
// drives the reader (scene_json.cpp), the validator (scene.cpp), the writer
// (--print-scene, scene_write.cpp), the building of a world (scene.cpp),
// --save (save.cpp), the command line's world flags (a world row with a
// `flag`: world_flags, read_world_flag; app/cli.cpp) and the key tables of
// docs/scenes.md (key_tables_markdown, written by tools/scene_keys.sh;
// tests/test_keys.cpp fails when they differ).
// Adding a block key: its field in BlockSpec (scene.hpp; and in Body for a key
// the physics reads, or in BlockRole for one the games read, each with a
// default member initializer) and its row in keys.cpp; then tools/scene_keys.sh.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "physics/physics.hpp"
#include "scene/checker.hpp"
#include "scene/json_reader.hpp"

namespace physics::scene_io {

// A key's meaning, for docs/scenes.md's tables and the command line's
// help. The browser build has neither: it leaves the texts out of its
// module (about 7 KB, docs/web.md), and a key's meaning reads "" there.
#if defined(__wasm__)
struct DocText {
  constexpr DocText(const char*) {}
  constexpr operator std::string_view() const { return {}; }
};
#else
using DocText = std::string_view;
#endif

// What the doc says of a key. `key` is as in a path, ".name": its name is
// what follows the dot.
struct KeyDoc {
  const char* key;
  std::string_view type, range, fallback;
  DocText doc;
  // A world key that is also a command-line flag (--name): what its help adds
  // to the doc ("" nothing); null: no flag. Its value's syntax comes from the type.
  const char* flag = nullptr;
  const char* name() const { return key + 1; }
};

// A key that the tables read, check and write into a `Spec`.
template <class Spec>
struct Key {
  KeyDoc doc;
  // A required key: what its absence's message adds, e.g. "([width, height], px)"; "" if optional.
  std::string_view missing = {};
  // v: the key's value; path: the key's path (".name" included).
  void (*read)(const Reader& r, const json& v, const Path& path, Spec& out) = nullptr;
  // Writes the key into o where it is not its default (or always, if the writer always did).
  void (*write)(ojson& o, const Spec& s) = nullptr;
  // The key's meaning (range, cross-key rules); base: the object's path ("world",
  // "blocks[3]"), the key's is base + doc.key; null: nothing to check.
  void (*check)(const scene_check::Checker& k, const Spec& s, const std::string& base) = nullptr;
  bool contact = false;  // a contact key: a random entry's too (for all its bodies)
  // Save: the key's value in a block saved from body e of a world made from
  // `from` (null: a key for the games, saved from the body's role below).
  void (*from_world)(const Components& k, EntityId e, const SceneSpec& from, Spec& out) = nullptr;
  // Building: the key's value in the body a block makes (`s` its scene: the
  // world's defaults), and from the body into the public API's def that
  // creates it (`dt`: the world's; null: nothing to do).
  void (*to_body)(const Spec& b, const SceneSpec& s, Body& out) = nullptr;
  void (*to_def)(const Body& b, double dt, BodyDef& out) = nullptr;
  // A key for the games: its part in the body's role (roles_by_entity; `body`
  // the body the block made), and back into a block saved from the world (Save;
  // `out` holds the body as it is now).
  void (*to_role)(const Spec& s, const Body& body, BlockRole& role) = nullptr;
  void (*from_role)(const BlockRole& role, Spec& out) = nullptr;
};

std::span<const Key<BlockSpec>> block_keys();  // a block's and a grid's
std::span<const Key<SceneSpec>> world_keys();  // "world": {...}
std::span<const Key<GameSpec>> game_keys();    // "game": {...}
std::span<const Key<TileSpec>> tile_keys();    // an entry of "tiles": [{...}, ...]
// Keys with their own readers (scene_json.cpp), here for their names and docs.
std::span<const KeyDoc> scene_keys();   // the top level
std::span<const KeyDoc> entry_keys();   // an entry of "blocks" that is a generator: grid, random, seed
std::span<const KeyDoc> grid_keys();    // a grid's, beyond a block's
std::span<const KeyDoc> random_keys();  // a random entry's, beyond the contact keys
std::span<const KeyDoc> state_keys();   // "state": {...}

// The names the reader accepts in each object, in the tables' order.
const std::vector<std::string_view>& block_names();
const std::vector<std::string_view>& grid_names();    // block_names, then grid_keys
const std::vector<std::string_view>& random_names();  // random_keys, then the contact keys
const std::vector<std::string_view>& world_names();
std::vector<std::string_view> names(std::span<const KeyDoc> docs);
template <class Spec>
std::vector<std::string_view> names(std::span<const Key<Spec>> rows) {
  std::vector<std::string_view> out;
  for (const auto& k : rows) out.emplace_back(k.doc.name());
  return out;
}

// Reading a block's keys (a grid's too): the required ones first, then each
// given one, in the table's order. Unknown keys are the caller's (Reader::keys).
void read_block_keys(const Reader& r, const json& b, const Path& p, BlockSpec& out);
void read_contact_keys(const Reader& r, const json& b, const Path& p, ContactSpec& out);
void write_block_keys(ojson& o, const BlockSpec& b);
// A key's value given as text (a command-line flag's, a map editor's string
// property: "0,0.001" for [x, y], on/off for a boolean, "a,b" for an array of
// strings) as the JSON its row reads; none if the text is not of the row's type.
std::optional<json> value_of_text(const KeyDoc& d, std::string_view text);
void write_contact_keys(ojson& o, const ContactSpec& c);

}  // namespace physics::scene_io

namespace physics {

// The validator's part for a block's keys, in the table's order (scene.cpp).
void check_block_keys(const scene_check::Checker& k, const BlockSpec& b, const std::string& path);
void check_contact_keys(const scene_check::Checker& k, const ContactSpec& c, const std::string& path);

// The body block b makes (entry and index: where it came from), and the
// public API's def its keys make of it, in a world stepping dt ms (populate,
// scene.cpp, creates it with create_body).
Body body_of(const BlockSpec& b, const SceneSpec& s, std::size_t entry, std::int64_t index);
BodyDef body_def(const Body& b, double dt);

// A body's role from its block's keys (walls aside).
BlockRole role_of(const BlockSpec& b, const Body& body);
// Body e of a world made from `from`, with its role, as a block (Save): every
// key from the world or the role, so that a saved world runs on.
BlockSpec block_from_world(const Components& k, EntityId e, const SceneSpec& from, const BlockRole& role);

// docs/scenes.md's key tables, as markdown.
std::string key_tables_markdown();

}  // namespace physics
