#include "games/level.hpp"

namespace physics {

std::vector<Tagged> tagged(WorldId w, std::span<const BlockRole> roles, const std::string& tag) {
  const std::vector<BodyId> all = bodies(w);  // in creation order: the roles' order
  // The scene's tile layers come after its blocks and have no role.
  std::size_t n = all.size();
  while (n > roles.size() && is_tile_layer(all[n - 1])) --n;
  if (n != roles.size())
    throw SceneError("a game's world has " + std::to_string(all.size()) + " bodies but " +
                     std::to_string(roles.size()) + " roles");
  std::vector<Tagged> out;
  for (std::size_t e = 0; e < roles.size(); ++e)
    if (roles[e].tag == tag) out.push_back({all[e], &roles[e], e});
  return out;
}

std::vector<BodyId> ids(const std::vector<Tagged>& t) {
  std::vector<BodyId> out;
  for (const Tagged& x : t) out.push_back(x.body);
  return out;
}

}  // namespace physics
