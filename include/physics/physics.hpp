// The engine's public API: worlds of axis-aligned boxes, stepped at a fixed dt.
// Guide: docs/api.md. Units: px, ms, px/ms, px/ms^2; y grows downwards; a
// body's position is its box's top-left corner; sizes are whole pixels.
//
// Worlds and bodies are named by ids ({index, generation}, as Box2D v3's):
// destroying a world or a body makes its ids stale. Every function given a
// stale, null or foreign id, or a bad value (NaN, a size of 0, a negative
// mass...), throws physics::Error naming the problem; nothing is changed
// then. `is_valid` tells without throwing. Not thread-safe (the table of
// worlds is shared): call the API from one thread, or lock around every call.
//
// Links against libphysics.a (pkg-config physics, or CMake find_package
// (physics) with target physics::physics). Includes only standard headers.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "physics/math.hpp"

static_assert(__cplusplus >= 202002L, "physics/physics.hpp needs C++20 (-std=c++20)");

namespace physics {

// ---- errors and ids ----

// Thrown on a stale or foreign id and on a bad value; what() is one line.
class Error : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// A world: index1 is its slot + 1 (0 is the null id), generation counts the
// slot's reuses so that a destroyed world's id never names a later one.
struct WorldId {
  std::uint16_t index1 = 0;
  std::uint16_t generation = 0;
  friend bool operator==(WorldId, WorldId) = default;
};

// A body of one world: its slot in the world + 1, and its generation.
struct BodyId {
  std::uint32_t index1 = 0;
  WorldId world;
  std::uint16_t generation = 0;
  friend bool operator==(BodyId, BodyId) = default;
};

inline constexpr WorldId null_world{};
inline constexpr BodyId null_body{};

// ---- definitions ----

// How contacts are resolved: the course's one pass over the pairs (the
// sheet's), the iterated solver for stacks and resting contact, or auto
// (what each substep needs, swept collision included). docs/numerics.md.
enum class SolverKind : std::uint8_t { course, stable, automatic };
// Motion in a substep: the course's symplectic Euler, or exact constant-force motion.
enum class IntegratorKind : std::uint8_t { course, exact };

struct WorldDef {
  double dt = 1000.0 / 60.0;    // ms a step, in [1e-6, 1e6]
  int substeps = 1;             // each step runs forces, move, collision this many times, in [1, 1000]
  Vec2 gravity{};               // px/ms^2, applied to finite masses
  SolverKind solver = SolverKind::course;
  int iterations = 8;           // velocity iterations of the stable solver, in [1, 1000]
  bool ccd = false;             // swept collision: no tunnelling through thin bodies
  IntegratorKind integrator = IntegratorKind::course;
  bool forces = true;           // the systems a world runs: without forces, no gravity nor force;
  bool move = true;             // without move, nothing moves;
  bool collision = true;        // without collision, bodies pass through each other
  bool contact_events = false;  // record begin/end touch events (contact_events())
  // Threads of the stable and auto solvers' loops over contacts and bodies and
  // of their broad phase, and of Forces and Move in every solver, in [1, 64]
  // (1 in a build without threads): the same results, bit for bit, for any
  // number (docs/performance.md).
  int threads = 1;
  // Bodies whose centre leaves these bounds count as escaped (health()); no bounds if empty.
  std::optional<Aabb> bounds;
};
WorldDef default_world_def();  // the course's: dt 1000/60 ms, one substep, no gravity, the course solver

// The face of a one-way body that stops others (none: every face stops them).
enum class OneWay : std::uint8_t { none, up, down, left, right };

// Which pairs meet: a and b interact only if (a.category & b.mask) and (b.category & a.mask).
struct Filter {
  std::uint32_t category = 1;
  std::uint32_t mask = 0xFFFFFFFFu;
  friend bool operator==(Filter, Filter) = default;
};

inline constexpr double fixed_mass = std::numeric_limits<double>::infinity();  // a body nothing moves

struct BodyDef {
  Vec2 position{};            // px, top-left corner
  Vec2 size{10.0, 10.0};      // px, whole numbers in [1, 1048576]
  double mass = 1.0;          // in [1e-300, 1e150], or fixed_mass
  Vec2 velocity{};            // px/ms
  Vec2 force{};               // applied on the first step only, as a scene's "force"
  double restitution = 1.0;   // in [0, 1]; a pair uses the smaller
  double friction = 0.0;      // in [0, 1000]; a pair uses sqrt(mu_a mu_b)
  Filter filter{};
  bool sensor = false;        // reports contact events, is never pushed nor pushes
  OneWay one_way = OneWay::none;
  Color color{255, 0, 0, 255};  // for drawing only
  std::uint64_t user_data = 0;  // yours: the engine only stores it
};
BodyDef default_body_def();  // a 10x10 red body of mass 1 at (0, 0), at rest

// ---- worlds ----

WorldId create_world(const WorldDef& def = default_world_def());  // throws Error on a bad def
void destroy_world(WorldId world);                                // its bodies' ids go stale too
bool is_valid(WorldId world);                                     // false for null, stale, never made
// One step of def.dt ms: forces, move, collision for each substep, in the course's order.
void step(WorldId world);
std::int64_t frame(WorldId world);  // steps taken since creation (or since the restored state's)
std::size_t body_count(WorldId world);      // the live bodies
std::vector<BodyId> bodies(WorldId world);  // the live bodies, in creation order
WorldDef world_def(WorldId world);          // the def as the world runs it
void set_gravity(WorldId world, Vec2 gravity);  // px/ms^2, from the next step on
double kinetic_energy(WorldId world);  // sum of m v^2 / 2 over finite masses
Vec2 momentum(WorldId world);          // sum of m v over finite masses

// ---- bodies ----

BodyId create_body(WorldId world, const BodyDef& def = default_body_def());  // throws Error on a bad def
void destroy_body(BodyId body);  // it no longer moves, collides nor is listed; its id goes stale
bool is_valid(BodyId body);       // false for null, stale (destroyed), never made
WorldId world_of(BodyId body);    // the world it belongs to

Vec2 position(BodyId body);                     // px, top-left corner
void set_position(BodyId body, Vec2 position);  // finite; a teleport: no velocity change
Vec2 size(BodyId body);                 // px, whole numbers
void set_size(BodyId body, Vec2 size);  // whole pixels in [1, 1048576]
Aabb bounds(BodyId body);  // position to position + size
Vec2 velocity(BodyId body);                     // px/ms
void set_velocity(BodyId body, Vec2 velocity);  // finite, within 1e6 per axis
Vec2 force(BodyId body);                   // the pending sum of forces for the next step
void apply_force(BodyId body, Vec2 force);  // added to it; the next step turns it into velocity, then clears it
void apply_impulse(BodyId body, Vec2 impulse);  // velocity += impulse / mass now; nothing for fixed bodies
double mass(BodyId body);                 // fixed_mass for a fixed body
void set_mass(BodyId body, double mass);  // in [1e-300, 1e150] or fixed_mass
double restitution(BodyId body);                        // in [0, 1]
void set_restitution(BodyId body, double restitution);  // in [0, 1]; a pair uses the smaller
double friction(BodyId body);                     // Coulomb's coefficient
void set_friction(BodyId body, double friction);  // in [0, 1000]; a pair uses sqrt(mu_a mu_b)
Filter filter(BodyId body);                   // category and mask
void set_filter(BodyId body, Filter filter);  // from the next step on
bool is_sensor(BodyId body);                // reports overlaps, never pushes
void set_sensor(BodyId body, bool sensor);  // from the next step on
OneWay one_way(BodyId body);                 // the face that stops others
void set_one_way(BodyId body, OneWay face);  // none: every face
Color color(BodyId body);                 // for drawing
void set_color(BodyId body, Color color);  // the engine never reads it
std::uint64_t user_data(BodyId body);                 // yours
void set_user_data(BodyId body, std::uint64_t data);  // the engine only stores it

// ---- tile layers (docs/api.md, "Tile layers") ----

// A cell's kind: empty, solid, or one-way up (stops bodies coming down onto its top only).
// The values 3 to 255 are reserved for more kinds.
enum class TileKind : std::uint8_t { empty = 0, solid = 1, one_way_up = 2 };

// A fixed body holding a grid of columns x rows cells of cell_size px. Faces
// between two solid cells never collide: a box slides along a floor or a
// wall of tiles as along one body. The body's size is the grid's extent.
struct TileLayerDef {
  Vec2 position{};                  // px, the grid's top-left corner
  int cell_size = 16;               // px, whole, in [1, 1048576]; the extent at most 1048576 px a side
  int columns = 0, rows = 0;        // at least 1 each
  std::vector<TileKind> cells;      // columns x rows, row by row, top row first
  double restitution = 1.0;         // in [0, 1]; a pair uses the smaller
  double friction = 0.0;            // in [0, 1000]; a pair uses sqrt(mu_a mu_b)
  Filter filter{};
  Color color{128, 128, 128, 255};  // for drawing only
  std::uint64_t user_data = 0;
};
BodyId create_tile_layer(WorldId world, const TileLayerDef& def);  // throws Error on a bad def
bool is_tile_layer(BodyId body);
// The kind of cell (column, row) of a layer: empty outside the grid. Throws
// Error if the body is not a tile layer.
TileKind tile_at(BodyId layer, int column, int row);

// ---- queries (interiors are open: touching is not overlapping) ----

struct RayResult {
  BodyId body;     // the first body the ray enters
  Vec2 point;      // where, on its boundary
  Vec2 normal;     // unit outward normal of the face entered
  double fraction; // in [0, 1] of max_distance
  int column = -1, row = -1;  // the cell entered, when body is a tile layer
};
// From origin along direction (need not be unit) for max_distance px; bodies it starts in are ignored.
std::optional<RayResult> ray_cast(WorldId world, Vec2 origin, Vec2 direction, double max_distance);
std::vector<BodyId> query_box(WorldId world, Aabb box);  // bodies whose interior meets box
std::vector<BodyId> query_point(WorldId world, Vec2 point);  // bodies whose interior holds point
// Tile layers: a ray enters a solid cell by any face, a one-way cell by its top face going down (ignoring the
// solid it starts in); a box or point query lists a layer when it meets a non-empty cell. The cells it meets:
struct TileCellResult {
  BodyId layer;
  int column, row;
  TileKind kind;
};
std::vector<TileCellResult> query_tiles(WorldId world, Aabb box);  // non-empty cells whose interior meets box

// ---- contact events (WorldDef::contact_events) ----

struct TouchEvent {
  bool begin;          // true: started touching in the step; false: stopped
  BodyId a, b;         // a created before b
  Vec2 normal;         // unit, pushes a away from b
  double depth;        // px, the overlap at the end of the step
  double normal_impulse, tangent_impulse;  // exchanged during the step
  std::int64_t frame;  // the step after which it happened
};
std::vector<TouchEvent> contact_events(WorldId world);  // the last step's, in pair order
void enable_contact_events(WorldId world);  // from the next step on, as WorldDef::contact_events

struct Touching {
  BodyId a, b;         // a created before b
  Vec2 normal;         // unit, pushes a away from b
  double depth;        // px, the overlap at the end of the step
  double normal_impulse, tangent_impulse;  // exchanged during the step (0 for a pair merely resting in range)
};
std::vector<Touching> touching(WorldId world);  // the pairs touching after the last step, in pair order

// ---- state ----

// A copy of a world's whole state (bodies, frame, solver warm start): restoring
// it and stepping gives, bit for bit, what stepping from the copy's moment gave.
class WorldState {
 public:
  WorldState();
  ~WorldState();
  WorldState(const WorldState&);
  WorldState& operator=(const WorldState&);
  WorldState(WorldState&&) noexcept;
  WorldState& operator=(WorldState&&) noexcept;
  struct Data;  // the engine's; opaque here

 private:
  std::unique_ptr<Data> data_;
  friend WorldState save_state(WorldId world);
  friend void restore_state(WorldId world, const WorldState& state);
};
WorldState save_state(WorldId world);  // a copy of everything the next steps read
// The world becomes the saved one: its bodies, frame and def; ids of bodies alive at the save are valid
// again, ids of bodies made since are stale. Throws Error if the state is empty or another world's.
void restore_state(WorldId world, const WorldState& state);

// ---- profile and health ----

struct StageTime {
  std::string_view stage;  // "forces", "move", "collision", "pairs", "ccd", ... (docs/api.md)
  double ms_per_step;
};
std::vector<StageTime> profile(WorldId world);  // wall time per stage, averaged over the steps taken

struct HealthReport {
  bool finite = true;                 // false once a position or velocity is NaN or infinite
  std::optional<BodyId> non_finite;   // the first such body; do not step the world again
  std::int64_t escaped = 0;           // bodies whose centre left WorldDef::bounds (each once)
  std::optional<BodyId> first_escape;
  double deepest_overlap = 0.0;       // px, a persistent deep overlap seen (course solver), else 0
};
HealthReport health(WorldId world);  // what the checks after each step found

}  // namespace physics
