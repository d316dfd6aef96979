#include "app/testbed.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "course/entities/block.hpp"
#include "engine/query.hpp"
#include "app/headless.hpp"
#include "games/registry.hpp"
#include "scene/scene_json.hpp"

namespace physics {

namespace {

constexpr Color spawn_color{255, 140, 0, 255};

// A spawned block's cell (Testbed::room_for_spawn): its corner in units of
// its size (inside the world, far within int32), and the cell as one key.
std::pair<std::int64_t, std::int64_t> spawn_cell_xy(Vector pos) {
  return {static_cast<std::int64_t>(std::floor(pos.x / Testbed::spawn_size)),
          static_cast<std::int64_t>(std::floor(pos.y / Testbed::spawn_size))};
}
std::uint64_t spawn_cell_key(std::int64_t x, std::int64_t y) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(x)) << 32) | static_cast<std::uint32_t>(y);
}
std::uint64_t spawn_cell(Vector pos) {
  const auto [x, y] = spawn_cell_xy(pos);
  return spawn_cell_key(x, y);
}

SceneSpec with_overrides(SceneSpec s, const Overrides& o) {
  apply(s, o);
  return s;
}

// "solver stable (8 it.)  substeps 2  CCD on  overlays: aabb, contacts"
std::string options_line(const Params& p, const Overlays& o) {
  std::string s = "solver " + std::string(name(p.solver));
  if (p.solver != Solver::course) s += " (" + std::to_string(p.iterations) + " it.)";
  s += "  substeps " + std::to_string(p.substeps) + "  CCD " +
       (p.solver == Solver::automatic ? "auto" : p.ccd ? "on" : "off");
  if (p.integrator == Integrator::exact) s += "  integrator exact";  // the default, the sheet's, goes unsaid
  s += "  overlays: ";
  std::string list;
  for (const auto& [on, name] : {std::pair{o.aabb, "aabb (A)"}, {o.velocity, "velocity (V)"},
                                 {o.contacts, "contacts (C)"}})
    if (on) list += (list.empty() ? "" : ", ") + std::string(name);
  return s + (list.empty() ? "none (A, V, C)" : list);
}

// "ray: body 1 at (200.0, 560.0), normal (0, -1), 93.9% of the drag"; a
// tile layer's cell after its body: "body 3 cell (12, 4) at ...".
std::string ray_line(const RayHit& h) {
  char cell[48] = "";
  if (h.column >= 0) std::snprintf(cell, sizeof cell, " cell (%d, %d)", h.column, h.row);
  char line[160];
  std::snprintf(line, sizeof line, "ray: body %u%s at (%.1f, %.1f), normal (%g, %g), %.1f%% of the drag",
                static_cast<unsigned>(h.body), cell, h.point.x, h.point.y, h.normal.x, h.normal.y, 100.0 * h.fraction);
  return line;
}

}  // namespace

Testbed::Testbed(std::vector<SceneSpec> scenes, std::size_t current, Overrides overrides, Overlays overlays,
                 WorldMaker make)
    : scenes_(std::move(scenes)), current_(current < scenes_.size() ? current : 0), overrides_(overrides),
      overlays_(overlays), make_(make) {
  install(with_overrides(scenes_.at(current_), overrides_));
  record_contacts();
  reframe();
}

// The world of `spec`, its bodies' roles and its game's level (SceneError if
// the scene is invalid or lacks what its game needs): all three are built
// first and kept together, or none is.
void Testbed::install(const SceneSpec& spec) {
  const std::vector<Body> bodies = expand(spec, spec.name);
  World world = make_(spec, bodies, true);
  std::vector<BlockRole> roles = roles_by_entity(spec, bodies);
  // A game plays through the public API, on a view of the world (the same
  // id once the world is moved into place).
  std::unique_ptr<api::View> view;
  std::unique_ptr<Level> level;
  if (!spec.game.kind.empty()) {
    view = std::make_unique<api::View>(world);
    level = make_level(spec, view->id(), roles);
  }
  if (world_) *world_ = std::move(world);
  else world_ = std::make_unique<World>(std::move(world));
  if (view) view->rebind(*world_);
  roles_ = std::move(roles);
  level_ = std::move(level);
  game_view_ = std::move(view);
  outcome_ = Level::Outcome::playing;
  style_ = spec.style;
}

