#include "scene/scene_json.hpp"

// The scene file reader: the parser's document (json_parse.hpp) read key by
// key with the typed reader (json_reader.hpp), a block's and the world's keys
// by their tables (keys.hpp); and the file I/O.
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>

#include "scene/json_parse.hpp"
#include "scene/keys.hpp"
#include "scene/map.hpp"

namespace physics {

using namespace scene_io;

namespace {

constexpr std::uintmax_t max_file_size = 64u << 20;      // bytes

void read_world(const Reader& r, const json& w, SceneSpec& s) {
  r.keys(w, "world", world_names());
  const Path world = "world";
  for (const auto& k : world_keys())
    if (const json* v = find(w, k.doc.name())) k.read(r, *v, Path(world, k.doc.key), s);
}

// "game": {"kind": "platformer" | "targets", "shots": N, "next": "level2.json"}
GameSpec read_game(const Reader& r, const json& g) {
  if (!g.is_object()) r.fail("game", "must be an object {\"kind\": ...} (got " + r.got(g) + ")");
  r.keys(g, "game", names(game_keys()));
  const Path game = "game";
  GameSpec out;
  for (const auto& k : game_keys())
    if (!k.missing.empty() && !find(g, k.doc.name()))
      r.fail(game, "missing key \"" + std::string(k.doc.name()) + "\" " + std::string(k.missing));
  for (const auto& k : game_keys())
    if (const json* v = find(g, k.doc.name())) k.read(r, *v, Path(game, k.doc.key), out);
  return out;
}

// "tiles": [{"pos": [x, y], "cell": 16, "rows": ["#..=", ...]}, ...]
std::vector<TileSpec> read_tiles(const Reader& r, const json& v) {
  if (!v.is_array()) r.fail("tiles", "must be an array of tile layers (got " + r.got(v) + ")");
  std::vector<std::string_view> allowed;
  for (const auto& k : tile_keys()) allowed.push_back(k.doc.name());
  const Path tiles = "tiles";
  std::vector<TileSpec> out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Path at(tiles, i);
    r.keys(v[i], at, allowed);
    TileSpec t;
    for (const auto& k : tile_keys()) {
      const json* x = find(v[i], k.doc.name());
      if (!x && !k.missing.empty()) r.fail(at, "missing key \"" + std::string(k.doc.name()) + "\" " + std::string(k.missing));
      if (x) k.read(r, *x, Path(at, k.doc.key), t);
    }
    out.push_back(std::move(t));
  }
  return out;
}

BlockSpec read_block(const Reader& r, const json& b, const Path& p) {
  r.keys(b, p, block_names());
  BlockSpec out;
  read_block_keys(r, b, p, out);
  return out;
}

GridSpec read_grid(const Reader& r, const json& g, const Path& p) {
  r.keys(g, p, grid_names());
  GridSpec out;
  read_block_keys(r, g, p, out.first);
  const json* count = find(g, "count");
  if (!count) r.fail(p, "missing key \"count\" ([columns, rows])");
  r.pair(*count, p + ".count", "an array of two integers [columns, rows]");
  out.columns = static_cast<int>(r.integer((*count)[0], p + ".count[0]", 1, max_bodies));
  out.rows = static_cast<int>(r.integer((*count)[1], p + ".count[1]", 1, max_bodies));
  // Default step: the block's size, so the blocks touch.
  out.step = {static_cast<double>(out.first.width), static_cast<double>(out.first.height)};
  if (const json* v = find(g, "step")) out.step = r.vec(*v, p + ".step");
  return out;
}

RandomSpec read_random(const Reader& r, const json& g, const Path& p) {
  r.keys(g, p, random_names());
  RandomSpec out;
  read_contact_keys(r, g, p, out.contact);
  const json* count = find(g, "count");
  if (!count) r.fail(p, "missing key \"count\" (the number of blocks)");
  out.count = r.integer(*count, p + ".count", 1, max_bodies);
  const json* side = find(g, "side");
  const json* size = find(g, "size");
  if (side && size) r.fail(p, "give \"side\" (square blocks) or \"size\", not both");
  if (!side && !size) r.fail(p, "missing key \"size\" ([width, height]) or \"side\" (square blocks)");
  if (side) {
    out.side = r.size_spec(*side, p + ".side");
  } else {
    r.pair(*size, p + ".size", "an array [width, height] of integers or ranges [min, max]");
    out.width = r.size_spec((*size)[0], p + ".size[0]");
    out.height = r.size_spec((*size)[1], p + ".size[1]");
  }
  const json* mass = find(g, "mass");
  if (!mass) r.fail(p, "missing key \"mass\" (a number > 0, a range [min, max], or \"inf\")");
  if (mass->is_array()) {
    out.mass = r.real_spec(*mass, p + ".mass");
  } else {
    out.mass = RealSpec::fixed(r.mass(*mass, p + ".mass"));
  }
  if (const json* v = find(g, "velocity")) out.velocity = r.vec_spec(*v, p + ".velocity");
  if (const json* v = find(g, "force")) out.force = r.vec_spec(*v, p + ".force");
  if (const json* v = find(g, "impulse")) out.impulse = r.vec_spec(*v, p + ".impulse");
  if (const json* v = find(g, "restitution")) {
    out.restitution = r.real_spec(*v, p + ".restitution");  // in [0, 1]: validate()
  }
  if (const json* v = find(g, "color"); v && !(v->is_string() && v->get<std::string>() == "random"))
    out.color = r.color(*v, p + ".color");
  const json* cells = find(g, "cells");
  const json* area = find(g, "area");
  if (cells && area) r.fail(p, "give \"cells\" or \"area\", not both");
  if (cells) {
    const Path c = p + ".cells";
    r.keys(*cells, c, {"pos", "columns", "step", "jitter"});
    out.use_cells = true;
    for (const char* k : {"pos", "columns", "step"})
      if (!find(*cells, k)) r.fail(c, std::string("missing key \"") + k + "\"");
    out.origin = r.vec(cells->at("pos"), c + ".pos");
    out.columns = static_cast<int>(r.integer(cells->at("columns"), c + ".columns", 1, max_bodies));
    out.step = r.vec(cells->at("step"), c + ".step");
    if (const json* v = find(*cells, "jitter")) {
      out.jitter = r.vec(*v, c + ".jitter");  // >= 0: validate()
    }
  } else {
    // Default area: the inside of the walls, or the whole world, set by
    // read_scene once the world is read (NaN here: a file's numbers are finite).
    out.use_cells = false;
    out.origin = out.extent = Vector{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    if (area) {
      const Path a = p + ".area";
      r.keys(*area, a, {"pos", "size"});
      if (const json* v = find(*area, "pos")) out.origin = r.vec(*v, a + ".pos");
      if (const json* v = find(*area, "size")) out.extent = r.vec(*v, a + ".size");
    }
  }
  return out;
}

// The rows of a saved state's list of pairs (`shape`, e.g. "[c, b, substeps]",
// `length` numbers each): f(row, its path, the pair it names), after the
// shape and the two ids are checked.
template <class F>
void read_pair_rows(const Reader& r, const json* list, const char* name, std::size_t length, const char* shape,
                    F&& f) {
  if (!list) return;
  if (!list->is_array()) r.fail(name, "must be an array (got " + r.got(*list) + ")");
  const Path path = name;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const json& e = (*list)[i];
    const Path p(path, i);
    if (!e.is_array() || e.size() != length) r.fail(p, std::string("must be ") + shape + " (got " + r.got(e) + ")");
    const auto id = [&](std::size_t k) { return static_cast<EntityId>(r.integer(e[k], p, 0, max_bodies + 4)); };
    f(e, p, Pair{id(0), id(1)});
  }
}

// The auto mode's state: {"hold": n, "jam": n, "pressed": [[c, b, substeps], ...],
// "pushed": [[body, by, side, ago], ...]}.
AutoState read_auto_state(const Reader& r, const json& v) {
  r.keys(v, "state.auto", {"hold", "jam", "pressed", "pushed"});
  AutoState out;
  if (const json* h = find(v, "hold")) out.hold = static_cast<int>(r.integer(*h, "state.auto.hold", 0, AutoMode::hold));
  if (const json* j = find(v, "jam")) out.jam = static_cast<int>(r.integer(*j, "state.auto.jam", 0, AutoMode::hold));
  read_pair_rows(r, find(v, "pressed"), "state.auto.pressed", 3, "[c, b, substeps]",
                 [&](const json& e, const Path& p, Pair pair) {
                   out.pressed.push_back({pair, static_cast<int>(r.integer(e[2], p, 1, 1 << 30))});
                 });
  read_pair_rows(r, find(v, "pushed"), "state.auto.pushed", 4, "[body, by, side, ago]",
                 [&](const json& e, const Path& p, Pair pair) {
                   out.pushed.push_back({pair.c, pair.b, static_cast<int>(r.integer(e[2], p, 0, 3)),
                                         static_cast<int>(r.integer(e[3], p, 0, AutoMode::persist - 1))});
                 });
  return out;
}

// A saved world's "state": {"frame": n, "warm_start": [[c, b, axis, jn, jt], ...], "auto": {...}}.
SavedState read_state(const Reader& r, const json& v) {
  r.keys(v, "state", names(state_keys()));
  SavedState out;
  if (const json* a = find(v, "auto")) out.automatic = read_auto_state(r, *a);
  if (const json* f = find(v, "frame")) out.frame = r.integer(*f, "state.frame", 0, max_frames);
  read_pair_rows(r, find(v, "warm_start"), "state.warm_start", 5, "[c, b, axis, jn, jt]",
                 [&](const json& e, const Path& p, Pair pair) {
                   out.warm_start.push_back(
                       {pair, static_cast<int>(r.integer(e[2], p, 0, 3)), r.number(e[3], p), r.number(e[4], p)});
                 });
  return out;
}

BlockEntry read_entry(const Reader& r, const json& e, const Path& p) {
  r.object(e, p);
  const bool grid = e.contains("grid"), random = e.contains("random");
  if (grid && random) r.fail(p, "an entry is a \"grid\" or a \"random\" generator, not both");
  if (grid) {
    r.keys(e, p, {"grid"});
    return read_grid(r, e["grid"], p + ".grid");
  }
  if (random) {
    r.keys(e, p, {"random", "seed"});
    RandomSpec out = read_random(r, e["random"], p + ".random");
    if (const json* v = find(e, "seed")) out.seed = r.seed(*v, p + ".seed");
    return out;
  }
  return read_block(r, e, p);
}

std::string stem(const std::string& source) {
  std::string name = std::filesystem::path(source).stem().string();
  return name.empty() ? "scene" : name;
}

}  // namespace

