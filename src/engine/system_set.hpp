// Which of the four systems a world runs (a scene's "systems" key): Draw,
// Forces, Move, Collision, by name and as a set. The engine's, so that a
// world's stages are named without the course's systems: the world holds
// each declared stage's bodies (World::bodies), which the engine's stages
// and the course's systems (course/system_defs.hpp) both run over.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace physics {

enum class SystemId : std::uint8_t { draw, forces, move, collision };
inline constexpr std::array<SystemId, 4> all_systems{SystemId::draw, SystemId::forces,
                                                     SystemId::move, SystemId::collision};
std::string_view name(SystemId s);
std::optional<SystemId> system_from_name(std::string_view name);

// Which systems a scene declares.
struct SystemSet {
  bool draw = true, forces = true, move = true, collision = true;
  bool has(SystemId s) const;
  void set(SystemId s, bool on);
  std::string to_string() const;  // "draw,move,..." in frame order
};

}  // namespace physics
