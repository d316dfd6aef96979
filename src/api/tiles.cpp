// The public API's tile layers: a TileLayerDef checked as create_body checks
// a BodyDef, then the engine's layer (engine/tiles.hpp, World::add_tile_layer).
#include <algorithm>

#include "api/convert.hpp"
#include "api/registry.hpp"

namespace physics {

namespace {
const TileLayer* layer_of(const World& w, EntityId e) {
  const auto layers = w.tiles.layers();
  const auto it = std::find_if(layers.begin(), layers.end(), [&](const TileLayer& l) { return l.body() == e; });
  return it == layers.end() ? nullptr : &*it;
}
}  // namespace

BodyId create_tile_layer(WorldId world, const TileLayerDef& d) {
  api::Live& w = api::world(world);
  api::check_finite(d.position, "a tile layer's position");
  api::check_restitution(d.restitution);
  api::check_friction(d.friction);
  TileGrid grid{d.cell_size, d.columns, d.rows, {}};
  grid.cells.reserve(d.cells.size());
  for (const TileKind t : d.cells) grid.cells.push_back(static_cast<std::uint8_t>(t));
  if (const std::string bad = check(grid); !bad.empty()) throw Error("bad TileLayerDef: " + bad);
  World& world_ = *w.world;
  const EntityId e = world_.add_tile_layer(api::to_engine(d.position), std::move(grid));
  Components& c = world_.components;
  c.restitution[e] = d.restitution;
  c.friction[e] = d.friction;
  c.color[e] = d.color;
  if (const ContactRules rules = api::rules_of(d.filter, false, OneWay::none); !rules.plain()) c.set_rules(e, rules);
  w.table.generation.resize(c.size(), 0);
  w.table.user_data.resize(c.size(), 0);
  w.table.generation[e] = w.issue(e);
  w.table.user_data[e] = d.user_data;
  return api::id_of(world, w, e);
}

bool is_tile_layer(BodyId id) {
  const api::Named n = api::body(id);
  return layer_of(*n.live.world, n.entity) != nullptr;
}

TileKind tile_at(BodyId id, int column, int row) {
  const api::Named n = api::body(id);
  const TileLayer* l = layer_of(*n.live.world, n.entity);
  if (!l) throw Error(api::describe(id) + " is not a tile layer");
  return static_cast<TileKind>(l->grid().at(column, row));
}

}  // namespace physics
