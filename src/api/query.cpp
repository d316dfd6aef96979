// The public API's queries: the engine's (engine/query.hpp), with ids.
#include <stdexcept>

#include "api/convert.hpp"
#include "api/registry.hpp"
#include "engine/query.hpp"

namespace physics {

namespace {
// The engine's query, its std::invalid_argument turned into the API's Error.
template <class F>
auto asked(F&& f) {
  try {
    return f();
  } catch (const Error&) {
    throw;
  } catch (const std::invalid_argument& e) {
    throw Error(e.what());
  }
}

std::vector<BodyId> ids(WorldId world, const api::Live& w, const std::vector<EntityId>& found) {
  std::vector<BodyId> out;
  for (const EntityId e : found)
    if (w.world->alive(e)) out.push_back(api::id_of(world, w, e));
  return out;
}
}  // namespace

std::optional<RayResult> ray_cast(WorldId world, Vec2 origin, Vec2 direction, double max_distance) {
  const api::Live& w = api::world(world);
  const auto hit = asked([&] {
    return physics::ray_cast(*w.world, api::to_engine(origin), api::to_engine(direction), max_distance);
  });
  if (!hit) return std::nullopt;
  return RayResult{api::id_of(world, w, hit->body), api::to_public(hit->point), api::to_public(hit->normal),
                   hit->fraction, hit->column, hit->row};
}

std::vector<BodyId> query_box(WorldId world, Aabb box) {
  const api::Live& w = api::world(world);
  return ids(world, w, asked([&] { return physics::query_box(*w.world, api::to_engine(box.lower), api::to_engine(box.upper)); }));
}

std::vector<BodyId> query_point(WorldId world, Vec2 point) {
  const api::Live& w = api::world(world);
  return ids(world, w, asked([&] { return physics::query_point(*w.world, api::to_engine(point)); }));
}

std::vector<TileCellResult> query_tiles(WorldId world, Aabb box) {
  const api::Live& w = api::world(world);
  const auto cells = asked([&] {
    return QueryIndex(*w.world).cells_meeting(api::to_engine(box.lower), api::to_engine(box.upper));
  });
  std::vector<TileCellResult> out;
  for (const TileCellHit& c : cells)
    out.push_back({api::id_of(world, w, c.layer), c.cell.column, c.cell.row, static_cast<TileKind>(c.cell.kind)});
  return out;
}

}  // namespace physics
