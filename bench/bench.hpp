// `make bench`: the same scenes run by our engine, Box2D 2.4.1 and Chipmunk 7.
//
// Every engine receives the scene in one neutral description: metres,
// seconds, y up, bodies given by their centre and half-extents, block side 1 m
// (Box2D is tuned for bodies of 0.1-10 m; Chipmunk has no unit). Each adapter
// converts to its engine's units and back, so the harness measures quality
// (escapes, overlap, energy) the same way for all three.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace bench {

struct Body {
  double cx = 0, cy = 0;  // centre, m (y up)
  double hx = 0, hy = 0;  // half-extents, m
  double vx = 0, vy = 0;  // m/s
  bool fixed = false;     // walls, floor: infinite mass, never moves
};

struct Scene {
  std::string name;          // gas, rain, pyramid
  double width = 0;          // container interior [0, width] x [0, height], m
  double height = 0;
  double gravity = 0;        // m/s², pointing down (-y)
  double restitution = 1.0;  // every body, every engine
  double friction = 0.0;     // every body, every engine (a pair's: sqrt(mu_a mu_b), so this value)
  double dt = 1.0 / 60.0;    // s per step
  bool resting = false;      // bodies come to rest in contact (ours: stable solver)
  std::vector<Body> bodies;  // fixed bodies (walls) first
  std::size_t dynamic_count() const;
};

// gas: N unit squares at area fraction 0.10 in a square box, random
// velocities (seed 42), no gravity, e = 1.
Scene make_gas(std::size_t n, std::uint64_t seed = 42);
// rain: N unit squares on a grid (area fraction 0.25 of the container) fall
// under gravity 10 m/s² into it, e = 0.5.
Scene make_rain(std::size_t n);
// pyramid: Box2D's large_pyramid, a base of 100 squares, 5050 in all,
// resting on the floor; fixed rotation, e = 0.
Scene make_pyramid(std::size_t base = 100);
// pyramid_friction: the same with friction 0.6 on every body and the walls.
Scene make_pyramid_friction(std::size_t base = 100);

// One engine running one scene. Bodies keep the scene's order.
class Engine {
 public:
  virtual ~Engine() = default;
  virtual void step() = 0;
  // Centre and velocity of every body, in the scene's units and order
  // (fixed ones included). out is resized to the scene's body count.
  virtual void read(std::vector<Body>& out) const = 0;
};

// Each adapter sets every body's mass to 1 (fixed: static), the scene's friction (0 but in pyramid_friction),
// fixed rotation, sleeping off, and keeps the engine's default iterations.
// Ours runs the course's solver on scenes without resting contact and the
// stable solver on the others, unless `course` forces the course's solver.
std::unique_ptr<Engine> make_ours(const Scene& s, bool course = false);
std::unique_ptr<Engine> make_box2d(const Scene& s);
std::unique_ptr<Engine> make_chipmunk(const Scene& s);

}  // namespace bench
