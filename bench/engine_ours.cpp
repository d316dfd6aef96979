// Our engine behind the bench's neutral interface, through the public API
// (include/physics/physics.hpp) as a game would use it. The scene is in
// metres, y up, centres; the engine works in pixels, y down, top-left
// corners (the sheet's SDL conventions), with integer box sizes: 1 m =
// px_per_m px.
#include <cmath>
#include <memory>

#include "bench.hpp"
#include "physics/physics.hpp"

namespace bench {

namespace {

constexpr double px_per_m = 10.0;

class Ours final : public Engine {
 public:
  Ours(const Scene& s, bool course, int threads)
      : height_(s.height), world_(physics::create_world(def(s, course, threads))) {
    if (!s.map.cells.empty()) {  // first, in an empty world: what the heap grows by is the layer's
      const std::size_t before = heap_bytes();
      add_map(s);
      map_mb = static_cast<double>(heap_bytes() - before) / (1024.0 * 1024.0);
    }
    for (const Body& b : s.bodies) {
      physics::BodyDef d = physics::default_body_def();
      d.position = {(b.cx - b.hx) * px_per_m, (s.height - (b.cy + b.hy)) * px_per_m};
      d.size = {std::trunc(2 * b.hx * px_per_m), std::trunc(2 * b.hy * px_per_m)};
      d.color = {200, 200, 200, 255};
      d.mass = b.fixed ? physics::fixed_mass : 1.0;
      d.restitution = s.restitution;
      d.velocity = {b.vx * px_per_m / 1000.0, (0.0 - b.vy) * px_per_m / 1000.0};  // (not -vy: a wall at rest has +0, as in a game)
      d.friction = s.friction;
      ids_.push_back(physics::create_body(world_, d));
    }
  }
  ~Ours() override { physics::destroy_world(world_); }
  Ours(const Ours&) = delete;
  Ours& operator=(const Ours&) = delete;

  void step() override { physics::step(world_); }
  const StageSteps* stages() const override { return &stages_; }
  // The time a stage since the last call (the last step's, called after
  // every step): the profile's totals (its means times the world's steps)
  // less the last call's.
  void keep_stage_times() override {
    const std::vector<physics::StageTime> p = physics::profile(world_);
    const auto steps = static_cast<double>(physics::frame(world_));
    if (stages_.names.empty())
      for (const physics::StageTime& t : p) stages_.names.emplace_back(t.stage), totals_.push_back(0.0);
    std::vector<double>& now = stages_.steps.emplace_back(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double total = p[i].ms_per_step * steps;
      now[i] = total - totals_[i], totals_[i] = total;
    }
  }

  // The map as one tile layer (its definition freed before the heap is measured again).
  void add_map(const Scene& s) {
    physics::TileLayerDef d;
    d.position = {0.0, (s.height - s.map.rows * s.map.cell) * px_per_m};
    d.cell_size = static_cast<int>(std::lround(s.map.cell * px_per_m));
    d.columns = s.map.columns, d.rows = s.map.rows;
    d.cells.reserve(s.map.cells.size());
    for (const std::uint8_t c : s.map.cells) d.cells.push_back(c ? physics::TileKind::solid : physics::TileKind::empty);
    d.restitution = s.restitution;
    d.friction = s.friction;
    physics::create_tile_layer(world_, d);
  }

  void read(std::vector<Body>& out) const override {
    out.resize(ids_.size());
    for (std::size_t i = 0; i < ids_.size(); ++i) {
      const physics::BodyId id = ids_[i];
      const physics::Vec2 p = physics::position(id), size = physics::size(id), v = physics::velocity(id);
      out[i] = Body{(p.x + size.x / 2) / px_per_m,
                    height_ - (p.y + size.y / 2) / px_per_m,
                    size.x / 2 / px_per_m,
                    size.y / 2 / px_per_m,
                    v.x * 1000.0 / px_per_m,
                    -v.y * 1000.0 / px_per_m,
                    !std::isfinite(physics::mass(id))};
    }
  }

 private:
  // A world runs only the systems it needs: the gas has no force to apply,
  // so it runs without Forces (and pays nothing for it). Scenes where bodies
  // come to rest on each other use the stable solver (the course's single
  // pass cannot hold a pile, see docs/numerics.md).
  static physics::WorldDef def(const Scene& s, bool course, int threads) {
    physics::WorldDef d = physics::default_world_def();
    d.threads = threads;
    d.forces = s.gravity != 0.0;
    d.dt = s.dt * 1000.0;
    d.gravity = {0.0, s.gravity * px_per_m / 1e6};
    d.solver = s.resting && !course ? physics::SolverKind::stable : physics::SolverKind::course;
    return d;
  }

  double height_;
  physics::WorldId world_;
  std::vector<physics::BodyId> ids_;
  StageSteps stages_;
  std::vector<double> totals_;  // by stage: ms up to the last step kept
};

}  // namespace

std::unique_ptr<Engine> make_ours(const Scene& s, bool course, int threads) {
  return std::make_unique<Ours>(s, course, threads);
}

}  // namespace bench
