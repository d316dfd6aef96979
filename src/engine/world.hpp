// A world: the component arrays, the body lists of the stages a scene
// declared, and the parameters of the step. It replaces the OCaml code's
// global tables, so that tests and the testbed can hold several worlds at
// once. It holds no course code: the course's systems are views of its lists
// (course/system_defs.hpp).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "engine/components.hpp"
#include "engine/auto_mode.hpp"
#include "engine/ccd.hpp"
#include "engine/contact.hpp"
#include "engine/contact_solver.hpp"
#include "engine/health.hpp"
#include "engine/integrator.hpp"
#include "engine/limits.hpp"
#include "engine/pairs.hpp"
#include "engine/slide.hpp"
#include "engine/system_set.hpp"
#include "engine/tiles.hpp"
#include "engine/timing.hpp"
#include "engine/workers.hpp"

namespace physics {

inline constexpr double course_dt = 1000.0 / 60.0;  // ms, the sheet's dt

// How Collision resolves contacts. `course` is the sheet's one pass over the
// pairs and stays the default; `stable` is the iterated contact solver for
// resting contact and stacks; `automatic` ("auto") picks per substep what the
// scene needs, CCD included (engine/auto_mode.hpp; docs/numerics.md).
enum class Solver : std::uint8_t { course, stable, automatic };
// "course", "stable", "auto": the names of the scene key and the flag.
std::string_view name(Solver s);
std::optional<Solver> solver_from_name(std::string_view name);

// How a substep moves a body under a constant force. `course` is the sheet's
// symplectic Euler (Forces: v += a·h, then Move: x += h·v) and stays the
// default; `exact` moves it by v·h + a·h²/2, as the exact reference does
// between events (engine/integrator.hpp).
enum class Integrator : std::uint8_t { course, exact };
// "course" or "exact": the one spelling of the scene key and the flag.
std::string_view name(Integrator i);
std::optional<Integrator> integrator_from_name(std::string_view name);

struct Params {
  double dt = course_dt;    // ms per frame
  int substeps = 1;         // Forces/Move/Collision run this many times with dt/substeps
  Vector gravity{};         // px/ms², applied by Forces to finite masses
  bool ccd = false;         // swept collision (time of impact), no tunnelling
  Solver solver = Solver::course;
  int iterations = 8;       // velocity iterations of the stable solver
  Integrator integrator = Integrator::course;

  double substep() const { return dt / substeps; }  // ms: the h of one substep
};

// The engine's own guard, run by World's constructor: a World can be built
// without a scene (tests, tools, the benchmark), so it checks its parameters
// itself. It uses the limits of engine/limits.hpp, the ones the scene
// validator (scene/scene.cpp) reports with a key path, so a validated scene
// always passes; for a scene it is a cheap second look at four numbers, not
// a second validation of its bodies. Throws std::invalid_argument naming the
// bad parameter.
void validate(const Params& p);

// The contacts of the course pass (the Collision stage's one pass over the
// pairs, engine/stages.hpp, or the course's Collision::update), for the
// testbed's overlays, contact events, the auto mode and tests: how many
// pairs the last pass resolved, and their contacts if record_contacts.
struct PassContacts {
  bool record_contacts = false;
  std::vector<Contact> contacts;
  std::size_t contact_count = 0;
};

struct World {
  Components components;
  Params params;
  StageTimes times;
  std::int64_t frame = 0;
  // The engine beside the sheet's stages: the one broad phase every stage
  // takes its pairs from, and the state of the numerics options (Params::ccd,
  // Params::solver): impact counters and the stable solver's warm-start
  // impulses. The course mode uses the broad phase alone.
  BroadPhase broadphase;
  Ccd ccd;
  ContactSolver contact_solver;
  // The threads of the stable solver's loops and their broad phase
  // (WorldDef::threads, --threads): the same bits for any number.
  Workers workers;
  AutoMode automatic;  // Solver::automatic's choices and counts
  // What the checks after each step found (engine/health.hpp).
  Health health;
  // Contact events (engine/events.hpp), if enabled (enable_events).
  ContactEvents events;
  // The last course pass's contacts (the Collision stage's).
  PassContacts pass;
  // Tile layers (engine/tiles.hpp) and the proxies of their strips.
  TileSet tiles;

  explicit World(SystemSet set = {}, Params p = {});