TextPos line_column(std::string_view text, std::size_t position) {
  // position counts the characters read, the offending one included.
  const std::size_t at = std::min(position == 0 ? 0 : position - 1, text.size());
  TextPos p;
  for (std::size_t i = 0; i < at; ++i) {
    if (text[i] == '\n') {
      ++p.line;
      p.column = 1;
    } else {
      ++p.column;
    }
  }
  return p;
}

SceneSpec read_scene(std::string_view text, const std::string& source) {
  const Reader r(source);
  SceneSpec s;
  // The blocks are read as the parser completes each one. Their first error
  // is kept and raised after the checks that come before the blocks (syntax
  // anywhere in the file, top-level keys, world), as if the file were read
  // whole first.
  std::optional<SceneError> block_error;
  // Room for the blocks up front: an entry is large (a variant of the three
  // kinds), and growing the vector moves each one again. Every block and
  // grid has a "pos" key, so their count bounds the entries of a plain file;
  // capped, so a file of nothing but "pos" reserves little.
  std::size_t entries = 0;
  for (auto at = text.find("\"pos\""); at != std::string_view::npos && entries < (1u << 17); at = text.find("\"pos\"", at + 5))
    ++entries;
  s.blocks.reserve(entries);
  StrictDom dom;
  const Path blocks = "blocks";
  dom.on_block = [&](const json& e, std::size_t i) {
    if (block_error) return;
    try {
      s.blocks.push_back(read_entry(r, e, Path(blocks, i)));
    } catch (const SceneError& err) {
      block_error = err;
    }
  };
  parse_strict(text, source, dom);
  const json& doc = dom.root;
  if (!doc.is_object()) r.fail("", "a scene file must hold one JSON object {...} (got " + r.got(doc) + ")");
  r.keys(doc, "", names(scene_keys()));
  s.name = stem(source);
  if (const json* v = find(doc, "name")) s.name = r.text(*v, "name");
  if (const json* v = find(doc, "description")) s.description = r.text(*v, "description");
  if (const json* v = find(doc, "world")) read_world(r, *v, s);
  if (const json* v = find(doc, "state")) s.state = read_state(r, *v);
  if (const json* v = find(doc, "game")) s.game = read_game(r, *v);
  if (const json* v = find(doc, "tiles")) s.tiles = read_tiles(r, *v);
  if (const json* v = find(doc, "style")) {
    const auto style = style_from_name(r.text(*v, "style"));
    if (!style) r.fail("style", "must be \"plain\", \"speed\" or \"sprite\" (got " + r.got(*v) + ")");
    s.style = *style;
  }
  if (const json* v = find(doc, "blocks"); v && !v->is_array())
    r.fail("blocks", "must be an array of blocks (got " + r.got(*v) + ")");
  if (block_error) throw *block_error;
  // Random generators without an area take the inside of the walls, or the whole world.
  const double t = s.walls ? wall_thickness : 0;
  for (BlockEntry& e : s.blocks)
    if (auto* g = std::get_if<RandomSpec>(&e); g && !g->use_cells) {
      if (std::isnan(g->origin.x)) g->origin = {t, t};
      if (std::isnan(g->extent.x)) g->extent = {s.width - 2 * t, s.height - 2 * t};
    }
  return s;
}

