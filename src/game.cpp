#include "game.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

#include "entities/block.hpp"
#include "utils/random.hpp"

namespace physics::Game {

void init_walls(World& w, int width, int height) {
  const int t = wall_thickness;
  Block::make(w, 0, 0, width, t, wall_blue, infinity);                   // top
  Block::make(w, 0, height - t, width, t, wall_blue, infinity);          // bottom
  Block::make(w, 0, t, t, height - 2 * t, wall_black, infinity);         // left
  Block::make(w, width - t, t, t, height - 2 * t, wall_black, infinity); // right
}

void init_scene(World& w, std::uint64_t seed) {
  init_walls(w);
  // Q3/Q4: the red square of mass 10, set going by an initial force.
  const auto red = Block::make(w, 100, 100, 40, 40, Color{255, 0, 0, 255}, 10.0);
  w.components.sum_forces[red.id] = {0.25, 0.25};

  // Q9: ten squares on a 5×2 grid of 100 px cells below the red one.
  Random rng(seed);
  for (int i = 0; i < 10; ++i) {
    const int side = rng.uniform_int(20, 40);
    const double mass = rng.uniform(1.0, 20.0);
    const Vector impulse{rng.uniform(0.0, 0.25), rng.uniform(0.0, 0.25)};
    const Color col{static_cast<std::uint8_t>(rng.uniform_int(40, 220)),
                    static_cast<std::uint8_t>(rng.uniform_int(40, 220)),
                    static_cast<std::uint8_t>(rng.uniform_int(40, 220)), 255};
    const double x = 180 + 110 * (i % 5) + rng.uniform(0, 50);
    const double y = 220 + 150 * (i / 5) + rng.uniform(0, 80);
    const auto b = Block::make(w, x, y, side, side, col, mass);
    // An impulse J changes the velocity by J/m. Forces applies Σf·dt/m on the
    // first frame, so the initial force J/dt is exactly that impulse.
    w.components.sum_forces[b.id] = Vector::mult(1.0 / w.params.dt, impulse);
  }
}

Summary run_headless(World& w, std::int64_t frames) {
  Summary s;
  s.bodies = w.components.size();
  s.mobile = w.finite_bodies();
  for (std::int64_t f = 0; f < frames; ++f) {
    w.step();
    // Bodies start at rest with their first impulse pending in sum_forces;
    // the motion they start with is the one after the first frame.
    if (f == 0) {
      s.ke_start = w.kinetic_energy();
      s.p_start = w.momentum();
    }
  }
  s.frames = frames;
  s.ke_end = w.kinetic_energy();
  s.p_end = w.momentum();
  return s;
}

void print_summary(std::ostream& out, const World& w, const Summary& s, const std::string& why) {
  const auto vec = [](Vector v) {
    std::ostringstream o;
    o << std::setprecision(6) << "(" << v.x << ", " << v.y << ")";
    return o.str();
  };
  out << "ran headless: " << why << "\n"
      << "frames:          " << s.frames << " (dt = " << w.params.dt << " ms, " << w.params.substeps
      << " substep(s))\n"
      << "bodies:          " << s.bodies << " (" << s.mobile << " mobile)\n"
      << std::setprecision(9) << "kinetic energy:  " << s.ke_start << " after frame 1, " << s.ke_end << " at the end\n"
      << "momentum:        " << vec(s.p_start) << " after frame 1, " << vec(s.p_end) << " at the end\n"
      << std::setprecision(4) << "physics ms/step: " << w.times.total_ms_per_step() << " total";
  for (const SystemId id : all_systems) {
    if (id == SystemId::draw || !w.systems.declared().has(id)) continue;
    out << ", " << name(id) << " " << w.times.ms_per_step(id);
  }
  out << "\n";
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
#include "window.hpp"

namespace {

using namespace physics;

constexpr std::int64_t headless_frames = 600;

void usage(std::ostream& out) {
  out << "usage: game [--headless] [--frames N] [--seed S] [--screenshot FILE.png] [--help]\n"
         "  Opens the course's question-9 scene in a window (Esc quits).\n"
         "  --headless          run without a window and print a summary (also when no display)\n"
         "  --frames N          frames to run (headless default 600; in a window, quit after N)\n"
         "  --seed S            seed of the random blocks (default 42)\n"
         "  --screenshot FILE   save the window's last frame as PNG (with --frames)\n";
}

// frames < 0: until the user quits.
int run_window(World& w, std::int64_t frames, const std::string& screenshot) {
  Window win(Game::width, Game::height, "physics - course TP3");
  if (!win.hud_warning().empty()) std::cerr << "warning: " << win.hud_warning() << "\n";
  // Fixed time step: the physics advances by dt whatever the display's rate,
  // so a run does not depend on the machine. At most 5 steps per displayed
  // frame, so a slow machine slows the simulation down instead of freezing.
  double last = win.seconds(), acc = 0.0, fps = 0.0;
  for (bool running = true; running;) {
    for (const InputEvent& ev : win.poll_events()) {
      if (ev.kind == InputEvent::Kind::quit || (ev.kind == InputEvent::Kind::key && ev.key == 27)) running = false;
    }
    const double now = win.seconds();
    const double elapsed = now - last;
    last = now;
    if (elapsed > 0) fps = 0.9 * fps + 0.1 / elapsed;
    acc = std::min(acc + elapsed * 1000.0, 5 * w.params.dt);
    while (acc >= w.params.dt) {
      w.step();
      acc -= w.params.dt;
    }
    win.render(w, {Game::hud_line(w, fps)});
    if (frames >= 0 && w.frame >= frames) {
      if (!screenshot.empty()) win.screenshot(screenshot);
      running = false;
    }
    win.present();
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  bool headless = false;
  std::int64_t frames = -1;
  std::string screenshot;
  std::uint64_t seed = 42;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&](const char* flag) -> std::string {
      if (i + 1 >= argc) {
        std::cerr << "game: " << flag << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    try {
      if (a == "--help" || a == "-h") {
        usage(std::cout);
        return 0;
      } else if (a == "--headless") {
        headless = true;
      } else if (a == "--frames") {
        frames = std::stoll(value("--frames"));
        if (frames < 0) throw std::invalid_argument("negative");
      } else if (a == "--screenshot") {
        screenshot = value("--screenshot");
      } else if (a == "--seed") {
        seed = std::stoull(value("--seed"));
      } else {
        std::cerr << "game: unknown option '" << a << "' (see --help)\n";
        return 2;
      }
    } catch (const std::logic_error&) {
      std::cerr << "game: bad value for " << a << "\n";
      return 2;
    }
  }
  std::string why = "--headless given";
  if (!headless && !display_available()) {
    headless = true;
    why = "no display (DISPLAY, WAYLAND_DISPLAY and SDL_VIDEODRIVER unset)";
  }
  if (!screenshot.empty() && frames < 0) frames = 60;
  SystemSet systems;
  systems.draw = !headless;
  World w(systems);
  Game::init_scene(w, seed);
  if (!headless) {
    try {
      return run_window(w, frames, screenshot);
    } catch (const WindowError& e) {
      std::cerr << "game: " << e.what() << "; running headless\n";
      why = std::string("window failed: ") + e.what();
      World fresh(SystemSet{false, true, true, true});
      Game::init_scene(fresh, seed);
      Game::print_summary(std::cout, fresh, Game::run_headless(fresh, frames < 0 ? headless_frames : frames), why);
      return 0;
    }
  }
  Game::print_summary(std::cout, w, Game::run_headless(w, frames < 0 ? headless_frames : frames), why);
  return 0;
}
#endif
