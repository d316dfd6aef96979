// Chipmunk 7.0.3 adapter. Chipmunk has no unit and its y axis points up; with
// a body's origin at its centre, the scene's metres pass through unchanged
// (cpFloat is double here).
//
// Compiled twice: against Debian's headers and library into build/bench
// (engine `chipmunk`), and against the release build of `make bench PEERS=DIR`
// into build/bench-peers (engine `chipmunk-release`, see the Makefile), so
// the two columns differ only by the library's build.
//
// Settings (quoted in bench/RESULTS.md):
// - gravity (0, -g); sleeping off: cpSpace's default sleepTimeThreshold is
//   INFINITY, which is off, so it is left alone;
// - dynamic bodies: cpBodyNew(1, INFINITY), mass 1, fixed rotation;
//   fixed bodies: cpBodyNewStatic, positioned at the centre;
// - boxes: cpBoxShapeNew(body, 2 hx, 2 hy, 0), friction 0;
// - elasticity sqrt(e) on every shape: Chipmunk multiplies the two shapes'
//   elasticities, so each pair gets e;
// - defaults kept: 10 iterations, collision slop and bias, bbtree index;
// - a tile map (tiles_*): its map_boxes as box shapes of one static body,
//   made after the scene's bodies.
#include <chipmunk/chipmunk.h>

#include <cmath>

#include "bench.hpp"

namespace bench {

namespace {

// Chipmunk is a C library: these deleters let unique_ptr own its objects.
struct FreeSpace {
  void operator()(cpSpace* p) const { cpSpaceFree(p); }
};
struct FreeBody {
  void operator()(cpBody* p) const { cpBodyFree(p); }
};
struct FreeShape {
  void operator()(cpShape* p) const { cpShapeFree(p); }
};

class ChipmunkEngine final : public Engine {
 public:
  explicit ChipmunkEngine(const Scene& s) : initial_(s.bodies), space_(cpSpaceNew()), dt_(s.dt) {
    cpSpaceSetGravity(space_.get(), cpv(0.0, -s.gravity));
    const cpFloat elasticity = std::sqrt(s.restitution);
    bodies_.reserve(s.bodies.size());
    shapes_.reserve(s.bodies.size());
    // Created in scene order, so bodies_[i] is scene body i.
    for (const Body& b : s.bodies) {
      cpBody* body = bodies_.emplace_back(b.fixed ? cpBodyNewStatic() : cpBodyNew(1.0, INFINITY)).get();
      // Position before the shape is added, so the spatial index sees it in place.
      cpBodySetPosition(body, cpv(b.cx, b.cy));
      cpBodySetVelocity(body, cpv(b.vx, b.vy));
      cpSpaceAddBody(space_.get(), body);

      cpShape* shape = shapes_.emplace_back(cpBoxShapeNew(body, 2.0 * b.hx, 2.0 * b.hy, 0.0)).get();
      cpShapeSetFriction(shape, std::sqrt(s.friction));  // Chipmunk multiplies the two: the pair gets s.friction
      cpShapeSetElasticity(shape, elasticity);
      cpSpaceAddShape(space_.get(), shape);  // shapes of static bodies go to the static index
    }
    if (!s.map.cells.empty()) {
      const std::size_t before = heap_bytes();
      add_map(s, elasticity);
      map_mb = static_cast<double>(heap_bytes() - before) / (1024.0 * 1024.0);
    }
  }

  void add_map(const Scene& s, cpFloat elasticity) {
    map_body_.reset(cpBodyNewStatic());
    cpSpaceAddBody(space_.get(), map_body_.get());
    for (const Body& b : map_boxes(s)) {
      const cpBB bb = cpBBNew(b.cx - b.hx, b.cy - b.hy, b.cx + b.hx, b.cy + b.hy);
      cpShape* shape = shapes_.emplace_back(cpBoxShapeNew2(map_body_.get(), bb, 0.0)).get();
      cpShapeSetFriction(shape, std::sqrt(s.friction));
      cpShapeSetElasticity(shape, elasticity);
      cpSpaceAddShape(space_.get(), shape);
    }
  }

  void step() override { cpSpaceStep(space_.get(), dt_); }

  void read(std::vector<Body>& out) const override {
    out.resize(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      // Size and fixedness never change: start from the scene's body.
      out[i] = initial_[i];
      const cpVect p = cpBodyGetPosition(bodies_[i].get());
      const cpVect v = cpBodyGetVelocity(bodies_[i].get());
      out[i].cx = p.x, out[i].cy = p.y, out[i].vx = v.x, out[i].vy = v.y;
    }
  }

 private:
  std::vector<Body> initial_;  // the scene's bodies, for their size
  // Members are destroyed in reverse order: the space first (cpSpaceFree
  // still wakes its bodies, but frees neither bodies nor shapes), then the
  // shapes, then the bodies they are attached to.
  std::vector<std::unique_ptr<cpBody, FreeBody>> bodies_;
  std::unique_ptr<cpBody, FreeBody> map_body_;  // the map's shapes' (not a scene body)
  std::vector<std::unique_ptr<cpShape, FreeShape>> shapes_;
  std::unique_ptr<cpSpace, FreeSpace> space_;
  cpFloat dt_;
};

}  // namespace

std::unique_ptr<Engine> make_chipmunk(const Scene& s) { return std::make_unique<ChipmunkEngine>(s); }

}  // namespace bench
