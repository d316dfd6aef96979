#include "reference/event_sim.hpp"

#include "engine/contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace physics::reference {

namespace {

constexpr Vector axis_normal[4] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};

double comp(Vector v, int a) { return a == 0 ? v.x : v.y; }

// Roots of A u² + B u + C in (0, H], appended to out (numerically stable form).
void roots_in(double A, double B, double C, double H, std::vector<double>& out) {
  const auto keep = [&](double u) {
    if (u > 0.0 && u <= H) out.push_back(u);
  };
  if (A == 0.0) {
    if (B != 0.0) keep(-C / B);
    return;
  }
  const double disc = B * B - 4.0 * A * C;
  if (disc < 0.0) return;
  const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
  keep(q / A);
  if (q != 0.0) keep(C / q);
}

}  // namespace

EventSim::EventSim(std::vector<Body> bodies, Vector gravity, double t_end, Options o)
    : bodies_(std::move(bodies)), g_(gravity), t_end_(t_end), opt_(o) {
  if (g_.x != 0.0 && g_.y != 0.0) throw std::invalid_argument("reference: gravity must be along an axis");
  support_.assign(bodies_.size(), -1);
  version_.assign(bodies_.size(), 0);
  for (std::size_t i = 0; i < bodies_.size(); ++i)
    for (std::size_t j = i + 1; j < bodies_.size(); ++j) {
      if (!finite(i) && !finite(j)) continue;
      Hit hit;
      if (predict_pair(i, j, hit))
        queue_.push(Queued{hit.t, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j), 0, 0});
    }
}

// A relative speed this small next to the bodies' own is what rounding left
// of an impulse that zeroed it: taken as zero, or the pair would meet again
// and again at the same instant (an inelastic collapse in a touching column
// drives speeds down geometrically: the absolute part ends it).
double EventSim::speed_floor(const Body& a, const Body& b) const {
  return 1e-3 * opt_.rest_speed + 1e-12 * (std::abs(a.v.x) + std::abs(a.v.y) + std::abs(b.v.x) + std::abs(b.v.y));
}

bool EventSim::finite(std::size_t i) const { return std::isfinite(bodies_[i].m); }

Vector EventSim::accel(std::size_t i) const {
  if (!finite(i) || support_[i] >= 0) return {};  // resting: the support carries the weight
  return g_;
}

// First time in [now, t_end] at which the boxes of i and j start to overlap
// while approaching, with the axis they meet on.
bool EventSim::predict_pair(std::size_t i, std::size_t j, Hit& out) const {
  const Body& bi = bodies_[i];
  const Body& bj = bodies_[j];
  const double H = t_end_ - now_;
  // Minkowski box s = j ⊖ i along each axis: s(u) = s0 + d·u + a·u²/2, size W.
  const Vector ai = accel(i), aj = accel(j);
  const double s0[2] = {bj.p.x - bi.p.x - bi.w, bj.p.y - bi.p.y - bi.h};
  const double W[2] = {bi.w + bj.w, bi.h + bj.h};
  const double floor = speed_floor(bi, bj);
  const auto clean = [&](double x) { return std::abs(x) <= floor ? 0.0 : x; };
  const double d[2] = {clean(bj.v.x - bi.v.x), clean(bj.v.y - bi.v.y)};
  const double a[2] = {aj.x - ai.x, aj.y - ai.y};
  const auto s_at = [&](int ax, double u) { return s0[ax] + d[ax] * u + 0.5 * a[ax] * u * u; };
  const auto inside_axis = [&](int ax, double u) {
    const double s = s_at(ax, u);
    return s < 0.0 && 0.0 < s + W[ax];
  };
  const auto inside = [&](double u) { return inside_axis(0, u) && inside_axis(1, u); };
  const auto rel_speed = [&](int axis, double u) {  // (v_i - v_j)·n at now + u
    const int ax = axis / 2;
    const double vn = -(d[ax] + a[ax] * u);
    return axis % 2 == 0 ? -vn : vn;
  };

  std::vector<double> r{0.0, H};
  for (int ax = 0; ax < 2; ++ax) {
    roots_in(0.5 * a[ax], d[ax], s0[ax], H, r);
    roots_in(0.5 * a[ax], d[ax], s0[ax] + W[ax], H, r);
  }
  std::sort(r.begin(), r.end());
  r.erase(std::unique(r.begin(), r.end()), r.end());

  if (inside(0.0)) {
    // Overlapping now (rounding after an event, or a scene that starts so):
    // an impact now if approaching along the shortest way out, else wait for
    // the next entry.
    int best = 0;
    double best_gap = -std::numeric_limits<double>::infinity();
    const double gaps[4] = {s0[0], -(s0[0] + W[0]), s0[1], -(s0[1] + W[1])};
    for (int k = 0; k < 4; ++k)
      if (gaps[k] > best_gap) best = k, best_gap = gaps[k];
    if (rel_speed(best, 0.0) < 0.0) {
      out = {now_, best};
      return true;
    }
  }
  bool was_inside = inside(0.0);
  double prev = 0.0;
  for (std::size_t k = 0; k + 1 < r.size(); ++k) {
    const double mid = 0.5 * (r[k] + r[k + 1]);
    const bool in = inside(mid);
    if (in && !was_inside) {
      // The axis that was not yet overlapping is the one they meet on (x on a tie).
      const int ax = !inside_axis(0, prev) ? 0 : 1;
      const int axis = 2 * ax + (s_at(ax, prev) >= 0.0 ? 0 : 1);
      if (rel_speed(axis, r[k]) <= 0.0) {
        out = {now_ + r[k], axis};
        return true;
      }
    }
    was_inside = in;
    prev = mid;
  }
  return false;
}

