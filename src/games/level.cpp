#include "games/level.hpp"

#include "games/platformer.hpp"
#include "games/targets.hpp"

namespace physics {

std::vector<EntityId> tagged(std::span<const BlockRole> roles, const std::string& tag) {
  std::vector<EntityId> out;
  for (std::size_t e = 0; e < roles.size(); ++e)
    if (roles[e].tag == tag) out.push_back(static_cast<EntityId>(e));
  return out;
}

std::unique_ptr<Level> make_level(const SceneSpec& s, World& w, std::span<const BlockRole> roles) {
  w.enable_events();
  if (s.game.kind == "platformer") return std::make_unique<Platformer>(s, w, roles);
  if (s.game.kind == "targets") return std::make_unique<Targets>(s, w, roles);
  throw SceneError(s.name + ": game.kind: unknown game \"" + s.game.kind + "\"");
}

}  // namespace physics
