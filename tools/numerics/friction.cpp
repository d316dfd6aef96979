#include "numerics/friction.hpp"

#include <cstdio>

namespace physics::numerics {

SlideResult run_slide(const Mode& m, const Slide& s) {
  World w = make_world(m, {0, s.g});
  walls(w);
  const EntityId b = block(w, 100, 520, 40, 40, 1.0, {s.v0, 0}, 0.0);
  for (EntityId e = 0; e < w.components.size(); ++e) w.components.friction[e] = s.mu;
  for (EntityId e = 0; e < 4; ++e) w.components.restitution[e] = 0.0;
  SlideResult r;
  const int limit = static_cast<int>(100000.0 / m.dt);
  for (r.frames = 0; r.frames < limit && w.components.velocity[b].x != 0.0; ++r.frames) Game::step(w);
  r.stopped = w.components.velocity[b].x == 0.0;
  r.distance = w.components.position[b].x - 100.0;
  r.error = (r.distance - s.exact()) / s.exact();
  return r;
}

std::vector<FrictionSetting> friction_settings() {
  std::vector<FrictionSetting> out;
  for (const double hz : {60.0, 120.0, 240.0, 480.0}) {
    char label[32];
    std::snprintf(label, sizeof label, "dt=1000/%.0f", hz);
    out.push_back({"course", label, Mode{"course", 1, false, Solver::course, 8, 1000.0 / hz}});
    out.push_back({"ccd", label, Mode{"ccd", 1, true, Solver::course, 8, 1000.0 / hz}});
    out.push_back({"stable", label, Mode{"stable", 1, false, Solver::stable, 8, 1000.0 / hz}});
    out.push_back({"auto", label, Mode{"auto", 1, false, Solver::automatic, 8, 1000.0 / hz}});
  }
  return out;
}

}  // namespace physics::numerics
