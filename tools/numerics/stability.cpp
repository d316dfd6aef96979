#include "numerics/stability.hpp"

#include <cmath>
#include <cstdio>

#include "course/game.hpp"
#include "course/system_defs.hpp"
#include "course/utils/random.hpp"

namespace physics::numerics {

namespace criteria {


int outside_walls(const World& w, Vector o) { return outside(w, o.x + 40, o.y + 40, o.x + 760, o.y + 560); }

// The energy the scene can trade: kinetic plus the potential of falling
// 600 px (the walls' height). Growth is measured against it, so that it does
// not depend on where the origin of y is.
double energy_in_play(const World& w) {
  double s = 0;
  const double g_abs = Vector::norm(w.params.gravity);
  for (std::size_t e = 0; e < w.components.size(); ++e) {
    const double m = w.components.mass[e];
    if (!std::isfinite(m)) continue;
    s += m * (0.5 * Vector::dot(w.components.velocity[e], w.components.velocity[e]) + g_abs * 600.0);
  }
  return s > 0 ? s : 1.0;
}

// Momentum drift relative to the momentum the bodies carry (Σ m|v|, not the
// total, which is 0 for two bodies meeting head on).
double momentum_scale(const World& w) {
  double s = 0;
  for (std::size_t e = 0; e < w.components.size(); ++e)
    if (std::isfinite(w.components.mass[e])) s += w.components.mass[e] * Vector::norm(w.components.velocity[e]);
  return s > 0 ? s : 1.0;
}
double drift(Vector a, Vector b, double scale) { return (std::abs(a.x - b.x) + std::abs(a.y - b.y)) / scale; }
std::string out_text(int n) { return n ? fmt(", %.0f out", n) : std::string(); }
// CCD that ran out of its impact budget stopped the scene for the rest of a
// substep: a pass earned that way is worth knowing.
// A cell passes only if CCD lost at most 1 % of the substeps that way: a
// scene that stands still because its time stopped has not been solved.
Outcome finish(bool pass, std::string figure, const World& w) {
  const auto capped = static_cast<double>(w.ccd.stats.capped_substeps);
  if (capped == 0) return {pass, figure};
  const double substeps = static_cast<double>(w.frame) * w.params.substeps;
  const bool lost = capped > 0.01 * substeps;
  return {pass && !lost, figure + fmt(", %.0f capped substeps", capped) + (lost ? " (time lost)" : "")};
}

// Tests only (Mode::stop_when_lost): a run of `frames` frames can stop once
// more than 1 % of its substeps are capped, since finish() then finds the
// same failure.
bool lost(const Mode& m, const World& w, int frames) {
  return m.stop_when_lost && static_cast<double>(w.ccd.stats.capped_substeps) > 0.01 * frames * w.params.substeps;
}

Track run(const Mode& m, World& w, int frames, bool with_walls, Vector wall_offset, int every,
          const std::function<void(const World&)>& each) {
  Track t;
  const double E0 = step_energy(w);
  const double play = energy_in_play(w);
  const Vector P0 = momentum(w);
  const double scale = momentum_scale(w);
  // (lost(): finish() would find the same failure at the end.)
  for (int f = 1; f <= frames; ++f) {
    Game::step(w);
    if (lost(m, w, frames)) break;
    if (each) each(w);
    if (f % every != 0 && f != frames) continue;
    if (!all_finite(w)) {
      t.finite = false;
      break;
    }
    t.max_overlap = std::max(t.max_overlap, max_overlap(w));
    t.energy_growth = std::max(t.energy_growth, (step_energy(w) - E0) / play);
    t.momentum_drift = std::max(t.momentum_drift, drift(momentum(w), P0, scale));
    if (with_walls) t.outside = std::max(t.outside, outside_walls(w, wall_offset));
  }
  return t;
}

Outcome nan_outcome() { return {false, "NaN/inf"}; }

}  // namespace criteria

namespace {

using namespace criteria;

constexpr double g = 0.001;  // px/ms²: a 500 px fall takes one second
constexpr Vector down{0, g};

// ---- mass ratios -----------------------------------------------------------

Outcome light_under_heavy(const Mode& m, double ratio) {
  World w = make_world(m, down);
  walls(w);
  block(w, 390, 540, 20, 20, 1.0);       // light, on the floor
  block(w, 380, 500, 40, 40, ratio);     // heavy, on the light one
  const Track t = run(m, w, 600, true);
  if (!t.finite) return nan_outcome();
  return finish(t.max_overlap < max_sink && t.outside == 0, fmt("sink %.3g px", t.max_overlap) + out_text(t.outside), w);
}

Outcome heavy_hits_light(const Mode& m, double ratio) {
  World w = make_world(m);
  block(w, 100, 100, 40, 40, ratio, {0.5, 0});
  block(w, 300, 110, 20, 20, 1.0);
  const Track t = run(m, w, 120, false);
  if (!t.finite) return nan_outcome();
  return {t.momentum_drift < momentum_tolerance && t.energy_growth < energy_tolerance,
          fmt("dp %.2g, dE %+.2g", t.momentum_drift, t.energy_growth)};
}

Outcome light_between_heavy(const Mode& m, double ratio) {
  World w = make_world(m);
  const EntityId a = block(w, 100, 100, 40, 40, ratio, {0.1, 0});
  const EntityId l = block(w, 200, 110, 20, 20, 1.0);
  const EntityId b = block(w, 300, 100, 40, 40, ratio, {-0.1, 0});
  bool order = true;
  Track t;
  const double E0 = step_energy(w);
  const double play = energy_in_play(w);
  const Vector P0 = momentum(w);
  const double scale = momentum_scale(w);
  for (int f = 0; f < 300 && t.finite; ++f) {
    Game::step(w);
    t.finite = all_finite(w);
    const auto& x = w.components.position;
    order = order && x[a].x < x[l].x && x[l].x < x[b].x;
    t.energy_growth = std::max(t.energy_growth, (step_energy(w) - E0) / play);
    t.momentum_drift = std::max(t.momentum_drift, drift(momentum(w), P0, scale));
  }
  if (!t.finite) return nan_outcome();
  return finish(order && t.momentum_drift < momentum_tolerance && t.energy_growth < energy_tolerance,
          std::string(order ? "order kept" : "passed through") + fmt(", dp %.2g, dE %+.2g", t.momentum_drift,
                                                                      t.energy_growth), w);
}

// ---- stacks ----------------------------------------------------------------

Outcome stack30(const Mode& m) {
  World w = make_world(m, down);
  walls(w);
  std::vector<EntityId> ids;
  for (int k = 0; k < 30; ++k) ids.push_back(block(w, 390, 560.0 - 15 * (k + 1), 20, 15, 1.0, {}, 0.5));
  std::vector<Vector> start;
  for (const EntityId e : ids) start.push_back(w.components.position[e]);
  const Track t = run(m, w, 3600, true, {}, 10);
  if (!t.finite) return nan_outcome();
  double moved = 0;
  for (std::size_t i = 0; i < ids.size(); ++i)
    moved = std::max(moved, Vector::norm(w.components.position[ids[i]] - start[i]));
  return finish(t.max_overlap < max_sink && moved < max_sink && t.outside == 0,
          fmt("sink %.3g px, moved %.3g px", t.max_overlap, moved) + out_text(t.outside), w);
}

// Box2D's large_pyramid, smaller (base 15: 120 blocks of 20 px), with
// friction 0.6 on every block and wall, for 20 s: does it stand, with what
// sink? (The bench runs the full one, base 100, against Box2D and Chipmunk.)
Outcome friction_pyramid(const Mode& m) {
  World w = make_world(m, down);
  walls(w);
  for (EntityId e = 0; e < w.components.size(); ++e) w.components.friction[e] = 0.6;
  std::vector<EntityId> ids;
  constexpr int base = 15, side = 20;
  const double x0 = 400.0 - base * side / 2.0;
  for (int i = 0; i < base; ++i)
    for (int j = i; j < base; ++j) {
      const EntityId e = block(w, x0 + side * (0.5 * i + (j - i)), 560.0 - side * (i + 1), side, side, 1.0, {}, 0.0);
      w.components.friction[e] = 0.6;
      ids.push_back(e);
    }
  const Vector top = w.components.position[ids.back()];
  const Track t = run(m, w, 1200, true, {}, 10);
  if (!t.finite) return nan_outcome();
  const double moved = Vector::norm(w.components.position[ids.back()] - top);
  return finish(t.max_overlap < max_sink && moved < max_sink && t.outside == 0,
          fmt("sink %.3g px, top moved %.3g px", t.max_overlap, moved) + out_text(t.outside), w);
}

Outcome high_mass_ratio(const Mode& m) {
  // Solver2D's "high mass ratio": a 20x20 box (mass by area: 400) dropped on
  // two 1x1 boxes (mass 1) lying on the floor under its corners.
  World w = make_world(m, down);
  walls(w);
  const EntityId s1 = block(w, 391, 559, 1, 1, 1.0);
  const EntityId s2 = block(w, 408, 559, 1, 1, 1.0);
  const EntityId big = block(w, 390, 450, 20, 20, 400.0, {}, 0.5);
  const Track t = run(m, w, 600, true);
  if (!t.finite) return nan_outcome();
  const auto& p = w.components.position;
  const bool on_top = p[big].y + 20 <= std::min(p[s1].y, p[s2].y) + max_sink;
  return finish(t.max_overlap < max_sink && on_top && t.outside == 0,
          fmt("sink %.3g px", t.max_overlap) + (on_top ? "" : ", fell through") + out_text(t.outside), w);
}

// ---- overlaps --------------------------------------------------------------

// Frames until the deepest overlap is below 0.01 px (or -1), within `limit`.
int frames_to_separate(World& w, int limit) {
  for (int f = 1; f <= limit; ++f) {
    Game::step(w);
    if (!all_finite(w)) return -2;
    if (max_overlap(w) < 0.01) return f;
  }
  return -1;
}

Outcome overlap25(const Mode& m) {
  World w = make_world(m);
  walls(w);
  block(w, 380, 280, 40, 40, 1.0);
  block(w, 410, 280, 40, 40, 1.0);  // 10 px of 40: 25 %
  const double E0 = step_energy(w);
  const int f = frames_to_separate(w, 30);
  if (f == -2) return nan_outcome();
  const double E = step_energy(w);
  return {f > 0 && E <= E0 + 1e-12, f > 0 ? fmt("%.0f frame(s)", f) : std::string("not within 30 frames")};
}

Outcome colocated(const Mode& m) {
  World w = make_world(m);
  walls(w);
  block(w, 380, 280, 40, 40, 1.0);
  block(w, 380, 280, 40, 40, 1.0);
  const int f = frames_to_separate(w, 30);
  if (f == -2) return nan_outcome();
  return {f > 0 && outside_walls(w) == 0, f > 0 ? fmt("%.0f frame(s)", f) : std::string("not within 30 frames")};
}

Outcome spawn_overlapping(const Mode& m) {
  World w = make_world(m);
  walls(w);
  Random rng(11);
  for (int i = 0; i < 10000; ++i) block(w, rng.uniform(40, 756), rng.uniform(40, 556), 4, 4, rng.uniform(1, 2));
  const double before = max_overlap(w);
  const Track t = run(m, w, 30, true, {}, 30);
  if (!t.finite) return nan_outcome();
  const double after = max_overlap(w);
  return {after < max_sink && t.outside == 0,
          fmt("overlap %.2g -> %.2g px", before, after) + out_text(t.outside)};
}

// ---- speed, size, position -------------------------------------------------

Outcome bullet(const Mode& m, double speed) {
  World w = make_world(m);
  walls(w);
  block(w, 400, 295, 10, 10, 1.0, {speed, 0});
  const Track t = run(m, w, 120, true);
  if (!t.finite) return nan_outcome();
  return finish(t.outside == 0, (t.outside ? std::string("tunnelled") : std::string("stayed in")), w);
}

// The cases the numerics issue (auto mode) adds, on today's modes.

// A block at 2000 px/ms towards a fixed wall 1 px thick inside the box (it
// bounces between that wall and the left one, e = 1): it must never be found
// beyond the thin wall.
Outcome bullet_thin_wall(const Mode& m) {
  World w = make_world(m);
  walls(w);
  const EntityId wall = block(w, 600, 40, 1, 520, infinity);
  const EntityId b = block(w, 300, 295, 10, 10, 1.0, {2000.0, 0});
  bool kept = true;
  for (int f = 0; f < 60; ++f) {
    Game::step(w);
    if (lost(m, w, 60)) break;
    kept = kept && w.components.position[b].x + 10 <= w.components.position[wall].x + 1e-9;
  }
  if (!all_finite(w)) return nan_outcome();
  return finish(kept && outside_walls(w, {}) == 0, kept ? "stayed on its side" : "passed through", w);
}

// Two blocks meeting head on at 1000 px/ms each, in the walled box.
Outcome bullets_head_on(const Mode& m) {
  World w = make_world(m);
  walls(w);
  const EntityId a = block(w, 200, 295, 10, 10, 1.0, {1000.0, 0});
  const EntityId b = block(w, 590, 295, 10, 10, 1.0, {-1000.0, 0});
  const double E0 = step_energy(w), play = energy_in_play(w);
  bool order = true;
  double growth = 0;
  for (int f = 0; f < 60; ++f) {
    Game::step(w);
    if (lost(m, w, 60)) break;
    order = order && w.components.position[a].x < w.components.position[b].x;
    growth = std::max(growth, (step_energy(w) - E0) / play);
  }
  if (!all_finite(w)) return nan_outcome();
  const int out = outside_walls(w, {});
  return finish(order && out == 0 && growth < energy_tolerance,
                std::string(order ? "order kept" : "passed through") + fmt(", dE %+.2g", growth) + out_text(out), w);
}

// A block of mass 1e9 dropped at 50 px/ms onto the 30-block stack: no
// pass-through, and once it has settled (the last 5 s of 10) no sink.
Outcome heavy_drop_on_stack(const Mode& m) {
  World w = make_world(m, down);
  walls(w);
  EntityId top = 0;
  for (int k = 0; k < 30; ++k) top = block(w, 390, 560.0 - 15 * (k + 1), 20, 15, 1.0, {}, 0.0);
  const EntityId heavy = block(w, 390, 60, 20, 20, 1e9, {0, 50.0}, 0.0);
  Track settle = run(m, w, 300, true);
  bool above = w.components.position[heavy].y + 20 <= w.components.position[top].y + max_sink;
  if (settle.finite) settle = run(m, w, 300, true);
  above = above && w.components.position[heavy].y + 20 <= w.components.position[top].y + max_sink;
  if (!settle.finite) return nan_outcome();
  return finish(above && settle.max_overlap < max_sink && settle.outside == 0,
                std::string(above ? "stayed on top" : "passed through") + fmt(", sink %.3g px", settle.max_overlap) +
                    out_text(settle.outside),
                w);
}

// Box2D's large_pyramid at full size (base 100: 5050 blocks of 10 px, e = 0)
// on a fixed floor, for 60 s: the top block must not move 1 px, nothing sink
// 1 px. A run stops as soon as its cell has failed (the figure then says
// when), and a run with CCD at its first capped substep, counted as failed.
// CCD alone is not run: its first substep alone takes 20-40 s here (80 000
// impacts, each predicted again against every body) before it is capped,
// and it fails every pile above (the 30-stack, the 120-block pyramid).
Outcome pyramid5050(const Mode& m) {
  if (m.ccd && m.solver == Solver::course)
    return {false, "not run: CCD alone caps its first substep (20-40 s at 5050 bodies), as on every pile above"};
  World w = make_world(m, down);
  block(w, 0, 1100, 1200, 40, infinity, {}, 0.0);  // the floor
  constexpr int base = 100, side = 10;
  EntityId top = 0;
  for (int i = 0; i < base; ++i)
    for (int j = i; j < base; ++j)
      top = block(w, 100 + side * (0.5 * i + (j - i)), 1100.0 - side * (i + 1), side, side, 1.0, {}, 0.0);
  const Vector start = w.components.position[top];
  constexpr int frames = 3600;
  double sink = 0, moved = 0;
  int f = 0;
  while (f < frames && sink < max_sink && moved < max_sink) {
    Game::step(w);
    ++f;
    if (w.ccd.stats.capped_substeps > 0) break;
    if (f % 30 != 0 && f != frames) continue;
    if (!all_finite(w)) return nan_outcome();
    sink = std::max(sink, max_overlap(w));
    moved = Vector::norm(w.components.position[top] - start);
  }
  const std::string when = f < frames ? fmt(" (stopped at %.0f s)", f * w.params.dt / 1000.0) : std::string();
  const bool capped = w.ccd.stats.capped_substeps > 0;
  return {f == frames && !capped && sink < max_sink && moved < max_sink,
          fmt("sink %.3g px, top moved %.3g px", sink, moved) + when + (capped ? ", capped (time lost)" : "")};
}

// A block launched at 0.5 px/ms along the floor, friction 0.5 on both, under
// g = 0.001 px/ms²: it stops after v0²/(2 mu g) = 250 px (within 3 %).
Outcome friction_slide(const Mode& m) {
  World w = make_world(m, down);
  walls(w);
  for (EntityId e = 0; e < w.components.size(); ++e) w.components.friction[e] = 0.5;
  const EntityId b = block(w, 100, 540, 20, 20, 1.0, {0.5, 0}, 0.0);
  w.components.friction[b] = 0.5;
  const Track t = run(m, w, 180, true);
  if (!t.finite) return nan_outcome();
  const double d = w.components.position[b].x - 100.0, exact = 0.25 / (2 * 0.5 * g);
  const bool stopped = std::abs(w.components.velocity[b].x) < 1e-9;
  return finish(stopped && std::abs(d - exact) < 0.03 * exact && t.outside == 0,
                fmt("stopped after %.5g px (exact %.4g)", d, exact) + (stopped ? "" : ", still sliding") +
                    out_text(t.outside),
                w);
}

// Ten blocks stacked on the floor, friction 0.5 everywhere, the bottom one
// pushed sideways by a fixed block moving at 0.01 px/ms for 3 s: the tower
// must slide as one piece (every block within 1 px of the bottom one's
// displacement, which follows the pusher), nothing sink 1 px.
Outcome friction_tower(const Mode& m) {
  World w = make_world(m, down);
  walls(w);
  for (EntityId e = 0; e < w.components.size(); ++e) w.components.friction[e] = 0.5;
  std::vector<EntityId> ids;
  for (int k = 0; k < 10; ++k) {
    ids.push_back(block(w, 100, 560.0 - 20 * (k + 1), 20, 20, 1.0, {}, 0.0));
    w.components.friction[ids.back()] = 0.5;
  }
  const EntityId pusher = block(w, 80, 540, 20, 20, infinity, {0.01, 0}, 0.0);
  std::vector<Vector> start;
  for (const EntityId e : ids) start.push_back(w.components.position[e]);
  const Track t = run(m, w, 180, true, {}, 10);
  if (!t.finite) return nan_outcome();
  const double base = w.components.position[ids[0]].x - start[0].x;
  double apart = 0;
  for (std::size_t i = 0; i < ids.size(); ++i)
    apart = std::max(apart, Vector::norm(w.components.position[ids[i]] - start[i] - Vector{base, 0}));
  const double pushed = w.components.position[pusher].x - 80.0;
  return finish(apart < max_sink && base > 0.9 * pushed && t.max_overlap < max_sink && t.outside == 0,
                fmt("moved %.3g px (pusher %.3g), ", base, pushed) + fmt("apart %.3g px, sink %.3g px", apart,
                                                                         t.max_overlap) + out_text(t.outside),
                w);
}

// The question-9 scene, its blocks' restitution set to e.
void q9(World& w, double e) {
  Game::init_scene(w);
  for (std::size_t k = 4; k < w.components.size(); ++k) w.components.restitution[k] = e;
  Game::step(w);  // the initial forces become velocities
}

Outcome far_coordinates(const Mode& m) {
  // The question-9 scene, moved 1e7 px away from the origin.
  const Vector o{1e7, 1e7};
  World w = make_world(m);
  q9(w, 1.0);
  for (auto& p : w.components.position) p = p + o;
  const Track t = run(m, w, 3000, true, o);
  if (!t.finite) return nan_outcome();
  return finish(t.outside == 0 && t.energy_growth < energy_tolerance,
          fmt("dE %+.2g", t.energy_growth) + out_text(t.outside), w);
}

Outcome one_pixel(const Mode& m) {
  World w = make_world(m);
  walls(w);
  Random rng(5);
  for (int i = 0; i < 200; ++i)
    block(w, 60 + 34.0 * (i % 20), 60 + 48.0 * (i / 20), 1, 1, rng.uniform(1, 5),
          {rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5)});
  const Track t = run(m, w, 600, true);
  if (!t.finite) return nan_outcome();
  return finish(t.outside == 0 && t.energy_growth < energy_tolerance,
          fmt("dE %+.2g", t.energy_growth) + out_text(t.outside), w);
}

Outcome corner_hits(const Mode& m) {
  World w = make_world(m);
  walls(w);
  // Into the bottom-right corner: 5 px into both walls after the same frame.
  const double v = 0.6, step = v * w.params.dt;
  block(w, 720 - step + 5, 520 - step + 5, 40, 40, 1.0, {v, v});
  // Two blocks meeting corner to corner, equal penetration on both axes.
  block(w, 100, 100, 40, 40, 2.0, {0.3, 0.3});
  block(w, 150, 150, 40, 40, 2.0, {-0.3, -0.3});
  const Track t = run(m, w, 600, true);
  if (!t.finite) return nan_outcome();
  return finish(t.outside == 0 && t.energy_growth < energy_tolerance,
          fmt("dE %+.2g", t.energy_growth) + out_text(t.outside), w);
}

Outcome long_run(const Mode& m, double e) {
  World w = make_world(m, down);
  q9(w, e);
  const Track t = run(m, w, 100000, true, {}, 10);
  if (!t.finite) return nan_outcome();
  return finish(t.outside == 0 && t.energy_growth < energy_tolerance,
          fmt("dE %+.2g", t.energy_growth) + out_text(t.outside), w);
}

}  // namespace

