// The public API's value types to the engine's and back, and its checks of
// values: each throws physics::Error with one line naming the bad value.
#pragma once

#include <string>

#include "engine/components.hpp"
#include "engine/world.hpp"
#include "physics/physics.hpp"

namespace physics::api {

inline Vector to_engine(Vec2 v) { return {v.x, v.y}; }
inline Vec2 to_public(Vector v) { return {v.x, v.y}; }
// The solver and the integrator, both ways (WorldDef <-> Params).
Solver to_engine(SolverKind s);
SolverKind to_public(Solver s);
Integrator to_engine(IntegratorKind i);
IntegratorKind to_public(Integrator i);

// Throws Error(what + " must be " + rule + " (got ...)") unless ok.
void require(bool ok, const char* what, const char* rule, double got);
void require(bool ok, const char* what, const char* rule, Vec2 got);

// Each value as a body's: throws Error naming `what` if out of range.
void check_finite(Vec2 v, const char* what);
void check_motion(Vec2 v, const char* what);  // finite, within 1e6 per axis
void check_size(Vec2 size);
void check_mass(double mass);
void check_restitution(double e);
void check_friction(double mu);
Rect to_rect(Vec2 size);  // after check_size

ContactRules rules_of(Filter f, bool sensor, OneWay one_way);
// The engine's one-way face as the API's, and back (rules_of): the same order.
static_assert(static_cast<int>(OneWay::right) == static_cast<int>(Face::right) &&
              static_cast<int>(OneWay::up) == static_cast<int>(Face::up));
inline OneWay to_public(Face f) { return static_cast<OneWay>(f); }

}  // namespace physics::api
