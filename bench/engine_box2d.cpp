// Box2D 2.4.1 adapter. Box2D works in metres, y up, body origin at the
// centre, like the scene, so positions and velocities pass through unchanged
// (as float: Box2D 2.4 is single precision).
//
// Settings (quoted in bench/RESULTS.md):
// - gravity (0, -g); sleeping off (world and every body);
// - dynamic bodies: fixedRotation = true, density = 1 / (4 hx hy), so mass 1;
//   fixed bodies: static bodies;
// - boxes: b2PolygonShape::SetAsBox(hx, hy), friction 0;
// - restitution e on every fixture (Box2D mixes max(a, b), so each pair gets
//   e); restitutionThreshold left at its default 1 m/s, except for e = 1 (the
//   gas), where it is 0 so slow collisions stay elastic as the scene says;
// - world.Step(dt, 8, 3): the testbed's velocity/position iterations;
// - a tile map (tiles_*): its map_boxes as fixtures of one static body, made
//   after the scene's bodies.
#include <box2d/box2d.h>

#include "bench.hpp"

namespace bench {

namespace {

class Box2dEngine final : public Engine {
 public:
  explicit Box2dEngine(const Scene& s)
      : initial_(s.bodies), world_(b2Vec2(0.0f, static_cast<float>(-s.gravity))), dt_(static_cast<float>(s.dt)) {
    world_.SetAllowSleeping(false);
    bodies_.reserve(s.bodies.size());
    // Created in scene order, so bodies_[i] is scene body i.
    for (const Body& b : s.bodies) {
      b2BodyDef def;
      def.type = b.fixed ? b2_staticBody : b2_dynamicBody;
      def.position.Set(static_cast<float>(b.cx), static_cast<float>(b.cy));
      def.linearVelocity.Set(static_cast<float>(b.vx), static_cast<float>(b.vy));
      def.fixedRotation = true;
      def.allowSleep = false;
      b2Body* body = world_.CreateBody(&def);

      b2PolygonShape box;
      box.SetAsBox(static_cast<float>(b.hx), static_cast<float>(b.hy));
      b2FixtureDef fix;
      fix.shape = &box;
      // Static bodies ignore density; dynamic ones get mass exactly 1.
      fix.density = static_cast<float>(1.0 / (4.0 * b.hx * b.hy));
      fix.friction = static_cast<float>(s.friction);  // Box2D mixes sqrt(a b): the pair gets s.friction
      fix.restitution = static_cast<float>(s.restitution);
      if (s.restitution == 1.0) fix.restitutionThreshold = 0.0f;
      body->CreateFixture(&fix);
      bodies_.push_back(body);
    }
    if (!s.map.cells.empty()) {
      const std::size_t before = heap_bytes();
      add_map(s);
      map_mb = static_cast<double>(heap_bytes() - before) / (1024.0 * 1024.0);
    }
  }

  void add_map(const Scene& s) {
    b2BodyDef def;  // static
    b2Body* body = world_.CreateBody(&def);
    for (const Body& b : map_boxes(s)) {
      b2PolygonShape box;
      box.SetAsBox(static_cast<float>(b.hx), static_cast<float>(b.hy),
                   b2Vec2(static_cast<float>(b.cx), static_cast<float>(b.cy)), 0.0f);
      b2FixtureDef fix;
      fix.shape = &box;
      fix.friction = static_cast<float>(s.friction);
      fix.restitution = static_cast<float>(s.restitution);
      body->CreateFixture(&fix);
    }
  }

  void step() override { world_.Step(dt_, 8, 3); }

  void read(std::vector<Body>& out) const override {
    out.resize(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      // Size and fixedness never change: start from the scene's body.
      out[i] = initial_[i];
      const b2Vec2 p = bodies_[i]->GetPosition();
      const b2Vec2 v = bodies_[i]->GetLinearVelocity();
      out[i].cx = p.x, out[i].cy = p.y, out[i].vx = v.x, out[i].vy = v.y;
    }
  }

 private:
  std::vector<Body> initial_;     // the scene's bodies, for their size
  b2World world_;                 // owns every body and fixture: its destructor frees them
  std::vector<b2Body*> bodies_;   // non-owning, scene order
  float dt_;
};

}  // namespace

std::unique_ptr<Engine> make_box2d(const Scene& s) { return std::make_unique<Box2dEngine>(s); }

}  // namespace bench