std::vector<StabilityCase> stability_cases() {
  std::vector<StabilityCase> cases;
  const std::string no_nan = "no NaN/inf";
  for (const double r : {1e3, 1e6, 1e9, 1e12}) {
    const std::string tag = fmt("%.0e", r);
    cases.push_back({"light under heavy " + tag, "max sink < 1 px, " + no_nan, false,
                     [r](const Mode& m) { return light_under_heavy(m, r); }});
    cases.push_back({"heavy hits light " + tag, "momentum drift < 1e-12, energy never grows", false,
                     [r](const Mode& m) { return heavy_hits_light(m, r); }});
    cases.push_back({"light between heavy " + tag, "no pass-through, momentum drift < 1e-12, energy never grows",
                     false, [r](const Mode& m) { return light_between_heavy(m, r); }});
  }
  cases.push_back({"30-block stack, 60 s", "max sink < 1 px and no block moves 1 px", true, stack30});
  cases.push_back({"20x20 on two 1x1 (Solver2D)", "max sink < 1 px, big block stays on top", false, high_mass_ratio});
  cases.push_back({"120-block pyramid, friction 0.6, 20 s", "max sink < 1 px, top block moves < 1 px", true,
                   friction_pyramid});
  cases.push_back({"5050-block pyramid, 60 s", "max sink < 1 px, top block moves < 1 px", true, pyramid5050});
  cases.push_back({"friction slide to rest", "stop distance within 3 % of v0²/(2 mu g)", false, friction_slide});
  cases.push_back({"10-block friction tower pushed at its base", "slides as one piece (1 px), sink < 1 px", false,
                   friction_tower});
  cases.push_back({"25 % overlap", "overlap < 0.01 px within 30 frames, energy not grown", false, overlap25});
  for (const double v : {10.0, 100.0, 1000.0})
    cases.push_back({fmt("bullet %.0f px/ms", v), "never leaves the walls (40 px)", false,
                     [v](const Mode& m) { return bullet(m, v); }});
  cases.push_back({"bullet 2000 px/ms, 1 px wall", "never beyond the 1 px wall", false, bullet_thin_wall});
  cases.push_back({"bullets head on, 1000 px/ms each", "order kept, none outside, energy never grows", false,
                   bullets_head_on});
  cases.push_back({"1e9 block at 50 px/ms on the 30-stack", "stays on top, sink < 1 px over the last 5 s", true,
                   heavy_drop_on_stack});
  cases.push_back({"coordinates ~1e7 px", "none outside the walls, energy never grows", false, far_coordinates});
  cases.push_back({"1 px blocks", "none outside the walls, energy never grows", false, one_pixel});
  cases.push_back({"two co-located blocks", "separated within 30 frames", false, colocated});
  cases.push_back({"corner hits", "none outside the walls, energy never grows", false, corner_hits});
  cases.push_back({"e = 0, 1e5 frames, gravity", "none outside, step energy never grows", true,
                   [](const Mode& m) { return long_run(m, 0.0); }});
  cases.push_back({"e = 1, 1e5 frames, gravity", "none outside, step energy never grows", true,
                   [](const Mode& m) { return long_run(m, 1.0); }});
  cases.push_back({"10 000 bodies spawned overlapping", "max overlap < 1 px after 30 frames, none outside", true,
                   spawn_overlapping});
  return cases;
}

