#include "numerics/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "course/utils/random.hpp"

namespace physics::numerics {

namespace {
constexpr double g = 0.001;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

std::string fraction(double dt) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "dt=1000/%.0f", 1000.0 / dt);
  return buf;
}
}  // namespace

std::vector<Scenario> report_scenarios() {
  std::vector<Scenario> s;
  s.push_back({"projectile", 2000, {0, g}, true, 4, [](World& w) {
                 walls(w);
                 block(w, 60, 400, 10, 10, 1.0, {0.3, -0.6});
               }});
  // The projectile up to just before it lands (at 1412 ms): free flight, no
  // event, where the exact integrator's error is rounding at every dt.
  s.push_back({"free flight", 1400, {0, g}, true, 4, [](World& w) {
                 walls(w);
                 block(w, 60, 400, 10, 10, 1.0, {0.3, -0.6});
               }});
  s.push_back({"bounce e=0.5", 4000, {0, g}, true, 4, [](World& w) {
                 walls(w);
                 block(w, 390, 100, 20, 20, 1.0, {}, 0.5);
               }});
  s.push_back({"two-body", 1000, {}, false, 0, [](World& w) {
                 block(w, 100, 100, 40, 40, 3.0, {0.4, 0.05}, 0.8);
                 block(w, 300, 110, 20, 30, 7.0, {-0.2, 0}, 0.8);
               }});
  s.push_back({"cradle", 1000, {}, false, 0, [](World& w) {
                 block(w, 100, 100, 20, 20, 1.0, {0.5, 0});
                 for (int k = 0; k < 4; ++k) block(w, 200 + 20 * k, 100, 20, 20, 1.0);
               }});
  s.push_back({"gas 50 (e=1)", 2000, {}, true, -1, [](World& w) {
                 walls(w);
                 Random rng(2024);
                 for (int i = 0; i < 50; ++i)
                   block(w, 60 + 70.0 * (i % 10), 60 + 95.0 * (i / 10), rng.uniform_int(10, 30), rng.uniform_int(10, 30),
                         rng.uniform(1, 10), {rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3)});
               }});
  s.push_back({"box on stack", 3000, {0, g}, true, 9, [](World& w) {
                 walls(w);
                 for (int k = 0; k < 5; ++k) block(w, 390, 540.0 - 20 * k, 20, 20, 1.0, {}, 0.5);
                 block(w, 392, 200, 20, 20, 1.0, {}, 0.5);
               }});
  s.push_back({"bullet 5 px/ms", 1000, {}, true, 4, [](World& w) {
                 walls(w);
                 block(w, 100, 295, 10, 10, 1.0, {5.0, 0.7});
               }});
  return s;
}

std::vector<Setting> report_settings() {
  std::vector<Setting> out;
  for (const double hz : {60.0, 120.0, 240.0, 480.0}) {
    Mode m{"course", 1, false, Solver::course, 8, 1000.0 / hz};
    out.push_back({"course (dt)", m, fraction(m.dt)});
  }
  for (const int k : {2, 4, 8, 16}) out.push_back({"substeps", Mode{"substeps", k}, "K=" + std::to_string(k)});
  for (const int k : {1, 2, 4, 8, 16})
    out.push_back({"ccd (substeps)", Mode{"ccd", k, true}, "K=" + std::to_string(k)});
  for (const int it : {1, 2, 4, 8, 16, 32})
    out.push_back({"stable (iterations)", Mode{"stable", 1, false, Solver::stable, it}, "it=" + std::to_string(it)});
  for (const int k : {1, 4, 16})
    out.push_back({"stable+ccd (substeps)", Mode{"stable+ccd", k, true, Solver::stable, 8}, "K=" + std::to_string(k)});
  // The exact integrator (--integrator exact) on the course pass and on the
  // stable solver, over the same dt as the course family.
  for (const Solver solver : {Solver::course, Solver::stable})
    for (const double hz : {60.0, 120.0, 240.0, 480.0}) {
      const bool stable = solver == Solver::stable;
      Mode m{stable ? "stable+exact" : "course+exact", 1, false, solver, 8, 1000.0 / hz};
      m.integrator = Integrator::exact;
      out.push_back({m.name + " (dt)", m, fraction(m.dt)});
    }
  // --solver auto (engine/auto_mode.hpp), over the same dt.
  for (const double hz : {60.0, 120.0, 240.0, 480.0}) {
    Mode m{"auto", 1, false, Solver::automatic, 8, 1000.0 / hz};
    out.push_back({"auto (dt)", m, fraction(m.dt)});
  }
  return out;
}

std::vector<reference::Body> reference_bodies(const World& w) {
  std::vector<reference::Body> out;
  const Components& k = w.components;
  for (std::size_t e = 0; e < k.size(); ++e)
    out.push_back({k.position[e], k.velocity[e], static_cast<double>(k.box[e].width),
                   static_cast<double>(k.box[e].height), k.mass[e], k.restitution[e]});
  return out;
}

