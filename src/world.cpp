#include "world.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace physics {

void validate(const Params& p) {
  if (!std::isfinite(p.dt) || p.dt <= 0.0)
    throw std::invalid_argument("dt must be a finite number > 0 (got " + std::to_string(p.dt) + ")");
  if (p.substeps < 1)
    throw std::invalid_argument("substeps must be >= 1 (got " + std::to_string(p.substeps) + ")");
  if (p.iterations < 1)
    throw std::invalid_argument("iterations must be >= 1 (got " + std::to_string(p.iterations) + ")");
  if (!std::isfinite(p.gravity.x) || !std::isfinite(p.gravity.y))
    throw std::invalid_argument("gravity must be finite");
}

double SystemTimes::ms_per_step(SystemId s) const {
  return steps == 0 ? 0.0 : static_cast<double>(ns[static_cast<int>(s)]) / 1e6 / static_cast<double>(steps);
}

double SystemTimes::total_ms_per_step() const {
  double t = 0.0;
  for (const SystemId s : all_systems) t += ms_per_step(s);
  return t;
}

World::World(SystemSet set, Params p) : systems(set), params(p) { validate(params); }

namespace {
template <class F>
void timed(std::int64_t& acc, F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  acc += std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

void World::step() {
  const double h = params.dt / params.substeps;
  auto& ns = times.ns;
  if (params.ccd || params.solver != Solver::course) {
    step_numerics(h);
    return;
  }
  for (int k = 0; k < params.substeps; ++k) {
    if (systems.forces)
      timed(ns[static_cast<int>(SystemId::forces)], [&] { systems.forces->update(components, h, params.gravity); });
    if (systems.move)
      timed(ns[static_cast<int>(SystemId::move)], [&] { systems.move->update(components, h); });
    if (systems.collision)
      timed(ns[static_cast<int>(SystemId::collision)], [&] { systems.collision->update(components); });
  }
  ++times.steps;
  ++frame;
}

// The numerics options (README: docs/numerics.md). Kept apart from the course
// loop above, which stays exactly the sheet's.
void World::step_numerics(double h) {
  auto& ns = times.ns;
  auto& collision_ns = ns[static_cast<int>(SystemId::collision)];
  const bool stable = params.solver == Solver::stable;
  SolverSettings settings;
  settings.iterations = params.iterations;
  settings.impacts = !params.ccd;
  for (int k = 0; k < params.substeps; ++k) {
    if (systems.forces)
      timed(ns[static_cast<int>(SystemId::forces)], [&] { systems.forces->update(components, h, params.gravity); });
    if (systems.collision) {
      timed(collision_ns, [&] {
        const auto bodies = systems.collision->entities();
        if (stable) contact_solver.solve_velocities(components, bodies, h, params.gravity, settings);
        if (params.ccd) ccd.resolve(components, bodies, h, params.gravity);
      });
    }
    if (systems.move)
      timed(ns[static_cast<int>(SystemId::move)], [&] { systems.move->update(components, h); });
    if (systems.collision) {
      timed(collision_ns, [&] {
        if (stable)
          contact_solver.solve_positions(components, systems.collision->entities(), params.gravity, settings);
        else
          systems.collision->update(components);  // what CCD left overlapping (spawned so, or capped)
      });
    }
  }
  ++times.steps;
  ++frame;
}

double World::kinetic_energy() const {
  double ke = 0.0;
  for (std::size_t e = 0; e < components.size(); ++e) {
    const double m = components.mass[e];
    if (!std::isfinite(m)) continue;
    ke += 0.5 * m * Vector::dot(components.velocity[e], components.velocity[e]);
  }
  return ke;
}

Vector World::momentum() const {
  Vector p{};
  for (std::size_t e = 0; e < components.size(); ++e) {
    const double m = components.mass[e];
    if (!std::isfinite(m)) continue;
    p = p + m * components.velocity[e];
  }
  return p;
}

std::size_t World::finite_bodies() const {
  std::size_t n = 0;
  for (const double m : components.mass) n += std::isfinite(m) ? 1 : 0;
  return n;
}

}  // namespace physics
