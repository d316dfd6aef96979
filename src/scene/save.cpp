#include "scene/save.hpp"

#include "scene/keys.hpp"

#include <algorithm>
#include <filesystem>
#include <string>

namespace physics::Save {

std::string next_from(const GameSpec& from, const std::string& file) {
  namespace fs = std::filesystem;
  if (from.next.empty() || file.empty()) return from.next;
  const fs::path target = from.next_path.empty() ? fs::path(from.next) : fs::path(from.next_path);
  const fs::path folder = fs::absolute(fs::path(file)).parent_path().lexically_normal();
  const fs::path rel = fs::absolute(target).lexically_normal().lexically_proximate(folder);
  return rel.generic_string();
}

SceneSpec scene_of(const World& w, const SceneSpec& from, std::span<const BlockRole> roles, const std::string& file) {
  SceneSpec s = from;
  s.params = w.params;
  s.blocks.clear();
  s.description = "saved after frame " + std::to_string(w.frame) + " of " + from.name;
  s.game.next = next_from(from.game, file);
  const Components& k = w.components;
  const auto is_layer = [&](EntityId e) {
    const auto layers = w.tiles.layers();
    return std::any_of(layers.begin(), layers.end(), [&](const TileLayer& l) { return l.body() == e; });
  };
  // The walls are the first bodies (populate makes them first) and are
  // made again by the "walls" key; the other alive bodies get new ids in order.
  const EntityId first = from.walls ? Game::wall_count : 0;
  std::vector<EntityId> new_id(k.size(), 0);
  EntityId next = first;
  for (EntityId e = 0; e < k.size(); ++e) {
    if (e < first) {
      new_id[e] = e;
    } else if (w.alive(e) && !is_layer(e)) {  // a layer is saved as its "tiles" entry (kept from `from`)
      new_id[e] = next++;
      s.blocks.push_back(block_from_world(k, e, from, e < roles.size() ? roles[e] : BlockRole{}));
    }
  }
  SavedState state;
  state.frame = w.frame;
  for (WarmImpulse imp : w.contact_solver.warm_impulses()) {
    if (!w.alive(imp.pair.c) || !w.alive(imp.pair.b)) continue;
    imp.pair = {new_id[imp.pair.c], new_id[imp.pair.b]};
    state.warm_start.push_back(imp);
  }
  // Before its first frame auto has no state yet: its first substep looks with
  // the solver (AutoMode::plan), which a restored state would skip.
  if (w.params.solver == Solver::automatic && w.frame > 0) {
    AutoState a = w.automatic.state();
    std::erase_if(a.pressed, [&](const AutoState::Run& r) { return !w.alive(r.pair.c) || !w.alive(r.pair.b); });
    for (AutoState::Run& r : a.pressed) r.pair = {new_id[r.pair.c], new_id[r.pair.b]};
    std::erase_if(a.pushed, [&](const AutoState::Push& p) { return !w.alive(p.body) || !w.alive(p.by); });
    for (AutoState::Push& p : a.pushed) p.body = new_id[p.body], p.by = new_id[p.by];
    state.automatic = a;
  }
  s.state = state;
  return s;
}

SceneSpec scene_of(const World& w, const SceneSpec& from) {
  return scene_of(w, from, roles_by_entity(from, expand(from, from.name)));
}

}  // namespace physics::Save