namespace {

double energy_of(const std::vector<Vector>& p, const std::vector<Vector>& v, const std::vector<double>& m, Vector grav) {
  double E = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (std::isfinite(m[i])) E += m[i] * (0.5 * Vector::dot(v[i], v[i]) - Vector::dot(grav, p[i]));
  return E;
}

// x-order inversions between two sets of positions (finite bodies).
int inversions(const std::vector<Vector>& a, const std::vector<Vector>& b, const std::vector<double>& m) {
  int n = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = i + 1; j < a.size(); ++j) {
      if (!std::isfinite(m[i]) || !std::isfinite(m[j])) continue;
      if ((a[i].x < a[j].x) != (b[i].x < b[j].x)) ++n;
    }
  return n;
}

}  // namespace

Errors measure(const Scenario& s, const Mode& mode) {
  World w = make_world(mode, s.gravity);
  s.build(w);
  const Components& k = w.components;
  const std::size_t n = k.size();
  const std::vector<double> mass = k.mass;
  const double dt = mode.dt;
  const auto frames = static_cast<int>(std::lround(s.t_end / dt));

  // Sample frames: a quarter, half, three quarters and all of the run.
  std::vector<int> samples;
  for (int q = 1; q <= 4; ++q) samples.push_back(std::max(1, frames * q / 4));

  // The reference, at the same sample times.
  reference::EventSim ref(reference_bodies(w), s.gravity, frames * dt);
  double ref_first = nan;

  double E_scale = 0, P_scale = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(mass[i])) continue;
    E_scale += mass[i] * (0.5 * Vector::dot(k.velocity[i], k.velocity[i]) + Vector::norm(s.gravity) * 600.0);
    P_scale += mass[i] * Vector::norm(k.velocity[i]);
  }
  if (P_scale == 0) P_scale = 1;

  Errors err;
  err.first_impact = nan;
  double sq = 0;
  int count = 0;
  std::size_t next = 0;
  std::vector<Vector> v_before(n);
  const auto involved = [&](std::size_t i) { return s.tracked < 0 ? std::isfinite(mass[i]) : i == static_cast<std::size_t>(s.tracked); };
  for (int f = 1; f <= frames; ++f) {
    for (std::size_t i = 0; i < n; ++i) v_before[i] = k.velocity[i];
    Game::step(w);
    // First impact: a velocity that is not free flight's v + g·dt.
    if (std::isnan(err.first_impact)) {
      for (std::size_t i = 0; i < n; ++i) {
        if (!involved(i)) continue;
        const Vector want = v_before[i] + dt * s.gravity;
        const Vector got = k.velocity[i];
        if (std::abs(got.x - want.x) + std::abs(got.y - want.y) > 1e-9 * (1 + Vector::norm(want))) {
          err.first_impact = f * dt;
          break;
        }
      }
    }
    err.max_penetration = std::max(err.max_penetration, max_overlap(w));
    if (s.walled) err.tunnelled = std::max(err.tunnelled, outside(w, 40, 40, 760, 560));
    if (next < samples.size() && f == samples[next]) {
      ref.advance_to(f * dt);
      const auto& rb = ref.bodies();
      std::vector<Vector> rp(n), rv(n);
      for (std::size_t i = 0; i < n; ++i) rp[i] = rb[i].p, rv[i] = rb[i].v;
      for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(mass[i])) continue;
        const Vector d = k.position[i] - rp[i];
        sq += Vector::dot(d, d);
        ++count;
      }
      const double E = energy_of(k.position, k.velocity, mass, s.gravity);
      const double Er = energy_of(rp, rv, mass, s.gravity);
      err.energy = std::max(err.energy, std::abs(E - Er) / E_scale);
      const Vector P = w.momentum(), Pr = ref.momentum();
      err.momentum = std::max(err.momentum, (std::abs(P.x - Pr.x) + std::abs(P.y - Pr.y)) / P_scale);
      if (!s.walled) err.tunnelled = std::max(err.tunnelled, inversions(k.position, rp, mass));
      ++next;
    }
  }
  for (const auto& ev : ref.events()) {
    const bool mine = s.tracked < 0 ? true
                                    : (ev.i == static_cast<std::uint32_t>(s.tracked) ||
                                       ev.j == static_cast<std::uint32_t>(s.tracked));
    if (mine) {
      ref_first = ev.t;
      break;
    }
  }
  err.pos_rms = count ? std::sqrt(sq / count) : 0.0;
  err.first_impact = err.first_impact - ref_first;  // NaN when either has none
  err.capped = w.ccd.stats.capped_substeps;
  if (!all_finite(w)) err.pos_rms = std::numeric_limits<double>::infinity();
  return err;
}

}  // namespace physics::numerics
