#include "games/level.hpp"

namespace physics {

std::vector<EntityId> tagged(std::span<const BlockRole> roles, const std::string& tag) {
  std::vector<EntityId> out;
  for (std::size_t e = 0; e < roles.size(); ++e)
    if (roles[e].tag == tag) out.push_back(static_cast<EntityId>(e));
  return out;
}

}  // namespace physics
