#include "engine/world.hpp"

#include "engine/contact.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace physics {

void validate(const Params& p) {
  if (!std::isfinite(p.dt) || p.dt < min_dt || p.dt > max_dt)
    throw std::invalid_argument("dt must be a finite number in [1e-6, 1e6] ms (got " + std::to_string(p.dt) + ")");
  if (p.substeps < 1 || p.substeps > max_substeps)
    throw std::invalid_argument("substeps must be in [1, 1000] (got " + std::to_string(p.substeps) + ")");
  if (p.iterations < 1 || p.iterations > max_iterations)
    throw std::invalid_argument("iterations must be in [1, 1000] (got " + std::to_string(p.iterations) + ")");
  if (!(std::abs(p.gravity.x) <= max_motion && std::abs(p.gravity.y) <= max_motion))
    throw std::invalid_argument("gravity must be finite, within 1e6 per axis");
}

std::string_view name(Solver s) {
  switch (s) {
    case Solver::stable: return "stable";
    case Solver::automatic: return "auto";
    default: return "course";
  }
}

std::optional<Solver> solver_from_name(std::string_view name) {
  for (const Solver s : {Solver::course, Solver::stable, Solver::automatic})
    if (physics::name(s) == name) return s;
  return std::nullopt;
}

std::string_view name(Integrator i) { return i == Integrator::exact ? "exact" : "course"; }

std::optional<Integrator> integrator_from_name(std::string_view name) {
  for (const Integrator i : {Integrator::course, Integrator::exact})
    if (name == physics::name(i)) return i;
  return std::nullopt;
}

std::string_view name(Stage s) {
  static constexpr std::string_view names[stage_count] = {
      "forces", "move", "collision", "pairs", "ccd", "prepare", "warm_start", "relax", "restitution", "impact_time",
      "store", "positions", "health"};
  return names[static_cast<std::size_t>(s)];
}

double StageTimes::ms_per_step(Stage s) const {
  return steps == 0 ? 0.0 : static_cast<double>(ns[static_cast<std::size_t>(s)]) / 1e6 / static_cast<double>(steps);
}

double StageTimes::total_ms_per_step() const {
  double t = 0.0;
  for (std::size_t s = 0; s < stage_count; ++s) t += ms_per_step(static_cast<Stage>(s));
  return t;
}

World::World(SystemSet set, Params p) : params(p) {
  validate(params);
  for (const SystemId s : all_systems)
    if (set.has(s)) stages_[index(s)].emplace();
}

SystemSet World::declared() const {
  SystemSet set;
  for (const SystemId s : all_systems) set.set(s, declares(s));
  return set;
}

std::span<const EntityId> World::bodies(SystemId s) const {
  const auto& list = stages_[index(s)];
  return list ? std::span<const EntityId>(*list) : std::span<const EntityId>();
}

std::vector<EntityId>* World::stage(SystemId s) {
  auto& list = stages_[index(s)];
  return list ? &*list : nullptr;
}

const std::vector<EntityId>* World::stage(SystemId s) const {
  const auto& list = stages_[index(s)];
  return list ? &*list : nullptr;
}

void World::add(SystemId s, EntityId e) {
  if (auto* list = stage(s)) list->push_back(e);
}

EntityId World::add_tile_layer(Vector position, TileGrid grid) {
  if (const std::string bad = check(grid); !bad.empty()) throw std::invalid_argument(bad);
  const EntityId e = components.create();
  components.position[e] = position;
  components.box[e] = Rect{grid.cell * grid.columns, grid.cell * grid.rows};
  components.mass[e] = infinity;
  health.ignore(e);
  tiles.add(TileLayer(e, std::move(grid)));
  return e;
}

// The strips near the Collision stage's bodies, as proxies listed before
// them. The reach covers every stage that pairs bodies in this substep: the
// course pass's margin (1 px), the stable solver's (0.5 px), contact
// events' (0.25 px), CCD's sweep (the swept box), and gravity's kick, which
// Forces gave before this.
void World::gather_tiles(double h) {
  created_.clear();
  tiles.gather(components, bodies(SystemId::collision), h, 2.0, proxies_, created_);
  if (!created_.empty()) {
    destroyed_.resize(components.size(), 0);
    for (const EntityId e : created_) destroyed_[e] = 2, health.ignore(e);
    events.owner.assign(tiles.owners().begin(), tiles.owners().end());
  }
  colliding_.assign(proxies_.begin(), proxies_.end());
  const auto list = bodies(SystemId::collision);
  colliding_.insert(colliding_.end(), list.begin(), list.end());
}

void World::destroy(EntityId e) {
  if (e >= components.size() || !alive(e)) return;
  for (auto& list : stages_)
    if (list) std::erase(*list, e);
  destroyed_.resize(components.size(), 0);
  destroyed_[e] = 1;
  if (!tiles.empty()) tiles.remove(e);  // a tile layer's strips go with it
}