void Testbed::rebuild() {
  try {
    install(with_overrides(scenes_[current_], overrides_));
    message_.clear();
  } catch (const SceneError& e) {
    say(e.what(), false);  // keep the world we have
  }
  restarted();
}

// What a new world starts without: last step's contacts, time owed, a drag.
void Testbed::restarted() {
  spawn_index_.reset();  // another world
  record_contacts();
  last_contacts_.clear();
  last_regions_.clear();
  acc_ms_ = 0.0;
  press_.reset();
  reframe();
  if (on_reset) on_reset(*world_);
}

void Testbed::reset() { rebuild(); }

// The Collision system records its contacts for the C overlay, or for the
// contact events (--events): one flag, two users.
void Testbed::record_contacts() {
  if (world_->declares(SystemId::collision)) world_->pass.record_contacts = overlays_.contacts || world_->events.enabled;
}

void Testbed::select(std::size_t i) {
  if (i >= scenes_.size()) return;
  current_ = i;
  rebuild();
}

void Testbed::after_step() {
  // The contacts of this step only (none is none: no arrows left behind by
  // bodies that have moved apart), placed where the bodies meet now.
  last_contacts_.clear();
  last_regions_.clear();
  if (world_->declares(SystemId::collision) && overlays_.contacts) {
    const Components& c = world_->components;
    last_contacts_ = world_->pass.contacts;
    for (const Contact& k : last_contacts_) {
      const Vector a = c.position[k.c], b = c.position[k.b];
      const Vector lo{std::max(a.x, b.x), std::max(a.y, b.y)};
      const Vector hi{std::min(a.x + c.box[k.c].width, b.x + c.box[k.b].width),
                      std::min(a.y + c.box[k.c].height, b.y + c.box[k.b].height)};
      last_regions_.push_back({lo, hi});
    }
  }
  if (on_step) on_step(*world_);
}

void Testbed::step() {
  pump();  // a replay's events of this tick come before its step
  // A world with a non-finite body is stopped: nothing after it is physics.
  if (world_->health.non_finite) return;
  if (level_ && outcome_ == Level::Outcome::playing) level_->before_step(game_view_->id());
  Game::step(*world_);
  spawn_index_.reset();  // the bodies have moved
  ++ticks_;
  after_step();
  if (level_ && outcome_ == Level::Outcome::playing) after_level_step();
  if (const std::optional<Vec2> f = level_ ? level_->focus() : std::nullopt; f && following_) camera_.follow({f->x, f->y});
  if (world_->health.non_finite) {
    paused_ = true;
    say("stopped: " + Headless::non_finite_line(*world_) + " (R: reset)", false);
  }
}

// A lost level starts again; a won one stops, and Enter loads the next.
void Testbed::after_level_step() {
  outcome_ = level_->after_step(game_view_->id());
  if (outcome_ == Level::Outcome::lost) {
    rebuild();
    say("level lost: starting again", true);
  } else if (outcome_ == Level::Outcome::won) {
    paused_ = true;
    say(scene().game.next.empty() ? "level won! (R: play it again)" : "level won! Enter: next level", false);
  }
}

// The won level's next one (scene key game.next), in place of this scene;
// if it cannot start, the won level stays, with the error on the HUD.
bool Testbed::next_level() {
  const std::string path = scene().game.next_path;
  if (outcome_ != Level::Outcome::won || path.empty()) return false;
  SceneSpec next;
  try {
    next = load_scene_file(path);
    install(with_overrides(next, overrides_));
  } catch (const SceneError& e) {
    say(e.what(), false);
    return true;
  }
  scenes_[current_] = std::move(next);
  message_.clear();
  paused_ = false;
  restarted();
  return true;
}

