#include "game.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

#include "builtin_scenes.hpp"
#include "entities/block.hpp"

namespace physics::Game {

void init_walls(World& w, int width, int height, double e) {
  const int t = wall_thickness;
  Block::make(w, 0, 0, width, t, wall_blue, infinity, e);                    // top
  Block::make(w, 0, height - t, width, t, wall_blue, infinity, e);           // bottom
  Block::make(w, 0, t, t, height - 2 * t, wall_black, infinity, e);          // left
  Block::make(w, width - t, t, t, height - 2 * t, wall_black, infinity, e);  // right
}

void init_scene(World& w, std::uint64_t seed) {
  SceneSpec s = *find_builtin("many");
  Overrides o;
  o.seed = seed;
  apply(s, o);
  populate(w, s, "scene many");
}

Summary run_headless(World& w, std::int64_t frames) {
  return run_headless(w, frames, [](const World&) {});
}

std::string system_times(const World& w) {
  std::ostringstream out;
  out << std::setprecision(4);
  bool first = true;
  for (const SystemId id : all_systems) {
    if (id == SystemId::draw) continue;  // the front end's, timed there
    out << (first ? "" : ", ") << name(id) << ' ';
    first = false;
    // A system the scene left out has no time at all, not a time of zero.
    if (w.systems.declared().has(id)) out << w.times.ms_per_step(id);
    else out << "off";
  }
  return out.str();
}

void print_summary(std::ostream& out, const World& w, const Summary& s, const std::string& why,
                   const std::string& scene) {
  const auto vec = [](Vector v) {
    std::ostringstream o;
    o << std::setprecision(6) << "(" << v.x << ", " << v.y << ")";
    return o.str();
  };
  std::ostringstream o;
  o << "ran headless: " << why << "\n";
  if (!scene.empty()) {
    SystemSet physics_systems = w.systems.declared();
    physics_systems.draw = false;
    const std::string names = physics_systems.to_string();
    o << "scene:           " << scene << " (systems: " << (names.empty() ? "none" : names) << ")\n";
  }
  o << "frames:          " << s.frames << " (dt = " << w.params.dt << " ms, " << w.params.substeps << " substep(s))\n"
    << "bodies:          " << s.bodies << " (" << s.mobile << " mobile)\n"
    << std::setprecision(9) << "kinetic energy:  " << s.ke_start << " after frame 1, " << s.ke_end << " at the end\n"
    << "momentum:        " << vec(s.p_start) << " after frame 1, " << vec(s.p_end) << " at the end\n"
    << std::setprecision(4) << "physics ms/step: " << w.times.total_ms_per_step() << " total, " << system_times(w)
    << "\n";
  out << o.str();
}

std::string hud_line(const World& w, double fps) {
  const Vector p = w.momentum();
  char buf[200];
  std::snprintf(buf, sizeof buf, "%.0f fps  physics %.3f ms/step  %zu bodies  KE %.5g  p (%.4g, %.4g)", fps,
                w.times.total_ms_per_step(), w.components.size(), w.kinetic_energy(), p.x, p.y);
  return buf;
}

}  // namespace physics::Game

#ifndef GAME_NO_MAIN
#include <limits>
#include <optional>

#include "cli.hpp"
#include "testbed.hpp"
#include "window.hpp"

namespace {

using namespace physics;

// The testbed in a window. Fixed time step: the physics advances by dt
// whatever the display's rate, so a run does not depend on the machine.
int run_window(Cli::Session& s) {
  const Cli::Options& o = s.options;
  Testbed tb(s.scenes, s.current, o.overrides, o.overlays);
  const SceneSpec& first = tb.scene();
  std::optional<Window> win;
  try {
    win.emplace(first.width, first.height, "physics - " + first.name + " (H: keys)");
  } catch (const WindowError& e) {
    throw Cli::NoWindow(e.what());
  }
  if (!win->hud_warning().empty()) *s.err << "warning: " << win->hud_warning() << "\n";
  Cli::Recorder& rec = *s.recorder;
  rec.start(tb.world());
  tb.on_step = [&](const World& w) { rec.after_step(w); };
  tb.on_reset = [&](const World& w) { rec.restart(w); };
  std::optional<std::int64_t> frames = o.frames;
  if (!o.screenshot.empty() && !frames) frames = Cli::screenshot_frames;

  double last = win->seconds(), fps = 0.0, draw_ms = 0.0;
  for (bool running = true; running;) {
    for (const InputEvent& ev : win->poll_events())
      if (tb.handle(ev) == Testbed::Action::quit) running = false;
    const double now = win->seconds();
    const double elapsed = now - last;
    last = now;
    if (elapsed > 0) fps = 0.9 * fps + 0.1 / elapsed;
    // With --frames, stop at exactly that frame whatever the display's speed.
    tb.advance(elapsed * 1000.0, frames.value_or(std::numeric_limits<std::int64_t>::max()));
    const double ms = win->render(tb.world(), tb.view(fps, draw_ms));
    draw_ms = draw_ms == 0.0 ? ms : 0.9 * draw_ms + 0.1 * ms;
    if (frames && tb.world().frame >= *frames) {
      if (!o.screenshot.empty()) win->screenshot(o.screenshot);
      running = false;
    }
    win->present();
  }
  rec.finish(tb.world());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  const Cli::WindowFrontEnd window{display_available, run_window};
  return Cli::run(args, std::cout, std::cerr, &window);
}
#endif
