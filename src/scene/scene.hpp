// A scene as data: the world's size and parameters, the systems it declares,
// whether it has the walls of question 1, and its blocks, single or made by
// generators (a grid of equal blocks, or seeded random blocks). Built-in
// scenes (builtin_scenes.hpp) and scene files (scene_json.hpp) both produce a
// SceneSpec; `make_world` turns one into a World, its bodies made through the
// public API. No SDL here (libphysics_scene.a): headless runs, benchmarks and
// fuzzers use it.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "engine/limits.hpp"
#include "engine/tiles.hpp"
#include "physics/physics.hpp"
#include "course/game.hpp"
#include "course/utils/random.hpp"

namespace physics {

// The course's screen and walls (question 1).
inline constexpr int default_width = Game::width;  // px
inline constexpr int default_height = Game::height;
inline constexpr int wall_thickness = Game::wall_thickness;
inline constexpr Color default_block_color{128, 128, 128, 255};

// The limits (max_world_size, max_block_size, max_bodies, ...) are in
// engine/limits.hpp: one set for the validator and the engine.

// Every error in a scene (file or built-in): the message names the source,
// the key path or line, and the problem, e.g.
//   scenes/x.json: blocks[3].mass: must be > 0 or "inf" (got -1)
struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A value that is either fixed or drawn uniformly from [lo, hi) by a random
// generator. Only drawn values consume random numbers, so a scene's draws
// are fixed by which properties are ranges.
struct RealSpec {
  double lo = 0.0, hi = 0.0;
  bool drawn = false;
  static RealSpec fixed(double v) { return {v, v, false}; }
  static RealSpec uniform(double lo, double hi) { return {lo, hi, true}; }
  double get(Random& rng) const { return drawn ? rng.uniform(lo, hi) : lo; }
  friend bool operator==(const RealSpec&, const RealSpec&) = default;
};
// Same for integers, drawn uniformly from [lo, hi] (both included).
struct IntSpec {
  int lo = 0, hi = 0;
  bool drawn = false;
  static IntSpec fixed(int v) { return {v, v, false}; }
  static IntSpec uniform(int lo, int hi) { return {lo, hi, true}; }
  int get(Random& rng) const { return drawn ? rng.uniform_int(lo, hi) : lo; }
  friend bool operator==(const IntSpec&, const IntSpec&) = default;
};
struct VecSpec {
  RealSpec x, y;
  static VecSpec fixed(Vector v) { return {RealSpec::fixed(v.x), RealSpec::fixed(v.y)}; }
  // x is drawn before y (braced initialisation evaluates in order).
  Vector get(Random& rng) const { return Vector{x.get(rng), y.get(rng)}; }
  friend bool operator==(const VecSpec&, const VecSpec&) = default;
};

// A block's contact properties beyond the sheet (docs/game-physics.md):
// scene keys "friction", "category", "mask", "sensor", "one_way".
struct ContactSpec {
  std::optional<double> friction;  // >= 0; unset: the world's
  ContactRules rules;
  friend bool operator==(const ContactSpec&, const ContactSpec&) = default;
};

// One block, as in Block::make, plus its initial motion.
//   velocity  px/ms at start
//   force     initial sum_forces (the sheet's Q5 "force instead of velocity")
//   impulse   px·mass/ms: changes the velocity by impulse/mass on frame 1
//             (given to Forces as the force impulse/dt)
struct BlockSpec {
  Vector pos{};
  int width = 0, height = 0;
  double mass = 0.0;  // > 0, or infinity
  Vector velocity{}, force{}, impulse{};
  Color color = default_block_color;
  std::optional<double> restitution;  // unset: the world's
  ContactSpec contact;
  // For the games (src/games/), ignored by the physics: what the block is in
  // a game ("player", "coin", "goal", "platform", "target", "crate", ...; at
  // most 32 characters of a-z, 0-9, '_' and '-'), and the normal impulse
  // that breaks it (a target's "strength", > 0; unset: unbreakable), and how
  // far a moving platform goes before it turns back ("travel", px).
  std::string tag;
  std::optional<double> strength;
  std::optional<double> travel;  // a moving platform: px from its start before it turns back (> 0)
  // Where a moving platform's travel starts and its unit direction (unset:
  // pos, and the velocity's direction). A platform saved on its way (--save)
  // keeps them, so that it turns back where it did before.
  std::optional<Vector> travel_from, travel_dir;
  friend bool operator==(const BlockSpec&, const BlockSpec&) = default;
};

// columns × rows copies of `first`, the body in column c and row r at
// first.pos + (c·step.x, r·step.y). Row by row, left to right.
struct GridSpec {
  BlockSpec first;
  int columns = 1, rows = 1;
  Vector step{};
  friend bool operator==(const GridSpec&, const GridSpec&) = default;
};

// `count` blocks whose properties may be drawn from ranges, from a
// SplitMix64 generator seeded with `seed`. For each body, in this order:
// size (side, or width then height), mass, velocity, force, impulse,
// restitution, colour (r, g, b), position (x, y). Positions come from either
//   cells: body i in the cell (i % columns, i / columns) of a grid at
//          `origin` with cells of `step`, offset by a draw in [0, jitter)
//   area:  anywhere the body fits inside the rectangle at `origin` of `extent`
struct RandomSpec {
  std::int64_t count = 0;
  std::uint64_t seed = 42;
  std::optional<IntSpec> side;  // set: square bodies, one draw
  IntSpec width, height;
  RealSpec mass;
  VecSpec velocity, force, impulse;
  std::optional<RealSpec> restitution;  // unset: the world's
  std::optional<Color> color;           // unset: random, each channel in [40, 220]
  bool use_cells = true;
  Vector origin{};
  int columns = 1;
  Vector step{}, jitter{};  // cells
  Vector extent{};          // area
  ContactSpec contact;      // the same for every body (never drawn)
  friend bool operator==(const RandomSpec&, const RandomSpec&) = default;
};

using BlockEntry = std::variant<BlockSpec, GridSpec, RandomSpec>;

// What a saved world (--save) adds to its scene: the frame it was saved
// after and the state the next step reads beyond the bodies (the stable
// solver's warm-start impulses, by body index in the file).
struct SavedState {
  std::int64_t frame = 0;
  std::vector<WarmImpulse> warm_start;
  std::optional<AutoState> automatic;  // with solver "auto": its choice's state (key "auto")
  friend bool operator==(const SavedState&, const SavedState&) = default;
};

// A scene that is a game's level (scene key "game", src/games/): which game,
// and its settings. kind "" : no game (the testbed as usual).
struct GameSpec {
  std::string kind;   // "platformer" or "targets"
  int shots = 5;      // targets: launches allowed, in [1, 99]
  std::string next;   // the next level's scene file, relative to this one's folder; "" for the last
  std::string next_path;  // the same, as a path from here (read_scene_file)
  friend bool operator==(const GameSpec&, const GameSpec&) = default;
};

// A tile layer (scene key "tiles"; engine/tiles.hpp): its grid drawn as rows
// of characters, '#' solid, '=' one-way up, '.' empty, top row first.
struct TileSpec {
  Vector pos{};  // px, the grid's top-left corner
  int cell = 16;  // px
  std::vector<std::string> rows;
  std::optional<double> restitution, friction;  // none: the world's
  Color color{128, 128, 128, 255};
  friend bool operator==(const TileSpec&, const TileSpec&) = default;
};
// The kind of cell character ch stands for, or none.
std::optional<Tile> tile_of_char(char ch);
// The engine's grid of a checked spec.
TileGrid tile_grid(const TileSpec& t);

// How the window and the offscreen pictures draw the blocks (scene key
// "style", flag --style; app/style.hpp): plain is the course's Draw system,
// speed colours each movable block by its speed, sprite draws a shape in
// each box by its tag (the collisions still use the box).
enum class Style { plain, speed, sprite };
std::string_view name(Style s);
std::optional<Style> style_from_name(std::string_view name);

struct SceneSpec {
  std::string name;
  std::string description;
  int width = default_width, height = default_height;
  Params params;
  double restitution = 1.0;  // walls, and blocks that give none
  double friction = 0.0;     // the same, for friction
  bool walls = true;
  SystemSet systems;
  std::vector<BlockEntry> blocks;
  std::vector<TileSpec> tiles;      // scene key "tiles": made after the blocks
  std::optional<SavedState> state;  // a saved world's (scene key "state")
  GameSpec game;                    // scene key "game"
  Style style = Style::plain;       // scene key "style"
};


// Command-line values; each set one replaces the scene's.
struct Overrides {
  // World keys, by name with the flag's text ({"gravity", "0,0.001"}), read
  // through the key table's rows (read_world_flag); a restitution or a
  // friction also replaces every block's own.
  std::vector<std::pair<std::string, std::string>> world;
  std::optional<std::uint64_t> seed;  // random generator k gets seed + k
  std::optional<Style> style;
};
void apply(SceneSpec& s, const Overrides& o);

// The world keys that are command-line flags (--dt, --gravity...): the rows of
// the key table (keys.cpp) with a `flag`, in its order.
struct WorldFlag {
  std::string name;   // the key's, and the flag's
  std::string value;  // the value's syntax, from the row's type: N, X, X,Y, on|off, course|stable|auto
  std::string help;   // from the row's doc, range, default and flag note
  bool boolean;       // the flag alone means on
};
const std::vector<WorldFlag>& world_flags();
// A flag's text as world key `name` of s, through its row's read and check.
// Throws SceneError("--name: problem (got 'text')").
void read_world_flag(SceneSpec& s, std::string_view name, const std::string& text);

// One concrete body of a scene, after generators are expanded. `entry` and
// `index` say where it came from, for error messages.
struct Body {
  Vector pos{};
  int width = 0, height = 0;
  double mass = 0.0;
  Vector velocity{}, force{}, impulse{};
  Color color{};
  double restitution = 1.0;
  double friction = 0.0;
  ContactRules rules;
  std::size_t entry = 0;
  std::int64_t index = 0;
};

// A body's part in a game: its block's tag and strength (walls: tag "wall").
struct BlockRole {
  std::string tag;
  double strength = infinity;  // normal impulse that breaks it
  double travel = infinity;    // px a moving platform goes from its start before turning back
  Vector travel_from{}, travel_dir{};  // where it starts, and its unit direction (BlockSpec's, resolved)
  friend bool operator==(const BlockRole&, const BlockRole&) = default;
};
// The roles of a world made from `s` and `bodies` (expand), by entity id.
std::vector<BlockRole> roles_by_entity(const SceneSpec& s, const std::vector<Body>& bodies);

// Number of bodies the entries make (walls excluded), without expanding them.
std::int64_t body_count(const SceneSpec& s);

// Validation: the one place that checks a scene. `validate` checks the spec
// (parameters, sizes, masses, restitutions, motions, counts, generators),
// with the limits of engine/limits.hpp; `expand` runs it, makes the bodies
// and checks that every one lies inside the world and overlaps no wall. A
// load validates once: the command line expands the scene (after its
// overrides) and builds the world from those bodies; make_world(spec, ...)
// expands once too. The scene file reader only checks what it must to
// convert JSON (types, keys, integers that fit). Errors are SceneError naming
// `source` and the key path (blocks[3], blocks[2] (grid body 17), world.dt).
void validate(const SceneSpec& s, const std::string& source);

// The scene's blocks in creation order, validated (see above).
std::vector<Body> expand(const SceneSpec& s, const std::string& source);

// Two blocks that overlap at the start (touching is no overlap), or none:
// the first pair a sweep along x finds, indices into `bodies`, lower first.
// Legitimate (the solver pushes them apart), so only warned about.
// O(n log n): a sweep over x with the y-intervals of the open boxes.
std::optional<std::pair<std::size_t, std::size_t>> first_overlap(const std::vector<Body>& bodies);
// "warning: SOURCE: blocks[2] and blocks[5] overlap at the start", or "".
std::string overlap_warning(const SceneSpec& s, const std::vector<Body>& bodies, const std::string& source);

// How many times validate() has run in this process (tests check that a load
// validates once).
std::int64_t validation_count();

// The four walls of a scene with `walls`: the sheet's (question 1), as the
// public API's defs, with the world's restitution and friction.
std::array<BodyDef, Game::wall_count> wall_defs(const SceneSpec& s);

// Adds the walls (if any) and `bodies` (from expand(s, ...)) to `w` through
// the public API (create_body on a view of w), using w.params.dt to turn
// impulses into initial forces. expand's checks are the API's and more, so
// create_body throws nothing for its bodies.
void populate(World& w, const SceneSpec& s, const std::vector<Body>& bodies);
// Same, expanding (so validating) the scene first.
void populate(World& w, const SceneSpec& s, const std::string& source = "scene");

// Health's watch (engine/health.hpp) on the bodies of w from `first` on: an
// escape is a body whose centre leaves the inside of the scene's walls (or
// its bounds).
void watch(World& w, const SceneSpec& s, EntityId first);

// A world with the scene's parameters and systems (Draw only if `with_draw`:
// a headless run has nothing to draw), and no body yet.
World empty_world(const SceneSpec& s, bool with_draw);
// The same, holding the walls and `bodies` (from expand): populate.
World make_world(const SceneSpec& s, const std::vector<Body>& bodies, bool with_draw);
// Same, expanding (so validating) the scene once. Throws SceneError.
World make_world(const SceneSpec& s, bool with_draw, const std::string& source = "scene");
// What builds a scene's world from its bodies: make_world, or the course's
// functions for the sheet's scenes (app/course_world.hpp, --course).
using WorldMaker = std::function<World(const SceneSpec& s, const std::vector<Body>& bodies, bool with_draw)>;
// make_world (the overload above) as a WorldMaker.
inline World make_scene_world(const SceneSpec& s, const std::vector<Body>& bodies, bool with_draw) {
  return make_world(s, bodies, with_draw);
}

}  // namespace physics
