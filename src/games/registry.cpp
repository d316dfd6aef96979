#include "games/registry.hpp"

#include "games/platformer.hpp"
#include "games/targets.hpp"

namespace physics {

std::unique_ptr<Level> make_level(const SceneSpec& s, WorldId w, std::span<const BlockRole> roles) {
  enable_contact_events(w);
  if (s.game.kind == "platformer") return std::make_unique<Platformer>(s, w, roles);
  if (s.game.kind == "targets") return std::make_unique<Targets>(s, w, roles);
  throw SceneError(s.name + ": game.kind: unknown game \"" + s.game.kind + "\"");
}

}  // namespace physics