namespace {
SolverSettings solver_settings(const Params& p, Workers& workers) {
  SolverSettings s;
  s.workers = &workers;
  s.iterations = p.iterations;
  s.impacts = !p.ccd;  // with CCD on, impacts are its business
  s.exact_motion = p.integrator == Integrator::exact;
  // SolverSettings::rounds: the stable solver's, and auto's under gravity
  // only: without it auto's solver path is a fast gas's (many fast bodies),
  // whose step they doubled (gas10k 1.9 -> 3.6 s for 300 frames) for nothing
  // the family measures.
  const bool rounds = p.solver == Solver::stable || (p.solver == Solver::automatic && !Vector::is_zero(p.gravity));
  s.rounds = rounds ? 3 : 0;
  s.physical_axes = p.solver == Solver::automatic;
  return s;
}
}  // namespace

void World::before_forces() {
  if (exact_motion() && declares(SystemId::move)) exact_.start(components, bodies(SystemId::move));
  // The velocities before Forces are read by the slide's shift (bodies with
  // friction) and, with CCD, by the solver (ContactSolver::turned_by_forces).
  if (slides()) {
    const std::vector<double>& mu = components.friction;
    const bool ccd = params.ccd || params.solver == Solver::automatic;
    // (The browser's build, short of room, always copies them.)
    const auto any_in = [&](int, std::size_t begin, std::size_t end) {
      const auto from = mu.begin() + static_cast<std::ptrdiff_t>(begin);
      const auto to = mu.begin() + static_cast<std::ptrdiff_t>(end);
      return static_cast<std::uint8_t>(std::any_of(from, to, [](double f) { return f != 0.0; }));
    };
    // (CCD reads them anyway: then no scan.)
    const bool needed =
        ccd || !keeps_unchanged || workers.or_over_ranges(mu.size(), min_parallel_items, any_in) != 0;
    slide_.start(components, needed);
  }
}

void World::before_move(double h) {
  const bool exact = exact_motion() && declares(SystemId::move);
  if (exact) exact_.after_forces(components, bodies(SystemId::move));
  if (declares(SystemId::collision)) {
    // Timed with the broad phase's pairs: it is the tiles' broad phase.
    if (!tiles.empty()) times.time(Stage::pairs, [&] { gather_tiles(h); });
    const auto colliding = this->colliding();
    if (params.solver == Solver::automatic) {
      auto_before_move(colliding, h);
    } else {
      if (params.solver == Solver::stable) solve_velocities(colliding, h, solver_settings(params, workers));
      if (params.ccd) sweep(colliding, h);
    }
  }
  // Last, so that they see which velocities the solver and CCD changed, and
  // timed with Move, whose result they correct.
  if (slides()) times.time(Stage::move, [&] { slide_.shift(components, h); });
  if (exact) times.time(Stage::move, [&] { exact_.shift(components, bodies(SystemId::move), h); });
}

// The auto mode's substep (engine/auto_mode.hpp): the solver's velocities
// if it chose the solver (impacts included: CCD only sweeps what is still
// fast after them), then CCD for the fast bodies.
void World::auto_before_move(std::span<const EntityId> bodies, double h) {
  pass.record_contacts = true;  // the pass's contacts tell auto whether they persist
  // The choice is not timed: two clock reads would cost a tenth of a small
  // scene's step, more than the choice itself (an O(n) look at velocities).
  if (automatic.plan(components, bodies, h, params.gravity)) {
    SolverSettings s = solver_settings(params, workers);
    s.impacts = !automatic.sweep_all();
    if (automatic.sweep_all()) {
      solve_velocities(bodies, h, s);
      automatic.stats.contacts += static_cast<std::int64_t>(contact_solver.constraints().size());
      automatic.stats.swept += static_cast<std::int64_t>(bodies.size());
      return automatic.after_sweep(sweep(bodies, h));
    }
    automatic.keep(components);
    contact_solver.solve_velocities(components, bodies, h, params.gravity, s, broadphase, times);
    automatic.after_solver(components, bodies, contact_solver.constraints(), contact_solver.impulses(), h);
    automatic.roll_back(components, bodies, contact_solver.constraints(), contact_solver.impulses());
    slide_.after_solver(components, contact_solver.constraints(), contact_solver.friction_rows());
    record_solver_contacts();
  }
  if (automatic.fast_count() == 0) return;
  automatic.stats.swept += static_cast<std::int64_t>(automatic.fast_count());
  const CcdSelection selection = automatic.selection();
  automatic.after_sweep(sweep(bodies, h, &selection));
}

void World::solve_velocities(std::span<const EntityId> bodies, double h, SolverSettings s) {
  if (slides()) s.before_forces = slide_.before_forces();
  contact_solver.solve_velocities(components, bodies, h, params.gravity, s, broadphase, times);
  slide_.after_solver(components, contact_solver.constraints(), contact_solver.friction_rows());
  record_solver_contacts();
}

