// `make bench`: the same scenes run by our engine, Box2D 2.4.1 and Chipmunk 7
// from Debian, and (make bench PEERS=DIR) Box2D v3.2 and a release Chipmunk
// built from source.
//
// Every engine receives the scene in one neutral description: metres,
// seconds, y up, bodies given by their centre and half-extents, block side 1 m
// (Box2D is tuned for bodies of 0.1-10 m; Chipmunk has no unit). Each adapter
// converts to its engine's units and back, so the harness measures quality
// (escapes, overlap, energy) the same way for all of them.
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

// A tile map, its top-left corner at (0, height) (y up): columns x rows
// cells of `cell` m, row by row from the top, one byte a cell: 0 empty, 1 solid.
struct TileMap {
  double cell = 1.0;
  int columns = 0, rows = 0;
  std::vector<std::uint8_t> cells;
  bool solid(int c, int r) const { return cells[static_cast<std::size_t>(r) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(c)] != 0; }
};

struct Scene {
  std::string name;          // gas, rain, pyramid, pyramid_friction, many_pyramids, tiles_SIDE
  double width = 0;          // container interior [0, width] x [0, height], m
  double height = 0;
  double gravity = 0;        // m/s², pointing down (-y)
  double restitution = 1.0;  // every body, every engine
  double friction = 0.0;     // every body, every engine (a pair's: sqrt(mu_a mu_b), so this value)
  double dt = 1.0 / 60.0;    // s per step
  bool resting = false;      // bodies come to rest in contact (ours: stable solver)
  double time_scale = 1.0;   // steps and warm-up are the harness's times this (rain_phase)
  int steps = 0, warmup = 0;  // if steps > 0: this scene's own (times time_scale), not the harness's (rain_falling)
  std::vector<Body> bodies;  // fixed bodies (walls, shelves) first
  std::vector<std::size_t> tops;  // pyramids' top blocks (indices in bodies): the harness reports how far they move
  TileMap map;               // tiles_SIDE: ours makes it a tile layer, the peers its map_boxes (not in bodies)
  std::size_t dynamic_count() const;
};

// gas: N unit squares at area fraction 0.10 in a square box, random
// velocities (seed 42), no gravity, e = 1.
Scene make_gas(std::size_t n, std::uint64_t seed = 42);
// rain: N unit squares on a grid (area fraction 0.25 of the container) fall
// under gravity 10 m/s² into it, e = 0.5.
Scene make_rain(std::size_t n);
// rain_settled: the rain's N squares at rest where it lands: rows wall to
// wall from the floor up (2k squares a row fill its 2k m container exactly),
// each square on the one below, the last row's remainder centred; e = 0.5.
// Every engine loads the same pile, so the settled phase is compared without
// running each to rest (a frictionless pile of 100 000 keeps flowing for
// thousands of steps).
Scene make_rain_settled(std::size_t n);
// pyramid: Box2D's large_pyramid, a base of 100 squares, 5050 in all,
// resting on the floor; fixed rotation, e = 0.
Scene make_pyramid(std::size_t base = 100);
// pyramid_friction: the same with friction 0.6 on every body and the walls.
Scene make_pyramid_friction(std::size_t base = 100);
// many_pyramids: Box2D v3's benchmark of that name (its shared/benchmarks.c,
// CreateManyPyramids): rows x columns pyramids of base `base` on shelves,
// 400 pyramids of 55 blocks, 22 000 in all; fixed rotation, e = 0.
Scene make_many_pyramids(std::size_t rows = 20, std::size_t columns = 20, std::size_t base = 10);
// tiles_SIDE: a map of side x side cells of 1 m (side a multiple of 20),
// rooms of 20 x 20 cells walled by solid cells (18 x 18 inside, a ledge in
// each), and 10 000 unit squares falling under 10 m/s², e = 0.5, into the
// 100 rooms of the top-left corner: the same bodies in the same rooms on
// every map, which only grows around them.
Scene make_tiles(int side);
// The map's solid cells as fixed boxes, for the engines without tile layers:
// each row's runs of solid cells, a run continued by the same run on the rows
// below it as one box (what a game on those engines builds).
std::vector<Body> map_boxes(const Scene& s);
// Bytes of heap in use (glibc's mallinfo2): an adapter's map is measured as
// the growth across building it.
std::size_t heap_bytes();

// One engine running one scene. Bodies keep the scene's order.
class Engine {
 public:
  virtual ~Engine() = default;
  virtual void step() = 0;
  // Centre and velocity of every body, in the scene's units and order
  // (fixed ones included). out is resized to the scene's body count.
  virtual void read(std::vector<Body>& out) const = 0;
  // The engine's own time a stage, step by step (`--stages`): the harness
  // calls keep_stage_times() after each step, outside the step's timing, and
  // stages() has the stages' names and each step's ms in each. Ours alone
  // (physics::profile); the peers keep none.
  struct StageSteps {
    std::vector<std::string> names;
    std::vector<std::vector<double>> steps;  // by step, by stage
  };
  virtual void keep_stage_times() {}
  virtual const StageSteps* stages() const { return nullptr; }
  // The heap the scene's map took when the adapter built it (ours: the tile
  // layer; the peers: its static boxes), MB (2^20 bytes); 0 without a map.
  double map_mb = 0;
};

// Each adapter sets every body's mass to 1 (fixed: static), the scene's friction (0 but in pyramid_friction),
// fixed rotation, sleeping off, and keeps the engine's default iterations.
// Ours runs the course's solver on scenes without resting contact and the
// stable solver on the others, unless `course` forces the course's solver.
// `threads`: WorldDef::threads (ours-2t: 2).
std::unique_ptr<Engine> make_ours(const Scene& s, bool course = false, int threads = 1);
std::unique_ptr<Engine> make_box2d(const Scene& s);     // Debian's 2.4.1 (build/bench)
std::unique_ptr<Engine> make_box2d3(const Scene& s, int workers = 1);  // v3.2 from source (build/bench-peers only)
// Chipmunk 7.0.3: Debian's build in build/bench, the release build in
// build/bench-peers (the same adapter compiled against each).
std::unique_ptr<Engine> make_chipmunk(const Scene& s);

// The engines linked into this binary, by the names the harness uses
// (bench/engines.cpp in build/bench, bench/peers/engines.cpp in
// build/bench-peers): the two cannot share a binary (see the Makefile).
const std::vector<std::string>& engine_names();
// nullptr when `name` is not linked into this binary.
std::unique_ptr<Engine> make_engine(const std::string& name, const Scene& s);

}  // namespace bench
