#include "app/soak.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace physics {

double total_energy(const World& w) {
  const Components& c = w.components;
  const Vector g = w.params.gravity;
  double e = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const double m = c.mass[i];
    if (!std::isfinite(m)) continue;
    e += 0.5 * m * Vector::dot(c.velocity[i], c.velocity[i]) - m * Vector::dot(g, c.position[i]);
  }
  return e;
}

SoakLimits soak_limits(const SceneSpec& spec, const World& w) {
  SoakLimits l;
  const double t = spec.walls ? wall_thickness : 0.0;
  l.min_x = t, l.min_y = t, l.max_x = spec.width - t, l.max_y = spec.height - t;
  const Components& c = w.components;
  const double g = Vector::norm(w.params.gravity);
  bool elastic = g == 0.0;
  double sink_energy = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (!std::isfinite(c.mass[i])) continue;
    elastic = elastic && c.restitution[i] == 1.0;
    sink_energy += c.mass[i] * g * 1.0;
  }
  const double e0 = std::abs(total_energy(w));
  l.energy_conserved = elastic;
  l.settled = g != 0.0 && w.params.solver == Solver::course;
  l.energy_slack = sink_energy + 1e-9 * e0;
  return l;
}

namespace {

// The first problem in the world's state, or an empty string.
std::string check(const World& w, const SoakLimits& lim, double e0, double e, double& wall_depth) {
  const Components& c = w.components;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (!std::isfinite(c.mass[i])) continue;
    const Vector p = c.position[i], v = c.velocity[i];
    std::ostringstream msg;
    msg.precision(17);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(v.x) || !std::isfinite(v.y)) {
      msg << "body " << i << " is not finite: pos (" << p.x << ", " << p.y << ") vel (" << v.x << ", " << v.y << ")";
      return msg.str();
    }
    const double w_ = c.box[i].width, h = c.box[i].height;
    wall_depth = std::max({wall_depth, lim.min_x - p.x, lim.min_y - p.y, p.x + w_ - lim.max_x, p.y + h - lim.max_y});
    const double cx = p.x + w_ / 2, cy = p.y + h / 2;
    if (!(cx > lim.min_x && cx < lim.max_x && cy > lim.min_y && cy < lim.max_y)) {
      msg << "body " << i << " left the walls: pos (" << p.x << ", " << p.y << ")";
      return msg.str();
    }
  }
  if (e > e0 + lim.energy_slack || (lim.energy_conserved && e < e0 - lim.energy_slack)) {
    std::ostringstream msg;
    msg.precision(17);
    msg << "energy " << e << " outside its bound (reference " << e0 << ", slack " << lim.energy_slack << ")";
    return msg.str();
  }
  return {};
}

}  // namespace

SoakResult soak(World& w, std::int64_t steps, std::int64_t every, const SoakLimits& limits) {
  SoakResult r;
  r.energy_start = r.energy_min = r.energy_max = r.energy_reference = total_energy(w);
  for (std::int64_t done = 0; done < steps;) {
    const std::int64_t n = std::min(every, steps - done);
    for (std::int64_t k = 0; k < n; ++k) Game::step(w);
    done += n;
    r.steps = done;
    ++r.checks;
    const double e = total_energy(w);
    r.energy_min = std::min(r.energy_min, e);
    r.energy_max = std::max(r.energy_max, e);
    if (limits.settled && r.checks == 1) r.energy_reference = e;
    r.failure = check(w, limits, r.energy_reference, e, r.max_wall_depth);
    if (!r.failure.empty()) {
      r.ok = false;
      r.failure = "step " + std::to_string(done) + ": " + r.failure;
      break;
    }
  }
  return r;
}

}  // namespace physics