bool World::sweep(std::span<const EntityId> bodies, double h, const CcdSelection* selection) {
  const std::int64_t capped = ccd.stats.capped_substeps;
  times.time(Stage::ccd, [&] {
    ccd.resolve(components, bodies, h, params.gravity, exact_motion(), broadphase, events, selection);
  });
  return ccd.stats.capped_substeps > capped;
}

void World::enable_events() {
  events.enabled = true;
  if (declares(SystemId::collision)) pass.record_contacts = true;
}

// The course pass's contacts, recorded by the pass (engine/step.hpp).
void World::record_contacts() {
  if (!declares(SystemId::collision)) return;
  if (params.solver == Solver::automatic) automatic.after_course_pass(components, pass.contacts);
  if (!events.enabled) return;
  for (const Contact& c : pass.contacts) events.touch(c.c, c.b, c.normal, c.jn, c.jt);
}

// The stable solver's velocity contacts, with their accumulated impulses
// (the bounce's included): those that exchanged one touched.
void World::record_solver_contacts() {
  if (!events.enabled) return;
  const auto rows = contact_solver.friction_rows();
  const auto constraints = contact_solver.constraints();
  const auto impulses = contact_solver.impulses();
  for (std::size_t i = 0; i < constraints.size(); ++i) {
    const ContactConstraint& ct = constraints[i];
    if (params.solver == Solver::automatic && (automatic.undone(ct.c) || automatic.undone(ct.b))) continue;
    const ContactImpulse& j = impulses[i];
    const double jn = j.lambda + j.lambda2 + (ct.resting ? 0.0 : ct.restitution * j.lambda);
    const double jt = rows.empty() ? 0.0 : rows[i].lambda + rows[i].lambda2;
    if (jn > 0.0) events.touch(ct.c, ct.b, axis_normal[ct.axis], jn, jt);
  }
}

void World::finish_events() {
  if (events.enabled && declares(SystemId::collision)) events.finish(components, colliding(), frame);
}

void World::end_frame() {
  ++times.steps;
  ++frame;
  finish_events();
  times.time(Stage::health, [&] { check_health(); });
}

void World::after_move() {
  if (!declares(SystemId::collision) || !solver_step()) return;
  contact_solver.solve_positions(components, colliding(), params.gravity, solver_settings(params, workers),
                                 broadphase, times);
}

void World::check_health() {
  health.check_bodies(components, frame, &workers);
  if (!health.finite() || health.deep || frame % Health::overlap_period != 0) return;
  if (!declares(SystemId::collision) || params.solver != Solver::course) return;
  // The deepest overlap of the last look, if still deeper than 1 px, is a
  // persistent one; then look for the deepest overlap now.
  if (health.suspect) {
    const auto [c, b] = *health.suspect;
    const double d = overlap_depth(components, c, b);
    if (d > Health::deep_overlap) {
      health.deep = DeepOverlap{c, b, d, frame};
      return;
    }
  }
  health.suspect.reset();
  double deepest = Health::deep_overlap;
  // The pairs the step's last course pass began with: a persistent overlap is
  // among them (it was there before the pass too), and walking them costs far
  // less than a new grid (which took ~1 % of a gas step every 60 frames).
  // A sensor's overlaps, filtered pairs and bodies passing through a one-way
  // platform are meant to overlap: only pairs the solvers see count.
  const bool rules = components.any_rules();
  const double h = params.substep();
  broadphase.each_course_candidate([&](Pair p) {  // (never two infinite masses)
    if (rules && !solvable(components, p.c, p.b, h)) return;
    const double d = overlap_depth(components, p.c, p.b);
    if (d > deepest) {
      deepest = d;
      health.suspect = std::pair{p.c, p.b};
    }
  });
}

BroadPhase::CoursePairs World::course_pairs() {
  return broadphase.course_pairs(components, colliding(), params.substep());
}

double World::kinetic_energy() const {
  double ke = 0.0;
  for (std::size_t e = 0; e < components.size(); ++e) {
    const double m = components.mass[e];
    if (!std::isfinite(m) || !alive(static_cast<EntityId>(e))) continue;
    ke += 0.5 * m * Vector::dot(components.velocity[e], components.velocity[e]);
  }
  return ke;
}

Vector World::momentum() const {
  Vector p{};
  for (std::size_t e = 0; e < components.size(); ++e) {
    const double m = components.mass[e];
    if (!std::isfinite(m) || !alive(static_cast<EntityId>(e))) continue;
    p = p + m * components.velocity[e];
  }
  return p;
}

std::size_t World::finite_bodies() const {
  std::size_t n = 0;
  for (std::size_t e = 0; e < components.size(); ++e)
    n += std::isfinite(components.mass[e]) && alive(static_cast<EntityId>(e)) ? 1 : 0;
  return n;
}

}  // namespace physics
