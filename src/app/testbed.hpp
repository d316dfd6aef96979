// The testbed: what the keys and the mouse do to the world in window mode,
// as pure logic (events in, world changes out). The window (window.cpp)
// only turns SDL events into InputEvents and draws what view() returns, so
// everything here is tested without a window (tests/test_testbed.cpp).
//
//   Space        pause / resume            N or →   one step (and pause)
//   R            reset the scene           1-9      scene 1-8, 9: a --scene file; Tab: next
//   left click   spawn a block             left drag  fling it opposite to the drag (slingshot)
//   right drag   a ray from the press point to the mouse: the first body it enters, point and normal
//   A  AABBs     V  velocity vectors       C  contact normals and penetrations
//   I  HUD on/off    T  stage times on the HUD   S  slow motion (x1/4)   H  this key list   Esc/Q  quit
//   wheel  zoom about the cursor   middle drag or Shift+drag  pan   F  camera back to fit (or follow the player)
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <map>
#include <vector>

#include "input/keys.hpp"
#include "scene/scene.hpp"
#include "engine/query.hpp"
#include "api/view.hpp"
#include "app/camera.hpp"
#include "games/level.hpp"
#include "engine/world.hpp"

namespace physics {

// What the window reports each frame, without SDL types.
struct InputEvent {
  // key: a key pressed (or repeated while held); key_up: released (the games
  // hold keys down; the testbed's own keys act on the press).
  // wheel: the mouse wheel at (x, y), `key` notches (up > 0); the camera's
  // only, never logged.
  enum class Kind { quit, key, mouse_down, mouse_up, mouse_move, key_up, wheel } kind;
  int key = 0;  // Kind::key, Kind::key_up; Kind::wheel: notches
  int x = 0, y = 0;
  int button = 0;  // 1 left, 2 middle, 3 right (SDL's numbering)
};

struct InputLog;  // app/input_log.hpp: events with their ticks (--record, --replay)

struct Overlays {
  bool aabb = false, velocity = false, contacts = false, hud = true, help = false;
  bool times = false;  // the stages' times on the HUD (T): off, a compact HUD
};

// Where a contact of the last step is: the overlap of the two boxes' x and
// y ranges right after the step (the correction leaves them touching, so a
// segment of their shared edge), in world coordinates.
struct ContactRegion {
  Vector lo, hi;
  Vector middle() const { return 0.5 * (lo + hi); }
};

// The right drag's ray, from the press point to the mouse, and the first
// body it enters (ray_cast on the world as it is now), if any.
struct RayView {
  Vector from, to;
  std::optional<RayHit> hit;
};

// One frame's picture beyond the blocks themselves.
struct View {
  Overlays overlays;
  std::span<const Contact> contacts;  // the last step's collisions (none if it had none), if shown
  std::span<const ContactRegion> contact_regions;  // where each one is, in the same order
  std::optional<std::pair<Vector, Vector>> sling;  // drag: from the press point (a game's sling) to the pull
  std::vector<Vector> preview;                     // a drag's flight under gravity, dots every preview_ms
  std::optional<RayView> ray;                      // right drag
  std::vector<std::string> hud;   // lines, top left
  std::vector<std::string> help;  // the key list, when H is on
  std::span<const BlockRole> roles;  // each body's part in a game (tag, strength), by entity id
  Style style = Style::plain;        // how the blocks are drawn (app/style.hpp)
  Camera camera;                     // world to screen for all of the above but the HUD and key list
};

class Testbed {
 public:
  static constexpr double slow_motion = 0.25;   // time scale of S
  static constexpr int max_steps_per_frame = 5; // a slow machine slows down instead of freezing
  static constexpr int spawn_size = 30;         // px, square
  static constexpr double spawn_mass = 5.0;
  static constexpr double fling_scale = 0.005;  // px/ms of velocity per px of drag
  static constexpr double max_fling = 2.0;      // px/ms: below a wall's 40 px per frame
  static constexpr int click_radius = 4;        // px: a shorter drag is a click
  static constexpr double message_ms = 2000.0;  // real ms a "no room there" stays on the HUD
  static constexpr double preview_ms = 40.0;    // between two dots of the aiming preview
  static constexpr double preview_span_ms = 2000.0;  // how far ahead it looks

  // `scenes` is the list keys 1-9 and Tab walk through; `overrides` (the
  // command line's values) apply to each of them; `make` builds each world
  // (--course: the course's functions). Throws SceneError if the first scene
  // is invalid.
  Testbed(std::vector<SceneSpec> scenes, std::size_t current, Overrides overrides = {}, Overlays overlays = {},
          WorldMaker make = make_scene_world);

  enum class Action { none, quit };
  Action handle(const InputEvent& e);

  // Real time passed since the last call, in ms: runs the fixed steps it
  // covers (none while paused; a quarter in slow motion), never past frame
  // `last_frame`. Returns the steps.
  int advance(double elapsed_ms, std::int64_t last_frame = std::numeric_limits<std::int64_t>::max());
  void step();
  void reset();
  // Switches to scene i (ignored if out of range); rebuilds it.
  void select(std::size_t i);

