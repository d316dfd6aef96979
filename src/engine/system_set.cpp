#include "engine/system_set.hpp"

namespace physics {

std::string_view name(SystemId s) {
  switch (s) {
    case SystemId::draw: return "draw";
    case SystemId::forces: return "forces";
    case SystemId::move: return "move";
    case SystemId::collision: return "collision";
  }
  return "?";
}

std::optional<SystemId> system_from_name(std::string_view n) {
  for (const SystemId s : all_systems)
    if (name(s) == n) return s;
  return std::nullopt;
}

bool SystemSet::has(SystemId s) const {
  switch (s) {
    case SystemId::draw: return draw;
    case SystemId::forces: return forces;
    case SystemId::move: return move;
    case SystemId::collision: return collision;
  }
  return false;
}

void SystemSet::set(SystemId s, bool on) {
  switch (s) {
    case SystemId::draw: draw = on; break;
    case SystemId::forces: forces = on; break;
    case SystemId::move: move = on; break;
    case SystemId::collision: collision = on; break;
  }
}

std::string SystemSet::to_string() const {
  std::string out;
  for (const SystemId s : all_systems) {
    if (!has(s)) continue;
    if (!out.empty()) out += ',';
    out += name(s);
  }
  return out;
}

}  // namespace physics
