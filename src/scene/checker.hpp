// The scene validator's checks, internal to src/scene: each throws
// SceneError("source: path: problem"), the path built only for a failing
// value (a large scene's thousands of bodies pass without a string made).
// Shared by validate() (scene.cpp) and the key tables (keys.cpp).
#pragma once

#include <cmath>
#include <string>

#include "engine/format.hpp"
#include "scene/scene.hpp"

namespace physics::scene_check {

// "%g"-like text for messages: short, and exact enough to find the value.
inline std::string num(double v) { return format_g(v, 10); }

inline std::string entry_path(std::size_t i) { return "blocks[" + std::to_string(i) + "]"; }

// A key path, built only when a check fails: `base` + `key`
// ("blocks[3]" + ".mass"). Checks run for every body of a large scene, so
// the strings of messages are never built on the way to a pass.
struct At {
  const std::string& base;
  const char* key = "";
  std::string str() const { return base + key; }
};

// Raises the error for one scene; every message starts with "source: path: ".
struct Checker {
  const std::string& source;
  [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
    throw SceneError(source + ": " + path + ": " + problem);
  }
  [[noreturn]] void fail(At at, const std::string& problem) const { fail(at.str(), problem); }
  void finite(double v, At at) const {
    if (!std::isfinite(v)) fail(at, "must be a finite number (got " + num(v) + ")");
  }
  void finite(Vector v, At at) const {
    if (!std::isfinite(v.x) || !std::isfinite(v.y)) fail(at, "must be finite (got [" + num(v.x) + ", " + num(v.y) + "])");
  }
  // Velocities, forces, impulses and gravity: finite is not enough, since a
  // finite 1e308 px/ms overflows to infinity on the first Move. 1e6 px/ms
  // (a world crossed in one microsecond) is far beyond any sensible scene.
  void motion(Vector v, At at) const {
    finite(v, at);
    if (std::abs(v.x) > max_motion || std::abs(v.y) > max_motion)
      fail(at, "must be within ±" + num(max_motion) + " (got [" + num(v.x) + ", " + num(v.y) + "])");
  }
  void motion(const VecSpec& v, At at) const {
    range(v, at);
    motion(Vector{v.x.lo, v.y.lo}, at);
    motion(Vector{v.x.hi, v.y.hi}, at);
  }
  void size(int v, At at) const {
    if (v <= 0) fail(at, "must be > 0 (got " + std::to_string(v) + ")");
    if (v > max_block_size) fail(at, "must be <= " + std::to_string(max_block_size) + " (got " + std::to_string(v) + ")");
  }
  void mass(double m, At at) const {
    if (std::isnan(m) || m <= 0.0 || m == -infinity) fail(at, "must be > 0 or \"inf\" (got " + num(m) + ")");
    if (m != infinity && (m < min_mass || m > max_mass))
      fail(at, "must be in [" + num(min_mass) + ", " + num(max_mass) + "] or \"inf\" (got " + num(m) +
                   "): beyond, energies and impulses overflow");
  }
  void friction(double mu, At at) const {
    if (!(mu >= 0.0 && mu <= max_friction)) fail(at, "must be in [0, " + num(max_friction) + "] (got " + num(mu) + ")");
  }
  void restitution(double e, At at) const {
    if (!(e >= 0.0 && e <= 1.0)) fail(at, "must be in [0, 1] (got " + num(e) + ")");
  }
  void range(const RealSpec& r, At at) const {
    finite(r.lo, at);
    finite(r.hi, at);
    if (r.drawn && r.lo > r.hi) fail(at, "range [" + num(r.lo) + ", " + num(r.hi) + "] is empty (min > max)");
  }
  void range(const VecSpec& v, At at) const {
    range(v.x, at);
    range(v.y, at);
  }
  void size_range(const IntSpec& r, At at) const {
    size(r.lo, at);
    size(r.hi, at);
    if (r.drawn && r.lo > r.hi)
      fail(at, "range [" + std::to_string(r.lo) + ", " + std::to_string(r.hi) + "] is empty (min > max)");
  }
};

}  // namespace physics::scene_check
