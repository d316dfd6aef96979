// The systems of a world (course: system_defs.ml instantiates Draw, Move,
// Forces and Collision). A scene declares which ones it uses; the others are
// never created, so nothing registers with them and nothing updates them.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "course/systems/collision.hpp"
#include "course/systems/draw.hpp"
#include "course/systems/forces.hpp"
#include "course/systems/move.hpp"

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

struct Systems {
  std::optional<Draw> draw;
  std::optional<Forces> forces;
  std::optional<Move> move;
  std::optional<Collision> collision;

  explicit Systems(SystemSet set = {});
  SystemSet declared() const;
};

}  // namespace physics