void Testbed::say(std::string message, bool fades) {
  message_ = std::move(message);
  message_left_ms_ = fades ? message_ms : std::numeric_limits<double>::infinity();
}

int Testbed::advance(double elapsed_ms, std::int64_t last_frame) {
  // A passing message fades after message_ms of real time, paused or not.
  if (!message_.empty() && elapsed_ms > 0.0 && (message_left_ms_ -= elapsed_ms) <= 0.0) message_.clear();
  pump();  // a replay's events due now, paused or not
  if (paused_ || !(elapsed_ms > 0.0)) return 0;
  const double dt = world_->params.dt;
  acc_ms_ = std::min(acc_ms_ + elapsed_ms * (slow_ ? slow_motion : 1.0), max_steps_per_frame * dt);
  // Whole steps covered; the 1e-9 keeps k·dt summed from k pieces a step.
  const int due = static_cast<int>(std::floor(acc_ms_ / dt + 1e-9));
  int n = 0;
  while (n < due && world_->frame < last_frame && !paused_) {
    step();
    pump();  // a replayed pause stops the steps of this frame
    ++n;
  }
  acc_ms_ = due > 0 ? std::max(0.0, acc_ms_ - due * dt) : acc_ms_;
  return n;
}

bool Testbed::spawn(Vector centre, Vector v) {
  const SceneSpec& s = scene();
  const double half = spawn_size / 2.0;
  const Vector pos{centre.x - half, centre.y - half};
  const double t = s.walls ? wall_thickness : 0.0;
  if (!(pos.x >= t && pos.y >= t && pos.x + spawn_size <= s.width - t && pos.y + spawn_size <= s.height - t)) {
    say(s.walls ? "no room there: a block cannot overlap the walls" : "no room there: outside the world", true);
    return false;
  }
  if (!room_for_spawn(pos)) {
    say("no room there: a block cannot overlap another body", true);
    return false;
  }
  const auto b = Block::make(*world_, pos.x, pos.y, spawn_size, spawn_size, spawn_color, spawn_mass,
                             with_overrides(s, overrides_).restitution);
  world_->components.velocity[b.id] = v;
  roles_.resize(world_->components.size());
  message_.clear();
  ++spawn_index_->spawned;
  spawn_index_->cells[spawn_cell(pos)].push_back(b.id);
  return true;
}

// Nor into a body (a tower would explode), with the sheet's test (mdiff,
// has_origin) on every candidate, so a block is refused exactly where
// Collision would see it overlap. The candidates: the bodies of the grid
// whose box meets the block's, and the blocks spawned since in the 3x3
// cells around it (two spawn_size squares overlap only within one cell).
bool Testbed::room_for_spawn(Vector pos) {
  const Components& c = world_->components;
  // Another body added since (a game's launch): the index is rebuilt.
  if (spawn_index_ && spawn_index_->indexed + spawn_index_->spawned != c.size()) spawn_index_.reset();
  if (!spawn_index_) {
    spawn_index_.emplace();
    std::vector<FloatBox> boxes;
    boxes.reserve(c.size());
    // A tile layer's box and its strips' proxies are not what collides: its
    // cells are, looked at below. (A NaN box is in no cell.)
    const TileSet& tiles = world_->tiles;
    for (std::size_t e = 0; e < c.size(); ++e)
      boxes.push_back(!tiles.empty() && tiles.part_of_tiles(static_cast<EntityId>(e))
                          ? FloatBox{NAN, NAN, NAN, NAN}
                          : FloatBox::around(c.position[e], c.box[e], 0.0));
    spawn_index_->grid.index(boxes);
    spawn_index_->indexed = c.size();
  }
  const auto overlaps = [&](std::size_t e) {
    const auto [s_pos, s_box] = Rect::mdiff(pos, Rect{spawn_size, spawn_size}, c.position[e], c.box[e]);
    return Rect::has_origin(s_pos, s_box);
  };
  bool hit = false;
  spawn_index_->grid.query(FloatBox::around(pos, Rect{spawn_size, spawn_size}, 0.0),
                           [&](std::uint32_t e) { hit = hit || overlaps(e); });
  const auto [cx, cy] = spawn_cell_xy(pos);
  for (std::int64_t dx = -1; dx <= 1 && !hit; ++dx)
    for (std::int64_t dy = -1; dy <= 1 && !hit; ++dy)
      if (const auto it = spawn_index_->cells.find(spawn_cell_key(cx + dx, cy + dy)); it != spawn_index_->cells.end())
        hit = std::any_of(it->second.begin(), it->second.end(), overlaps);
  if (!hit && !world_->tiles.empty())
    hit = !QueryIndex(*world_).cells_meeting(pos, pos + Vector{double(spawn_size), double(spawn_size)}).empty();
  return !hit;
}

