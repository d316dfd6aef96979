#include "engine/rules.hpp"

#include <algorithm>

namespace physics {

bool one_way_stops(const Components& k, EntityId p, EntityId b, double h) {
  const Vector pp = k.position[p], pb = k.position[b];
  const Rect rp = k.box[p], rb = k.box[b];
  const Vector v = k.velocity[b] - k.velocity[p];
  // past: how far b's leading side is beyond p's face (> 0: behind it);
  // approach: b's speed towards the face. y grows downwards.
  double past = 0.0, approach = 0.0;
  switch (k.rules(p).one_way) {
    case Face::none: return true;
    case Face::up: past = (pb.y + rb.height) - pp.y, approach = v.y; break;
    case Face::down: past = (pp.y + rp.height) - pb.y, approach = -v.y; break;
    case Face::left: past = (pb.x + rb.width) - pp.x, approach = v.x; break;
    case Face::right: past = (pp.x + rp.width) - pb.x, approach = -v.x; break;
  }
  return past <= std::max(approach, 0.0) * h + one_way_slop;
}

bool solvable(const Components& k, EntityId c, EntityId b, double h) {
  const ContactRules& rc = k.rules(c);
  const ContactRules& rb = k.rules(b);
  if (!filters_meet(rc, rb) || rc.sensor || rb.sensor) return false;
  return one_way_stops(k, c, b, h) && one_way_stops(k, b, c, h);
}

bool reported(const Components& k, EntityId c, EntityId b, double h) {
  const ContactRules& rc = k.rules(c);
  const ContactRules& rb = k.rules(b);
  if (!filters_meet(rc, rb)) return false;
  return rc.sensor || rb.sensor || solvable(k, c, b, h);
}

}  // namespace physics