  // The stages the world runs (the scene's "systems"), each with its bodies
  // in registration order, the order that fixes the pairs' and so the bits
  // of a run. A stage not declared has no list: nothing registers with it
  // and nothing runs it. The engine's stages and the course's systems
  // (course/system_defs.hpp, bound to these lists) read the same ones.
  bool declares(SystemId s) const { return stages_[index(s)].has_value(); }
  SystemSet declared() const;
  std::span<const EntityId> bodies(SystemId s) const;  // empty if not declared
  // The list itself, for registering (nullptr if not declared).
  std::vector<EntityId>* stage(SystemId s);
  const std::vector<EntityId>* stage(SystemId s) const;
  // Registers e with stage s, if the world declares it.
  void add(SystemId s, EntityId e);

  // A tile layer: a fixed body at `position` whose box is the grid's extent,
  // in no stage (its strips collide, through proxies, not its box). Throws
  // std::invalid_argument with check()'s line for a bad grid.
  EntityId add_tile_layer(Vector position, TileGrid grid);
  // The bodies the solvers see this substep: the Collision stage's, after
  // the proxies of the strips near them when there are tile layers.
  std::span<const EntityId> colliding() const {
    return tiles.empty() ? bodies(SystemId::collision) : std::span<const EntityId>(colliding_);
  }

  // The archive's `unregister`, from every stage: the body no longer
  // moves, collides or is drawn, its id is not reused (its slot stays in the
  // component arrays), and dumps and diagnostics leave it out.
  void destroy(EntityId e);
  // Proxies of tile strips are never alive: no list, dump or save shows them.
  bool alive(EntityId e) const { return e >= destroyed_.size() || destroyed_[e] == 0; }

  // The engine's stages around Forces and Move in a substep of h ms
  // (run_frame calls them, engine/step.hpp; they do nothing in the course
  // mode): before Forces, the exact integrator's look at the velocities;
  // before Move, the stable solver's velocities, CCD's impacts and the exact
  // integrator's shift; after it, the stable solver's position projection,
  // which replaces the course's Collision pass.
  void before_forces();
  void before_move(double h);
  void after_move();
  // Whether this substep's contacts are the stable solver's (after_move),
  // not the course pass's: with Solver::stable, and with Solver::automatic
  // when it chose the solver.
  // Whether Move's motion is made exact (engine/integrator.hpp).
  bool exact_motion() const { return params.integrator == Integrator::exact; }
  bool solver_step() const {
    return params.solver == Solver::stable || (params.solver == Solver::automatic && automatic.solver_path());
  }
  // The checks after a step (run_frame runs them, timed as Stage::health):
  // non-finite values, escapes, persistent deep overlaps (course solver).
  void check_health();
  // Contact events (nothing unless enable_events() was called): the course
  // pass's contacts of a substep (run_frame calls it after the pass; the
  // stable solver's and CCD's are recorded in before_move), and the events
  // of the step, after it.
  void enable_events();
  void record_contacts();
  void finish_events();
  // The end of run_frame's frame: the frame counted, then, not part of the
  // sheet, its contact events and the health checks of the state it left.
  void end_frame();

  // The pairs of the Collision stage's bodies, for its pass.
  BroadPhase::CoursePairs course_pairs();

  // Diagnostics over finite masses (fixed bodies carry no kinetic energy and
  // an infinite momentum that means nothing).
  double kinetic_energy() const;
  Vector momentum() const;
  std::size_t finite_bodies() const;

 private:
  static std::size_t index(SystemId s) { return static_cast<std::size_t>(s); }
  void record_solver_contacts();  // before_move's, after the stable solver's velocities
  void auto_before_move(std::span<const EntityId> bodies, double h);
  // The stable solver's velocities (and their contacts' events).
  void solve_velocities(std::span<const EntityId> bodies, double h, SolverSettings s);
  // CCD over the bodies (a selection's only, if given); whether it ran out of budget.
  bool sweep(std::span<const EntityId> bodies, double h, const CcdSelection* selection = nullptr);
  void gather_tiles(double h);
  std::vector<EntityId> colliding_, proxies_, created_;  // gather_tiles' lists
  ExactIntegrator exact_;  // Params::integrator == Integrator::exact
  SlideIntegrator slide_;  // friction's motion under the stable solver (engine/slide.hpp)
  // (It corrects Move's result: without Move nothing moves, and nothing is shifted.)
  bool slides() const {
    return params.solver != Solver::course && declares(SystemId::collision) && declares(SystemId::move);
  }
  std::array<std::optional<std::vector<EntityId>>, all_systems.size()> stages_;  // by SystemId
  std::vector<std::uint8_t> destroyed_;  // by id (1 destroyed, 2 a proxy); shorter than the arrays until either
};

}  // namespace physics
