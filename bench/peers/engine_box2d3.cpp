// Box2D v3.2 adapter, for build/bench-peers (make bench PEERS=DIR). It is
// compiled with v3's include path only: Debian's 2.4.1 headers have the same
// name (box2d/box2d.h). Box2D v3 works in metres, y up, body origin at the
// centre, like the scene, so positions and velocities pass through unchanged
// (as float: the default build is single precision).
//
// Settings, mirroring bench/engine_box2d.cpp (quoted in bench/RESULTS.md):
// - gravity (0, -g); sleeping off (world and every body); one worker thread
//   (the default), or two for `box2d3-2t` (workerCount 2: v3's own scheduler
//   and threads, which it makes when no task callbacks are given);
// - dynamic bodies: motionLocks.angularZ (v3's fixed rotation), density
//   1 / (4 hx hy), so mass 1; fixed bodies: static bodies;
// - boxes: b2MakeBox(hx, hy), the scene's friction (v3 mixes sqrt(a b): the
//   pair gets it) and restitution e (mixed max(a, b): the pair gets e) in the
//   shape's material;
// - restitutionThreshold left at its default 1 m/s, except for e = 1 (the
//   gas), where it is 0 so slow collisions stay elastic as the scene says;
// - b2World_Step(dt, 4): v3's recommended 4 substeps;
// - a tile map (tiles_*): its map_boxes as shapes of one static body, made
//   after the scene's bodies.
#include <box2d/box2d.h>

#include "../bench.hpp"

namespace bench {

namespace {

constexpr int substeps = 4;

b2BodyId add_body(b2WorldId world, const Body& b) {
  b2BodyDef def = b2DefaultBodyDef();
  def.type = b.fixed ? b2_staticBody : b2_dynamicBody;
  def.position.x = static_cast<float>(b.cx);
  def.position.y = static_cast<float>(b.cy);
  def.linearVelocity = {static_cast<float>(b.vx), static_cast<float>(b.vy)};
  def.motionLocks.angularZ = true;
  def.enableSleep = false;
  return b2CreateBody(world, &def);
}

void add_box(b2BodyId body, const Body& b, const Scene& s) {
  b2ShapeDef def = b2DefaultShapeDef();
  // Static bodies ignore density; dynamic ones get mass exactly 1.
  def.density = static_cast<float>(1.0 / (4.0 * b.hx * b.hy));
  def.material.friction = static_cast<float>(s.friction);
  def.material.restitution = static_cast<float>(s.restitution);
  const b2Polygon box = b2MakeBox(static_cast<float>(b.hx), static_cast<float>(b.hy));
  b2CreatePolygonShape(body, &def, &box);
}

class Box2d3Engine final : public Engine {
 public:
  Box2d3Engine(const Scene& s, int workers) : initial_(s.bodies), dt_(static_cast<float>(s.dt)) {
    b2WorldDef def = b2DefaultWorldDef();
    def.workerCount = workers;
    def.gravity = {0.0f, static_cast<float>(-s.gravity)};
    def.enableSleep = false;
    if (s.restitution == 1.0) def.restitutionThreshold = 0.0f;
    world_ = b2CreateWorld(&def);
    bodies_.reserve(s.bodies.size());
    // Created in scene order, so bodies_[i] is scene body i.
    for (const Body& b : s.bodies) {
      bodies_.push_back(add_body(world_, b));
      add_box(bodies_.back(), b, s);
    }
    if (!s.map.cells.empty()) {
      const std::size_t before = heap_bytes();
      add_map(s);
      map_mb = static_cast<double>(heap_bytes() - before) / (1024.0 * 1024.0);
    }
  }

  void add_map(const Scene& s) {
    b2BodyDef def = b2DefaultBodyDef();  // static
    const b2BodyId body = b2CreateBody(world_, &def);
    b2ShapeDef shape = b2DefaultShapeDef();
    shape.material.friction = static_cast<float>(s.friction);
    shape.material.restitution = static_cast<float>(s.restitution);
    for (const Body& b : map_boxes(s)) {
      const b2Vec2 centre{static_cast<float>(b.cx), static_cast<float>(b.cy)};
      const b2Polygon box = b2MakeOffsetBox(static_cast<float>(b.hx), static_cast<float>(b.hy), centre, b2Rot_identity);
      b2CreatePolygonShape(body, &shape, &box);
    }
  }
  ~Box2d3Engine() override { b2DestroyWorld(world_); }  // frees every body and shape
  Box2d3Engine(const Box2d3Engine&) = delete;
  Box2d3Engine& operator=(const Box2d3Engine&) = delete;

  void step() override { b2World_Step(world_, dt_, substeps); }

  void read(std::vector<Body>& out) const override {
    out.resize(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      // Size and fixedness never change: start from the scene's body.
      out[i] = initial_[i];
      const auto p = b2Body_GetPosition(bodies_[i]);
      const b2Vec2 v = b2Body_GetLinearVelocity(bodies_[i]);
      out[i].cx = p.x, out[i].cy = p.y, out[i].vx = v.x, out[i].vy = v.y;
    }
  }

 private:
  std::vector<Body> initial_;     // the scene's bodies, for their size
  b2WorldId world_{};
  std::vector<b2BodyId> bodies_;  // handles into world_, scene order
  float dt_;
};

}  // namespace

std::unique_ptr<Engine> make_box2d3(const Scene& s, int workers) { return std::make_unique<Box2d3Engine>(s, workers); }

}  // namespace bench