Testbed::Action Testbed::handle(const InputEvent& e) {
  using Kind = InputEvent::Kind;
  if (recording_) record_event(e);
  switch (e.kind) {
    case Kind::quit: return Action::quit;
    case Kind::mouse_down:
      if (e.button == 1) press_ = mouse_ = Vector{double(e.x), double(e.y)};
      if (e.button == 3) ray_from_ = mouse_ = Vector{double(e.x), double(e.y)};
      return Action::none;
    case Kind::mouse_move:
      mouse_ = {double(e.x), double(e.y)};
      return Action::none;
    case Kind::mouse_up: {
      if (e.button == 3) ray_from_.reset();
      if (e.button != 1 || !press_) return Action::none;
      const Vector from = *press_;
      press_.reset();
      // Slingshot: the block leaves from where the drag began, opposite to the drag.
      const Vector v = fling(from - Vector{double(e.x), double(e.y)});
      if (level_ && level_->launch(game_view_->id(), {from.x, from.y}, {v.x, v.y})) {
        roles_.resize(world_->components.size(), level_->role_of_new_body());
        return Action::none;
      }
      spawn(from, v);
      return Action::none;
    }
    case Kind::key:
      if (level_ && level_->key(e.key, true)) return Action::none;
      break;
    case Kind::key_up:
      if (level_) level_->key(e.key, false);
      return Action::none;
    case Kind::wheel: return Action::none;  // the camera's (live)
  }
  const int k = (e.key >= 'A' && e.key <= 'Z') ? e.key - 'A' + 'a' : e.key;
  switch (k) {
    case key::escape:
    case 'q': return Action::quit;
    case key::space:
    case 'p': paused_ = !paused_; acc_ms_ = 0.0; break;
    case key::enter: next_level(); break;
    case 'n':
    case key::right:
      paused_ = true;
      step();
      break;
    case 'r': {
      const bool won = outcome_ == Level::Outcome::won;  // paused on the win: play it again at once
      reset();
      if (won) paused_ = false;
      break;
    }
    case key::tab: select((current_ + 1) % scenes_.size()); break;
    case 'a': overlays_.aabb = !overlays_.aabb; break;
    case 'v': overlays_.velocity = !overlays_.velocity; break;
    case 'c':
      overlays_.contacts = !overlays_.contacts;
      record_contacts();
      if (!overlays_.contacts) last_contacts_.clear(), last_regions_.clear();
      break;
    case 'i': overlays_.hud = !overlays_.hud; break;
    case 't': overlays_.times = !overlays_.times; break;
    case 's': slow_ = !slow_; break;
    case 'h': overlays_.help = !overlays_.help; break;
    default:
      if (k >= '1' && k <= '9') select(static_cast<std::size_t>(k - '1'));
      break;
  }
  return Action::none;
}