std::string shock_ablation() {
  std::string md =
      "| iterations | shock propagation | ratio 1e1 | ratio 1e2 | ratio 1e3 | ratio 1e6 | ratio 1e12 |\n"
      "|---|---|---|---|---|---|---|\n";
  for (const int it : {8, 32, 128})
    for (const bool shock : {false, true}) {
      md += "| " + std::to_string(it) + " | " + (shock ? "on" : "off") + " |";
      for (const double r : {1e1, 1e2, 1e3, 1e6, 1e12}) {
        // One substep per frame of what Game::step does with the stable solver, with the
        // solver's settings at hand.
        World w = make_world(Mode{"stable", 1, false, Solver::stable, it}, down);
        walls(w);
        block(w, 390, 540, 20, 20, 1.0);
        block(w, 380, 500, 40, 40, r);
        SolverSettings settings;
        settings.iterations = it;
        settings.shock_propagation = shock;
        ContactSolver solver;
        BroadPhase broadphase;
        StageTimes times;
        const double h = w.params.dt;
        double sink = 0;
        for (int f = 0; f < 600; ++f) {
          Systems(w).forces->update(w.components, h, w.params.gravity);
          solver.solve_velocities(w.components, w.bodies(SystemId::collision), h, w.params.gravity, settings,
                                  broadphase, times);
          Systems(w).move->update(w.components, h);
          solver.solve_positions(w.components, w.bodies(SystemId::collision), w.params.gravity, settings, broadphase,
                                 times);
          sink = std::max(sink, max_overlap(w));
        }
        md += fmt(" %.3g px |", sink);
      }
      md += "\n";
    }
  return md;
}

