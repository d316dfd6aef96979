#include "api/convert.hpp"

#include <cmath>

#include "engine/format.hpp"
#include "engine/limits.hpp"

namespace physics::api {

void require(bool ok, const char* what, const char* rule, double got) {
  if (!ok) throw Error(std::string(what) + " must be " + rule + " (got " + format_g(got) + ")");
}

void require(bool ok, const char* what, const char* rule, Vec2 got) {
  if (!ok)
    throw Error(std::string(what) + " must be " + rule + " (got (" + format_g(got.x) + ", " + format_g(got.y) + "))");
}

void check_finite(Vec2 v, const char* what) {
  require(std::isfinite(v.x) && std::isfinite(v.y), what, "finite", v);
}

void check_motion(Vec2 v, const char* what) {
  require(std::abs(v.x) <= max_motion && std::abs(v.y) <= max_motion, what, "finite, within 1e6 per axis", v);
}

void check_size(Vec2 s) {
  const auto whole = [](double d) { return d >= 1.0 && d <= max_block_size && d == std::floor(d); };
  require(whole(s.x) && whole(s.y), "a body's size", "whole pixels in [1, 1048576]", s);
}

// The scene files' bounds (engine/limits.hpp): beyond them an energy or an
// impulse overflows to inf.
void check_mass(double m) {
  require((m >= min_mass && m <= max_mass) || m == fixed_mass, "a body's mass", "in [1e-300, 1e150] or fixed_mass",
          m);
}

void check_restitution(double e) { require(e >= 0.0 && e <= 1.0, "a body's restitution", "in [0, 1]", e); }

void check_friction(double mu) {
  require(mu >= 0.0 && mu <= max_friction, "a body's friction", "in [0, 1000]", mu);
}

Solver to_engine(SolverKind s) {
  return s == SolverKind::stable ? Solver::stable : s == SolverKind::automatic ? Solver::automatic : Solver::course;
}
SolverKind to_public(Solver s) {
  return s == Solver::stable ? SolverKind::stable : s == Solver::automatic ? SolverKind::automatic : SolverKind::course;
}
Integrator to_engine(IntegratorKind i) { return i == IntegratorKind::exact ? Integrator::exact : Integrator::course; }
IntegratorKind to_public(Integrator i) { return i == Integrator::exact ? IntegratorKind::exact : IntegratorKind::course; }

Rect to_rect(Vec2 s) { return {static_cast<int>(s.x), static_cast<int>(s.y)}; }

ContactRules rules_of(Filter f, bool sensor, OneWay one_way) {
  ContactRules r;
  r.category = f.category;
  r.mask = f.mask;
  r.sensor = sensor;
  r.one_way = static_cast<Face>(one_way);  // same order: none, up, down, left, right
  return r;
}

}  // namespace physics::api