  // Record and replay (testbed_replay.cpp). The tick is the number of
  // physics steps run since construction (world().frame restarts at R).
  std::int64_t ticks() const { return ticks_; }
  // Appends every event handle() gets from now on, with its tick, to `log`
  // (which must outlive the recording; null stops it).
  void record(InputLog* log) { recording_ = log; }
  // From now on (call it before the first step), the events of `log` are
  // handled at their ticks: each tick's before the step of that tick, paused
  // or not. At the log's end tick the replay ends and the testbed pauses.
  void replay(InputLog log);
  bool replaying() const { return replay_ != nullptr; }
  std::size_t replayed() const { return replayed_; }  // logged events handled so far
  // The window's input: handled, but while replaying only a quit counts
  // (Esc, Q, closing the window), so the replay stays exact.
  Action live(const InputEvent& e);
  // The headless replay: handles each tick's events and steps until the
  // replay ends, the testbed is paused with nothing due (the log does not
  // fit this scene), or `last_tick` (whose events are handled).
  void play(std::int64_t last_tick = std::numeric_limits<std::int64_t>::max());

  World& world() { return *world_; }
  const World& world() const { return *world_; }
  const SceneSpec& scene() const { return scenes_[current_]; }
  // Each body's block tag and strength (scene keys "tag", "strength"), by entity id.
  std::span<const BlockRole> roles() const { return roles_; }
  // The scene's game (scene key "game"), or none; how its level stands.
  const Level* level() const { return level_.get(); }
  Level::Outcome outcome() const { return outcome_; }
  std::size_t current() const { return current_; }
  std::size_t scene_count() const { return scenes_.size(); }
  bool paused() const { return paused_; }
  bool slow() const { return slow_; }
  const Overlays& overlays() const { return overlays_; }
  const std::string& message() const { return message_; }

  // The window's size, screen px (by default the world's: scale 1). The
  // camera starts again from it: the world fitted, or its player followed.
  void set_viewport(Vector size);
  const Camera& camera() const { return camera_; }
  // A slingshot drag's velocity (the pull: press point minus release
  // point, world px): none for a click, at most max_fling.
  static Vector fling(Vector pull);

  // Spawns a block centred on (x, y) with velocity v, unless it would
  // overlap a wall or another body or leave the world (then a message says
  // "no room there" for message_ms). Returns whether it did.
  bool spawn(Vector centre, Vector v);

  View view(double fps, double draw_ms) const;
  // The H list; the digit line names as many scenes as there are (at most 9).
  static std::vector<std::string> key_list(std::size_t scene_count);

  // Called after every physics step, and after a reset or a scene switch
  // with the new world (frame 0): the trace.
  std::function<void(const World&)> on_step, on_reset;

 private:
  void rebuild();
  void reframe();
  bool camera_input(const InputEvent& e);
  InputEvent in_world(InputEvent e) const;
  std::vector<Vector> trajectory(Vector from, Vector v) const;
  void install(const SceneSpec& spec);
  void restarted();
  void add_measures(View& v, double fps, double draw_ms) const;
  void after_level_step();
  bool next_level();
  void record_contacts();
  void after_step();
  // Shows `message` on the HUD; a passing one (`fades`) for message_ms.
  void say(std::string message, bool fades);

  std::vector<SceneSpec> scenes_;
  std::size_t current_;
  Overrides overrides_;
  Overlays overlays_;
  WorldMaker make_;
  // On the heap, so that a game's api::View of it holds when the testbed moves.
  std::unique_ptr<World> world_;
  bool paused_ = false, slow_ = false;
  double acc_ms_ = 0.0;
  std::optional<Vector> press_;      // left button down: the slingshot
  std::optional<Vector> ray_from_;   // right button down: the ray
  Vector mouse_{};
  // The camera (picture only): the view's size, whether it follows the
  // game's player (F; a pan stops it), a pan's last point and button, Shift.
  Camera camera_;
  std::optional<Vector> viewport_;
  bool following_ = true, shift_ = false;
  std::optional<Vector> pan_from_;
  int pan_button_ = 0;
  void pump();  // replay: handles the logged events due at this tick
  void record_event(const InputEvent& e);
  std::int64_t ticks_ = 0;
  InputLog* recording_ = nullptr;
  std::shared_ptr<const InputLog> replay_;  // shared: InputLog is incomplete here
  std::size_t replayed_ = 0;  // also the next logged event's index
  std::vector<BlockRole> roles_;
  std::unique_ptr<Level> level_;  // the scene's game, if it has one
  std::unique_ptr<api::View> game_view_;  // the game's id of world_ (with level_)
  Level::Outcome outcome_ = Level::Outcome::playing;
  Style style_ = Style::plain;    // the scene's, or the command line's
  std::vector<Contact> last_contacts_;
  std::vector<ContactRegion> last_regions_;
  std::string message_;
  double message_left_ms_ = 0.0;
  // What a spawn may not overlap, so that a click costs O(1) and not a scan
  // of every body (200 000 replayed clicks took minutes): the bodies as they
  // were at the first click since the last step or new world, in the broad
  // phase's grid (one O(n) build, like a step's), and the blocks spawned
  // since, by cell of spawn_size. Dropped by a step and a new world.
  struct SpawnIndex {
    UniformGrid grid;
    std::size_t indexed = 0, spawned = 0;  // bodies in the grid, and in `cells`
    std::map<std::uint64_t, std::vector<EntityId>> cells;  // (not a hash table: its code cost the web build ~3.5 KB)
  };
  std::optional<SpawnIndex> spawn_index_;
  bool room_for_spawn(Vector pos);
};

}  // namespace physics
