#include "course/system_defs.hpp"

namespace physics {

Systems::Systems(World& w) {
  if (auto* l = w.stage(SystemId::draw)) draw.emplace(*l);
  if (auto* l = w.stage(SystemId::forces)) forces.emplace(*l);
  if (auto* l = w.stage(SystemId::move)) move.emplace(*l);
  if (auto* l = w.stage(SystemId::collision)) collision.emplace(*l, w.pass);
}

}  // namespace physics