SceneSpec parse_scene(std::string_view text, const std::string& source) {
  SceneSpec s = read_scene(text, source);
  expand(s, source);  // the validation (scene.hpp), placement included
  return s;
}

std::string read_input_file(const std::string& path, const std::string& what) {
  const std::string cannot = path + ": cannot read the " + what + ": ";
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) throw SceneError(cannot + "no such file");
  if (std::filesystem::is_directory(status)) throw SceneError(cannot + "it is a directory");
  // A C file, not a stream: the browser build links no iostreams (docs/web.md).
  struct Close {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  const std::unique_ptr<std::FILE, Close> file(std::fopen(path.c_str(), "rb"));
  std::FILE* const in = file.get();
  if (!in) throw SceneError(cannot + std::strerror(errno));
  const std::string too_large = cannot + "larger than " + std::to_string(max_file_size >> 20) + " MB";
  auto size = std::filesystem::is_regular_file(status) ? std::filesystem::file_size(path, ec) : 0;
  if (ec) size = 0;  // then read as a stream
  if (size > max_file_size) throw SceneError(too_large);
  // A regular file's size is known: read at once into a string of that size
  // (a stream, then a copy, doubled the work on a large scene). Anything else
  // (a device, a pipe, a file that grew) is read on in chunks, one byte past
  // the limit at most: /dev/zero is refused at 64 MB, not after 2 GB.
  std::string text(static_cast<std::size_t>(size), '\0');
  text.resize(std::fread(text.data(), 1, text.size(), in));
  for (char buf[65536]; !std::ferror(in) && !std::feof(in) && text.size() <= max_file_size;)
    text.append(buf, std::fread(buf, 1, sizeof buf, in));
  if (text.size() > max_file_size) throw SceneError(too_large);
  if (std::ferror(in)) throw SceneError(cannot + "read error");
  return text;
}

SceneSpec read_scene_file(const std::string& path) {
  const std::string text = read_input_file(path, "scene file");
  // A map from a level editor (.tmj, .ldtk) becomes a scene file's document
  // read by the same reader (map.hpp).
  SceneSpec s = is_map_file(path) ? read_map(text, path) : read_scene(text, path);
  // A game's next level is named relative to this file's folder; it must be
  // there now, not only once this level is won.
  if (!s.game.next.empty()) {
    std::error_code ec;
    s.game.next_path = (std::filesystem::path(path).parent_path() / s.game.next).string();
    if (!std::filesystem::is_regular_file(s.game.next_path, ec))
      throw SceneError(path + ": game.next: no scene file " + s.game.next_path);
  }
  return s;
}

SceneSpec load_scene_file(const std::string& path) {
  SceneSpec s = read_scene_file(path);
  expand(s, path);  // the validation (scene.hpp), placement included
  return s;
}

}  // namespace physics
