// The scene writer (--print-scene, --save): a SceneSpec as a scene file that
// read_scene reads back to the same scene, the keys of the world and of a
// block from their tables (keys.hpp), in a pretty layout.
#include "scene/scene_json.hpp"

#include "scene/keys.hpp"

namespace physics {

using namespace scene_io;

namespace {

using scene_io::vec;  // with the one below for ranges

ojson real(const RealSpec& r) { return r.drawn ? ojson::array({r.lo, r.hi}) : ojson(r.lo); }
ojson integer(const IntSpec& r) { return r.drawn ? ojson::array({r.lo, r.hi}) : ojson(r.lo); }
ojson vec(const VecSpec& v) { return ojson::array({real(v.x), real(v.y)}); }
bool zero(const VecSpec& v) { return v == VecSpec{}; }

ojson entry(const BlockEntry& e) {
  ojson o = ojson::object();
  if (const auto* b = std::get_if<BlockSpec>(&e)) write_block_keys(o, *b);
  if (const auto* g = std::get_if<GridSpec>(&e)) {
    ojson grid = ojson::object();
    write_block_keys(grid, g->first);
    grid["count"] = ojson::array({g->columns, g->rows});
    grid["step"] = vec(g->step);
    o["grid"] = grid;
  }
  if (const auto* r = std::get_if<RandomSpec>(&e)) {
    ojson gen = ojson::object();
    gen["count"] = r->count;
    if (r->side) gen["side"] = integer(*r->side);
    else gen["size"] = ojson::array({integer(r->width), integer(r->height)});
    gen["mass"] = r->mass.drawn ? real(r->mass) : mass_json(r->mass.lo);
    if (!zero(r->velocity)) gen["velocity"] = vec(r->velocity);
    if (!zero(r->force)) gen["force"] = vec(r->force);
    if (!zero(r->impulse)) gen["impulse"] = vec(r->impulse);
    if (r->restitution) gen["restitution"] = real(*r->restitution);
    write_contact_keys(gen, r->contact);
    gen["color"] = r->color ? ojson(hex(*r->color)) : ojson("random");
    if (r->use_cells) {
      gen["cells"] = {{"pos", vec(r->origin)}, {"columns", r->columns}, {"step", vec(r->step)},
                      {"jitter", vec(r->jitter)}};
    } else {
      gen["area"] = {{"pos", vec(r->origin)}, {"size", vec(r->extent)}};
    }
    o["random"] = gen;
    o["seed"] = r->seed;
  }
  return o;
}

// nlohmann's dump(2), except that a short array of numbers or strings (a
// position, a size, a range, the systems) stays on one line: [100, 200].
void write_pretty(const ojson& j, int indent, std::string& out) {
  constexpr std::size_t max_inline = 8;
  const std::string pad(static_cast<std::size_t>(indent) + 2, ' ');
  const bool flat = std::all_of(j.begin(), j.end(), [](const ojson& e) { return e.is_primitive(); });
  if (j.is_array() && (j.empty() || (flat && j.size() <= max_inline))) {
    out += '[';
    for (std::size_t i = 0; i < j.size(); ++i) out += (i ? ", " : "") + j[i].dump();
    out += ']';
  } else if (j.is_array()) {
    out += "[\n";
    for (std::size_t i = 0; i < j.size(); ++i) {
      out += (i ? ",\n" : "") + pad;
      write_pretty(j[i], indent + 2, out);
    }
    out += "\n" + std::string(static_cast<std::size_t>(indent), ' ') + ']';
  } else if (j.is_object() && !j.empty()) {
    out += "{\n";
    bool first = true;
    for (const auto& [key, value] : j.items()) {
      out += (first ? "" : ",\n") + pad + ojson(key).dump() + ": ";
      first = false;
      write_pretty(value, indent + 2, out);
    }
    out += "\n" + std::string(static_cast<std::size_t>(indent), ' ') + '}';
  } else {
    out += j.dump();
  }
}

}  // namespace

std::string to_json(const SceneSpec& s) {
  ojson o = ojson::object();
  o["name"] = s.name;
  if (!s.description.empty()) o["description"] = s.description;
  ojson world = ojson::object();
  for (const auto& k : world_keys()) k.write(world, s);
  o["world"] = world;
  ojson blocks = ojson::array();
  for (const BlockEntry& e : s.blocks) blocks.push_back(entry(e));
  o["blocks"] = blocks;
  if (!s.tiles.empty()) {
    ojson tiles = ojson::array();
    for (const TileSpec& t : s.tiles) {
      ojson layer = ojson::object();
      for (const auto& k : tile_keys()) k.write(layer, t);
      tiles.push_back(layer);
    }
    o["tiles"] = tiles;
  }
  if (!s.game.kind.empty()) {
    ojson game = ojson::object();
    for (const auto& k : game_keys()) k.write(game, s.game);
    o["game"] = game;
  }
  if (s.style != Style::plain) o["style"] = std::string(name(s.style));  // plain: today's files unchanged
  if (s.state) {
    ojson warm = ojson::array();
    for (const WarmImpulse& w : s.state->warm_start) warm.push_back({w.pair.c, w.pair.b, w.axis, w.jn, w.jt});
    o["state"] = {{"frame", s.state->frame}, {"warm_start", warm}};
    if (s.state->automatic) {
      ojson pressed = ojson::array();
      for (const AutoState::Run& r : s.state->automatic->pressed) pressed.push_back({r.pair.c, r.pair.b, r.substeps});
      o["state"]["auto"] = {{"hold", s.state->automatic->hold}, {"pressed", pressed}};
      if (s.state->automatic->jam > 0) o["state"]["auto"]["jam"] = s.state->automatic->jam;  // older files have none
      ojson pushed = ojson::array();
      for (const AutoState::Push& p : s.state->automatic->pushed) pushed.push_back({p.body, p.by, p.side, p.ago});
      if (!pushed.empty()) o["state"]["auto"]["pushed"] = pushed;  // nor this
    }
  }
  std::string out;
  write_pretty(o, 0, out);
  return out + "\n";
}

}  // namespace physics
