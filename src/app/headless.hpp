// A run without a window: `frames` frames of Game::step, and the summary the
// command line prints (kinetic energy, momentum, time per stage).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <string_view>

#include "course/game.hpp"

namespace physics::Headless {

struct Summary {
  std::int64_t frames = 0;
  std::size_t bodies = 0, mobile = 0;
  double ke_start = 0, ke_end = 0;
  Vector p_start{}, p_end{};
};

// `after_step` (may be empty) sees the world after every frame: the trace.
Summary run(World& w, std::int64_t frames);
template <class AfterStep>
Summary run(World& w, std::int64_t frames, AfterStep&& after_step);
// The summary the command line prints after a headless run; `summary` is its
// text (the browser build, which links no stream, prints that: docs/web.md).
std::string summary(const World& w, const Summary& s, const std::string& why, const std::string& scene = "");
void print_summary(std::ostream& out, const World& w, const Summary& s, const std::string& why,
                   const std::string& scene = "");

// "forces 0.0012, move 0.0008, collision off, relax 0.12 ...": physics ms per
// step of each of the world's stages; `off` for the course systems the scene
// left out; the engine's stages only when the options that run them are on.
std::string stage_times(const World& w);

// What the health check found (engine/health.hpp), for the summary, the HUD
// and the command line: `non_finite_line` is the one-line error
// ("body 7 has a non-finite velocity (nan, 0) after frame 3", empty if none);
// `escape_line` is "0" or "2 (the first: body 12, by frame 40)"; `advice`
// says what was seen (deep overlaps that persist, bodies that left the
// world) and the options that stop it (--solver stable, --ccd on), or is empty.
std::string non_finite_line(const World& w);
std::string escape_line(const World& w);
std::string advice(const World& w);
// What --solver auto used over the run, for the summary.
std::string auto_line(const World& w);

// `text` (a scene's name or description, from a file) as it may go to a
// terminal: control characters (C0, DEL, C1 in UTF-8) as \xNN, so that an
// ANSI escape or a newline in a name cannot recolour the terminal nor forge
// a summary line; other bytes (UTF-8 text) as they are.
std::string printable(std::string_view text);

// The HUD line: fps, physics ms/step, body count, kinetic energy, momentum.
std::string hud_line(const World& w, double fps);

// The summary's measures, for whoever runs the frames (run() below, the
// replay of an input log): after the first frame, the motion the run starts
// with (bodies start at rest with their first impulse pending in sum_forces);
// at the end, the frames run, the bodies, the motion it ends with, and the
// escapes since the last count (of a finite world).
void start_measures(Summary& s, const World& w);
void end_measures(Summary& s, World& w, std::int64_t frames);

template <class AfterStep>
Summary run(World& w, std::int64_t frames, AfterStep&& after_step) {
  Summary s;
  for (std::int64_t f = 0; f < frames; ++f) {
    Game::step(w);
    if (!w.health.finite()) break;  // nothing more to run, nor to record as a frame
    after_step(static_cast<const World&>(w));
    if (f == 0) start_measures(s, w);
  }
  end_measures(s, w, w.health.finite() ? frames : w.frame);
  return s;
}

}  // namespace physics::Headless
