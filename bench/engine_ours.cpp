// Our engine behind the bench's neutral interface. The scene is in metres,
// y up, centres; the engine works in pixels, y down, top-left corners (the
// sheet's SDL conventions), with integer box sizes: 1 m = px_per_m px.
#include <cmath>
#include <memory>

#include "bench.hpp"
#include "course/entities/block.hpp"
#include "course/game.hpp"

namespace bench {

namespace {

constexpr double px_per_m = 10.0;

class Ours final : public Engine {
 public:
  Ours(const Scene& s, bool course) : height_(s.height), world_(make_world(s, course)) {
    physics::World& w = *world_;
    w.components.reserve(s.bodies.size());
    for (const Body& b : s.bodies) {
      const auto e = physics::Block::make(
          w, (b.cx - b.hx) * px_per_m, (s.height - (b.cy + b.hy)) * px_per_m, static_cast<int>(2 * b.hx * px_per_m),
          static_cast<int>(2 * b.hy * px_per_m), physics::Color{200, 200, 200, 255},
          b.fixed ? physics::infinity : 1.0, s.restitution);
      w.components.velocity[e.id] = {b.vx * px_per_m / 1000.0, -b.vy * px_per_m / 1000.0};
      w.components.friction[e.id] = s.friction;
      ids_.push_back(e.id);
    }
  }

  void step() override { physics::Game::step(*world_); }

  void read(std::vector<Body>& out) const override {
    const physics::Components& k = world_->components;
    out.resize(ids_.size());
    for (std::size_t i = 0; i < ids_.size(); ++i) {
      const physics::EntityId e = ids_[i];
      const double w = k.box[e].width, h = k.box[e].height;
      out[i] = Body{(k.position[e].x + w / 2) / px_per_m,
                    height_ - (k.position[e].y + h / 2) / px_per_m,
                    w / 2 / px_per_m,
                    h / 2 / px_per_m,
                    k.velocity[e].x * 1000.0 / px_per_m,
                    -k.velocity[e].y * 1000.0 / px_per_m,
                    !std::isfinite(k.mass[e])};
    }
  }

 private:
  // A scene declares only the systems it needs: the gas has no force to
  // apply, so it runs without Forces (and pays nothing for it); nothing
  // draws. Scenes where bodies come to rest on each other use the stable
  // solver (the course's single pass cannot hold a pile, see docs/numerics.md).
  static std::unique_ptr<physics::World> make_world(const Scene& s, bool course) {
    physics::SystemSet set;
    set.draw = false;
    set.forces = s.gravity != 0.0;
    physics::Params p;
    p.dt = s.dt * 1000.0;
    p.gravity = {0.0, s.gravity * px_per_m / 1e6};
    p.solver = s.resting && !course ? physics::Solver::stable : physics::Solver::course;
    return std::make_unique<physics::World>(set, p);
  }

  double height_;
  std::unique_ptr<physics::World> world_;
  std::vector<physics::EntityId> ids_;
};

}  // namespace

std::unique_ptr<Engine> make_ours(const Scene& s, bool course) { return std::make_unique<Ours>(s, course); }

}  // namespace bench
