// The program: the command line (app/cli.hpp) and, with a display, the
// testbed in a window. Everything else is in the library.
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "app/cli.hpp"
#include "app/headless.hpp"
#include "app/input_log.hpp"
#include "app/testbed.hpp"
#include "app/window.hpp"

namespace {

using namespace physics;

// The window's loop, until the user quits or frame `frames`; the last frame
// shown goes to `screenshot` if one is asked for.
void loop(Testbed& tb, Window& win, std::optional<std::int64_t> frames, const std::string& screenshot,
          std::ostream& err) {
  double last = win.seconds(), fps = 0.0, draw_ms = 0.0;
  for (bool running = true; running;) {
    for (const InputEvent& ev : win.poll_events())
      if (tb.live(ev) == Testbed::Action::quit) running = false;
    const double now = win.seconds();
    const double elapsed = now - last;
    last = now;
    if (elapsed > 0) fps = 0.9 * fps + 0.1 / elapsed;
    // With --frames, stop at exactly that frame whatever the display's speed.
    tb.advance(elapsed * 1000.0, frames.value_or(std::numeric_limits<std::int64_t>::max()));
    const double ms = win.render(tb.world(), tb.view(fps, draw_ms));
    draw_ms = draw_ms == 0.0 ? ms : 0.9 * draw_ms + 0.1 * ms;
    if (frames && tb.world().frame >= *frames) running = false;
    // The picture is taken before present(), which leaves the back buffer
    // undefined; a window closed early (Esc, Q, the close button) saves the
    // last frame shown rather than leaving the file empty.
    if (!running && !screenshot.empty()) {
      win.screenshot(screenshot);
      if (tb.world().frame < *frames)
        err << "game: --screenshot: the window was closed at frame " << tb.world().frame << ", before frame "
            << *frames << ": " << screenshot << " shows frame " << tb.world().frame << "\n";
    }
    win.present();
  }
}

// The testbed in a window. Fixed time step: the physics advances by dt
// whatever the display's rate, so a run does not depend on the machine.
int run_window(Cli::Session& s) {
  const Cli::Options& o = s.options;
  Testbed tb(s.scenes, s.current, o.overrides, o.overlays, Cli::world_maker(o));
  const SceneSpec& first = tb.scene();
  std::optional<Window> win;
  try {
    win.emplace(first.width, first.height, "physics - " + Headless::printable(first.name) + " (H: keys)");
  } catch (const WindowError& e) {
    throw Cli::NoWindow(e.what());
  }
  if (!win->hud_warning().empty()) *s.err << "warning: " << win->hud_warning() << "\n";
  tb.set_viewport({double(win->width()), double(win->height())});
  Cli::Recorder& rec = *s.recorder;
  rec.start(tb.world());
  tb.on_step = [&](const World& w) { rec.after_step(w); };
  tb.on_reset = [&](const World&) { rec.restart(tb.world()); };
  // --record: every event the testbed handles, with its tick; --replay: the
  // log's events at their ticks (live input then only quits).
  InputLog log{o.scene, {}, 0};
  if (!o.record.empty()) tb.record(&log);
  if (s.replay) tb.replay(*s.replay);
  std::optional<std::int64_t> frames = o.frames;
  if (!o.screenshot.empty() && !frames) frames = Cli::screenshot_frames;

  loop(tb, *win, frames, o.screenshot, *s.err);

  // The log is written whatever the end: a session that broke the physics
  // is the one worth replaying.
  if (!o.record.empty()) {
    log.end = tb.ticks();
    try {
      write_input_log(o.record, log);
    } catch (const std::runtime_error& e) {
      throw Cli::WriteError(std::string("--record: ") + e.what());  // exit code 4, as every output
    }
  }
  // Nothing is written as if it were fine after a non-finite state (exit 3,
  // as headless).
  if (tb.world().health.non_finite) {
    rec.abandon();
    *s.err << "game: " << Headless::non_finite_line(tb.world()) << "\n";
    return 3;
  }
  SceneSpec scene = tb.scene();
  apply(scene, o.overrides);
  rec.finish(tb.world(), scene, tb.roles());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  const Cli::WindowFrontEnd window{display_available, run_window};
  return Cli::run(args, std::cout, std::cerr, &window);
}