bool expected_to_fail(const std::string& c, const std::string& m) {
  const auto is = [&](const char* prefix) { return c.rfind(prefix, 0) == 0; };
  if (m == "course")  // the sheet's one pass: what these options are for
    return is("light under heavy") || is("light between heavy") || is("30-block") || is("20x20") ||
           is("120-block") || is("bullet") || is("1 px") || is("e = 1") || is("10 000") || is("1e9 block") ||
           is("5050") || is("10-block");
  if (m == "substeps16")  // smaller steps: helps at 1e3 and 10 px/ms, not beyond
    return (is("light under heavy") && c != "light under heavy 1e+03") ||
           (is("light between heavy") && c != "light between heavy 1e+03") || is("30-block") || is("20x20") ||
           c == "bullet 100 px/ms" || c == "bullet 1000 px/ms" || is("bullet 2000") || is("bullets head on") ||
           is("10 000") || is("1e9 block") || is("5050") || is("10-block");
  // CCD alone has no resting contact: a body pressed on another under
  // gravity needs impacts without end (about π·sqrt(M/m) each substep: at
  // 1e3, 100, which the budget holds) and CCD stops the scene's time when its
  // budget runs out. (A light body squeezed between two heavy ones without
  // gravity takes them once, ~3 million at 1e12, which the budget for
  // lossless impacts holds.) (And the 10 000 case is not run: its discrete
  // pass is the course's all-pairs one.)
  if (m == "ccd")
    return (is("light under heavy") && c != "light under heavy 1e+03") || is("30-block") || is("120-block") ||
           is("20x20") || is("e = 0") || is("10 000") || is("1e9 block") || is("5050") || is("10-block");
  if (m == "stable")  // no CCD: 1.7 km per frame at 100 px/ms
    return c == "bullet 100 px/ms" || c == "bullet 1000 px/ms" || is("bullet 2000") || is("bullets head on");
  // With CCD on, impacts are CCD's: the 1e9 block landing on the 30-stack
  // makes impacts without end down the stack each substep.
  if (m == "stable+ccd") return is("1e9 block");
  return false;
}

}  // namespace physics::numerics