std::vector<std::string> Testbed::key_list(std::size_t scene_count) {
  // The digits that choose a scene: 1-8 for the built-ins, 9 for a scene
  // file given with --scene (it joins the list as the ninth).
  const std::size_t n = std::clamp<std::size_t>(scene_count, 1, 9);
  std::string digits = n == 1 ? "1      " : "1-" + std::to_string(n) + "    ";
  return {"Space  pause / resume (also P; the platformer's jump)",
          "N, ->  one step",
          "R      reset the scene",
          digits + (n == 9 ? "scene (9: the --scene file); Tab: next" : "choose a scene, Tab: next scene"),
          "click  spawn a block",
          "drag   slingshot: it flies opposite to the drag",
          "right drag: ray, first body hit, normal",
          "A      AABBs",
          "V      velocity vectors",
          "C      contact normals and penetration vectors",
          "wheel  zoom about the cursor",
          "middle drag or Shift+drag: pan",
          "F      camera: fit the world (or follow the player)",
          "I      HUD on/off",
          "T      stage times on the HUD",
          "S      slow motion (x1/4)",
          "H      this list",
          "Enter  a game's next level, after a win",
          "Esc, Q quit"};
}

// The HUD's lines about the engine: its measures, the options, the ray's
// hit and the health check's note (the course solver's limits met), as in
// the headless summary.
void Testbed::add_measures(View& v, double fps, double draw_ms) const {
  v.hud.push_back(Headless::hud_line(*world_, fps));
  char draw[64];
  std::snprintf(draw, sizeof draw, "  draw %.3f ms/frame", draw_ms);
  v.hud.push_back(options_line(world_->params, overlays_));
  const bool drawn = world_->declares(SystemId::draw);
  // Long lines are wrapped to the window's width where they are drawn (app/overlay).
  if (overlays_.times) v.hud.push_back("ms/step: " + Headless::stage_times(*world_) + (drawn ? draw : "  draw off"));
  if (v.ray && v.ray->hit) v.hud.push_back(ray_line(*v.ray->hit));
  if (const std::string note = Headless::advice(*world_); !note.empty()) v.hud.push_back("note: " + note);
}

View Testbed::view(double fps, double draw_ms) const {
  View v;
  v.overlays = overlays_;
  v.roles = roles_;
  v.style = style_;
  if (overlays_.contacts) v.contacts = last_contacts_, v.contact_regions = last_regions_;
  if (press_) {
    // A game that launches from its own point: the same drag, drawn from there.
    const std::optional<Vec2> point = level_ ? level_->launch_point() : std::nullopt;
    const std::optional<Vector> origin = point ? std::optional<Vector>(Vector{point->x, point->y}) : std::nullopt;
    v.sling = origin ? std::pair{*origin, *origin + (mouse_ - *press_)} : std::pair{*press_, mouse_};
    v.preview = trajectory(v.sling->first, fling(*press_ - mouse_));
  }
  if (ray_from_) {
    // Cast on every view: the bodies move under a ray held still.
    const Vector d = mouse_ - *ray_from_;
    v.ray = RayView{*ray_from_, mouse_, ray_cast(*world_, *ray_from_, d, Vector::norm(d))};
  }
  if (overlays_.hud) {
    const SceneSpec& s = scene();
    // The frame number on the title line: the measures' line is full in an 800 px window.
    std::string title = "scene " + std::to_string(current_ + 1) + "/" + std::to_string(scenes_.size()) + " " + s.name +
                        "  frame " + std::to_string(world_->frame);
    if (paused_) title += "  [paused]";
    if (slow_) title += "  [slow x0.25]";
    title += "   H: keys";
    v.hud.push_back(title);
    // A game's HUD is the game's lines, not the engine's measures.
    if (level_)
      for (std::string& line : level_->hud()) v.hud.push_back(std::move(line));
    else
      add_measures(v, fps, draw_ms);
    if (!message_.empty()) v.hud.push_back(message_);
  }
  if (overlays_.help) v.help = key_list(scenes_.size());
  v.camera = camera_;
  return v;
}