// When a resting body stops overlapping its support across gravity (it slid off).
double EventSim::slide_off_time(std::size_t i) const {
  const int s = support_[i];
  const int ax = g_.x != 0.0 ? 1 : 0;  // the axis across gravity
  const Body& b = bodies_[i];
  const Body& sp = bodies_[static_cast<std::size_t>(s)];
  const double bw = ax == 0 ? b.w : b.h, sw = ax == 0 ? sp.w : sp.h;
  const double d = comp(sp.v, ax) - comp(b.v, ax);  // no acceleration across gravity
  double u = std::numeric_limits<double>::infinity();
  if (d > 0.0) u = (comp(b.p, ax) + bw - comp(sp.p, ax)) / d;
  if (d < 0.0) u = (comp(b.p, ax) - comp(sp.p, ax) - sw) / d;
  return now_ + std::max(u, 0.0);
}

void EventSim::predict_body(std::size_t i) {
  for (std::size_t j = 0; j < bodies_.size(); ++j) {
    if (j == i || (!finite(i) && !finite(j))) continue;
    const std::size_t a = std::min(i, j), b = std::max(i, j);
    Hit hit;
    if (predict_pair(a, b, hit))
      queue_.push(Queued{hit.t, static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b), version_[a],
                         version_[b]});
  }
  if (support_[i] >= 0) {
    const double t = slide_off_time(i);
    if (t <= t_end_)
      queue_.push(Queued{t, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(i), version_[i], version_[i]});
  }
}

void EventSim::move_all_to(double t) {
  const double u = t - now_;
  if (u <= 0.0) return;
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    Body& b = bodies_[i];
    const Vector a = accel(i);
    b.p = b.p + u * b.v + (0.5 * u * u) * a;
    b.v = b.v + u * a;
  }
  now_ = t;
}

void EventSim::free_body(std::size_t i) {
  support_[i] = -1;
  ++version_[i];
  for (std::size_t k = 0; k < bodies_.size(); ++k)
    if (support_[k] == static_cast<int>(i)) free_body(k);
}

void EventSim::resolve(std::size_t i, std::size_t j, int axis) {
  const Vector n = axis_normal[axis];
  Body& bi = bodies_[i];
  Body& bj = bodies_[j];
  double vn = Vector::dot(bi.v - bj.v, n);
  if (std::abs(vn) <= speed_floor(bi, bj)) vn = 0.0;  // touching, not hitting: no impulse
  const double e = std::min(bi.e, bj.e);
  const double dv = -(1.0 + e) * vn;
  const Vector vi0 = bi.v, vj0 = bj.v;
  change_normal_velocity(bi.v, bj.v, n, dv, inverse_mass(bi.m), inverse_mass(bj.m));  // the engine's law
  // A resting body that an impulse reaches is free again, and so is what rests on it.
  if (!(bi.v == vi0) && support_[i] >= 0) free_body(i);
  if (!(bj.v == vj0) && support_[j] >= 0) free_body(j);

  // Resting: the upper body leaves a fixed or resting support too slowly to
  // ever get away (gravity brings it back at once): put it at rest on it.
  const double ng = Vector::dot(n, g_);
  if (ng == 0.0) return;
  const std::size_t upper = ng < 0.0 ? i : j, lower = ng < 0.0 ? j : i;
  if (!finite(upper) || (finite(lower) && support_[lower] < 0)) return;
  const double leave = std::abs(Vector::dot(bi.v - bj.v, n));
  if (leave > opt_.rest_speed) return;
  Body& up = bodies_[upper];
  const Body& low = bodies_[lower];
  if (g_.x != 0.0) up.v.x = low.v.x;
  else up.v.y = low.v.y;
  support_[upper] = static_cast<int>(lower);
}

void EventSim::advance_to(double t) {
  if (t > t_end_) throw std::invalid_argument("reference: advance_to past t_end");
  while (!queue_.empty() && queue_.top().t <= t) {
    const Queued ev = queue_.top();
    queue_.pop();
    if (ev.vi != version_[ev.i] || ev.vj != version_[ev.j]) continue;
    if (static_cast<std::int64_t>(log_.size()) >= opt_.max_events)
      throw std::runtime_error("reference: too many events (inelastic collapse?)");
    if (ev.i == ev.j) {  // slid off its support
      move_all_to(std::max(ev.t, now_));
      free_body(ev.i);
      predict_body(ev.i);
      continue;
    }
    // Predicted from an earlier state of the same trajectories: check again
    // from now (rounding can move it slightly).
    Hit hit;
    if (!predict_pair(ev.i, ev.j, hit)) continue;
    if (hit.t > ev.t + 1e-9 * (1.0 + std::abs(ev.t))) {
      queue_.push(Queued{hit.t, ev.i, ev.j, ev.vi, ev.vj});
      continue;
    }
    move_all_to(std::max(hit.t, now_));
    const std::vector<std::uint32_t> before = version_;
    resolve(ev.i, ev.j, hit.axis);
    ++version_[ev.i];
    ++version_[ev.j];
    log_.push_back(EventRecord{now_, ev.i, ev.j});
    for (std::size_t k = 0; k < bodies_.size(); ++k)
      if (version_[k] != before[k]) predict_body(k);
  }
  move_all_to(t);
}

double EventSim::energy() const {
  double E = 0.0;
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (!finite(i)) continue;
    const Body& b = bodies_[i];
    E += b.m * (0.5 * Vector::dot(b.v, b.v) - Vector::dot(g_, b.p));
  }
  return E;
}

Vector EventSim::momentum() const {
  Vector p{};
  for (std::size_t i = 0; i < bodies_.size(); ++i)
    if (finite(i)) p = p + bodies_[i].m * bodies_[i].v;
  return p;
}

}  // namespace physics::reference
