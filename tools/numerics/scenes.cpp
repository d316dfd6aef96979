#include "numerics/scenes.hpp"

#include <cmath>

#include "course/game.hpp"

namespace physics::numerics {

Params Mode::params(Vector gravity) const {
  Params p;
  p.dt = dt;
  p.substeps = substeps;
  p.ccd = ccd;
  p.solver = solver;
  p.iterations = iterations;
  p.integrator = integrator;
  p.gravity = gravity;
  return p;
}

std::vector<Mode> stability_modes() {
  return {
      Mode{"course", 1, false, Solver::course, 8},
      Mode{"substeps16", 16, false, Solver::course, 8},
      Mode{"ccd", 1, true, Solver::course, 8},
      Mode{"stable", 1, false, Solver::stable, 8},
      Mode{"stable+ccd", 1, true, Solver::stable, 8},
      Mode{"auto", 1, false, Solver::automatic, 8},
  };
}

World make_world(const Mode& m, Vector gravity) { return World(SystemSet{false, true, true, true}, m.params(gravity)); }

void walls(World& w, Vector o) {
  const int W = Game::width, H = Game::height, t = Game::wall_thickness;
  Block::make(w, o.x, o.y, W, t, Game::wall_blue, infinity);
  Block::make(w, o.x, o.y + H - t, W, t, Game::wall_blue, infinity);
  Block::make(w, o.x, o.y + t, t, H - 2 * t, Game::wall_black, infinity);
  Block::make(w, o.x + W - t, o.y + t, t, H - 2 * t, Game::wall_black, infinity);
}

EntityId block(World& w, double x, double y, int width, int height, double mass, Vector v, double e) {
  const EntityId id = Block::make(w, x, y, width, height, grey, mass, e).id;
  w.components.velocity[id] = v;
  return id;
}

bool all_finite(const World& w) {
  const Components& k = w.components;
  for (std::size_t e = 0; e < k.size(); ++e)
    if (!std::isfinite(k.position[e].x) || !std::isfinite(k.position[e].y) || !std::isfinite(k.velocity[e].x) ||
        !std::isfinite(k.velocity[e].y))
      return false;
  return true;
}

double max_overlap(const World& w) {
  const Components& k = w.components;
  const auto ids = w.bodies(SystemId::collision);
  // Sort by left edge so that only pairs overlapping in x are looked at.
  std::vector<EntityId> order(ids.begin(), ids.end());
  std::sort(order.begin(), order.end(), [&](EntityId a, EntityId b) { return k.position[a].x < k.position[b].x; });
  double worst = 0.0;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const EntityId a = order[i];
    const double ax1 = k.position[a].x + k.box[a].width;
    for (std::size_t j = i + 1; j < order.size() && k.position[order[j]].x < ax1; ++j) {
      const EntityId b = order[j];
      if (!std::isfinite(k.mass[a]) && !std::isfinite(k.mass[b])) continue;
      const double ox = std::min(ax1, k.position[b].x + k.box[b].width) - k.position[b].x;
      const double oy = std::min(k.position[a].y + k.box[a].height, k.position[b].y + k.box[b].height) -
                        std::max(k.position[a].y, k.position[b].y);
      if (ox > 0 && oy > 0) worst = std::max(worst, std::min(ox, oy));
    }
  }
  return worst;
}

int outside(const World& w, double x0, double y0, double x1, double y1) {
  const Components& k = w.components;
  int n = 0;
  for (std::size_t e = 0; e < k.size(); ++e) {
    if (!std::isfinite(k.mass[e])) continue;
    const double cx = k.position[e].x + k.box[e].width / 2.0, cy = k.position[e].y + k.box[e].height / 2.0;
    if (!(cx > x0 && cx < x1 && cy > y0 && cy < y1)) ++n;
  }
  return n;
}

double step_energy(const World& w) {
  const Components& k = w.components;
  const Vector g = w.params.gravity;
  const double h = w.params.substep();
  const bool exact = w.exact_motion();  // then the energy kept in free flight is the plain one
  double E = 0.0;
  for (std::size_t e = 0; e < k.size(); ++e) {
    const double m = k.mass[e];
    if (!std::isfinite(m)) continue;
    const Vector v = k.velocity[e];
    E += m * (0.5 * Vector::dot(v, v) - Vector::dot(g, k.position[e]) + (exact ? 0.0 : 0.5 * h * Vector::dot(g, v)));
  }
  return E;
}

Vector momentum(const World& w) { return w.momentum(); }

}  // namespace physics::numerics