Vector Testbed::fling(Vector pull) {
  if (!(Vector::norm(pull) > click_radius)) return {};
  const Vector v = fling_scale * pull;
  const double speed = Vector::norm(v);
  return speed > max_fling ? (max_fling / speed) * v : v;
}

// Where a block launched from `from` at `v` would be, every preview_ms, as
// the course's integrator moves it (v += g·h, then x += v·h) under gravity
// alone, until it reaches the walls or leaves the world: the aiming preview
// (no collision, no drag). None for a click.
std::vector<Vector> Testbed::trajectory(Vector from, Vector v) const {
  if (Vector::is_zero(v)) return {};
  const Params& p = world_->params;
  const double t = scene().walls ? wall_thickness : 0.0;
  const double h = p.substep();
  const int every = std::max(1, static_cast<int>(std::lround(preview_ms / h)));
  std::vector<Vector> dots;
  Vector x = from;
  for (int i = 1; i * h <= preview_span_ms; ++i) {
    v = v + h * p.gravity;
    x = x + h * v;
    if (x.x < t || x.y < t || x.x > scene().width - t || x.y > scene().height - t) break;
    if (i % every == 0) dots.push_back(x);
  }
  return dots;
}

void Testbed::set_viewport(Vector size) {
  viewport_ = size;
  reframe();
}

// The camera of a new world: its player followed at scale 1 (if the game
// has one and F has not been undone by a pan), else the whole world fitted.
void Testbed::reframe() {
  const Vector world{double(scene().width), double(scene().height)};
  const Vector view = viewport_.value_or(world);
  const std::optional<Vec2> f = level_ ? level_->focus() : std::nullopt;
  camera_ = f && following_ ? Camera::on({f->x, f->y}, world, view) : Camera::fit(world, view);
}

// The wheel, a pan (middle drag, or Shift and a left drag) and F: the
// camera's, handled live only (the picture, never logged). Shift is only
// watched: its key still goes on.
bool Testbed::camera_input(const InputEvent& e) {
  using Kind = InputEvent::Kind;
  const Vector at{double(e.x), double(e.y)};
  switch (e.kind) {
    case Kind::wheel: camera_.zoom_about(at, std::pow(Camera::wheel_step, e.key)); return true;
    case Kind::key:
    case Kind::key_up:
      if (e.key == key::lshift || e.key == key::rshift) shift_ = e.kind == Kind::key;
      if (e.kind == Kind::key && (e.key == 'f' || e.key == 'F')) {
        following_ = true;
        reframe();
        return true;
      }
      return false;
    case Kind::mouse_down:
      if (e.button != 2 && !(e.button == 1 && shift_)) return false;
      pan_from_ = at, pan_button_ = e.button;
      return true;
    case Kind::mouse_move:
      if (!pan_from_) return false;
      camera_.pan(at - *pan_from_);
      pan_from_ = at, following_ = false;
      return true;
    case Kind::mouse_up:
      if (!pan_from_ || e.button != pan_button_) return false;
      pan_from_.reset();
      return true;
    case Kind::quit: return false;
  }
  return false;
}

// A window event with its mouse point in world px (rounded: what the log
// keeps, so the live click and its replay land on the same point).
InputEvent Testbed::in_world(InputEvent e) const {
  using Kind = InputEvent::Kind;
  if (e.kind != Kind::mouse_down && e.kind != Kind::mouse_up && e.kind != Kind::mouse_move) return e;
  const Vector w = camera_.to_world({double(e.x), double(e.y)});
  e.x = static_cast<int>(std::lround(w.x)), e.y = static_cast<int>(std::lround(w.y));
  return e;
}

}  // namespace physics
