// An exact, event-driven reference simulator for axis-aligned boxes.
//
// No time step: between two events every finite body follows its parabola
// under the constant gravity g (fixed bodies their straight line), so the
// time at which two boxes start to touch is a root of a quadratic per axis,
// computed in closed form. Events are taken in time order from a priority
// queue (bodies carry versions; a prediction made before a body changed
// course is dropped) and each gets the course's impulse: along the axis the
// boxes touch on, restitution = min of the pair, j = -(1+e) v·n / (1/m_c + 1/m_b).
// Simultaneous contacts (a cradle, a stack) are resolved as the sequence of
// pairwise impacts at the same instant, which is what the cradle's closed
// form assumes.
//
// Resting contact: a body bouncing on a support with e < 1 would hit it
// infinitely often in finite time (Zeno: t_∞ = t_0 (1+e)/(1-e)). When the
// speed at which a body would leave a support that is fixed or itself resting
// is below `rest_speed`, it is set resting on it: its velocity along gravity
// becomes the support's (zero) and gravity no longer accelerates it, until an
// impulse reaches it or it slides off its support's top. The energy this
// removes is below m·rest_speed²/2.
//
// Scenes of up to a few hundred bodies: an event re-predicts the two bodies
// against all others (O(n)) and advances every body to the event's time.
// Bodies should not overlap at the start (touching is fine; an overlapping
// pair gets an impulse if it approaches, as in Ccd); gravity must be
// along an axis (or zero).
#pragma once

#include <cstdint>
#include <queue>
#include <vector>

#include "course/utils/vect.hpp"

namespace physics::reference {

struct Body {
  Vector p;              // top-left corner, px
  Vector v;              // px/ms
  double w = 0, h = 0;   // size, px
  double m = 1;          // mass; infinity for a fixed body
  double e = 1;          // restitution
};

struct EventRecord {
  double t;
  std::uint32_t i, j;
};

struct Options {
  double rest_speed = 1e-9;        // px/ms
  std::int64_t max_events = 50'000'000;
};

class EventSim {
 public:
  EventSim(std::vector<Body> bodies, Vector gravity, double t_end, Options o = {});

  // Processes every event up to t (<= t_end) and moves the bodies there.
  void advance_to(double t);

  double time() const { return now_; }
  const std::vector<Body>& bodies() const { return bodies_; }
  const std::vector<EventRecord>& events() const { return log_; }
  bool resting(std::size_t i) const { return support_[i] >= 0; }

  // Kinetic plus potential energy (-m g·p) and momentum of the finite bodies.
  double energy() const;
  Vector momentum() const;

 private:
  struct Hit {
    double t;  // absolute
    int axis;  // 0: -x, 1: +x, 2: -y, 3: +y (moves i away from j)
  };
  struct Queued {
    double t;
    std::uint32_t i, j;  // j == i: body i slides off its support
    std::uint32_t vi, vj;
    bool operator>(const Queued& o) const {
      if (t != o.t) return t > o.t;
      if (i != o.i) return i > o.i;
      return j > o.j;
    }
  };

  Vector accel(std::size_t i) const;
  bool finite(std::size_t i) const;
  double speed_floor(const Body& a, const Body& b) const;
  bool predict_pair(std::size_t i, std::size_t j, Hit& out) const;
  double slide_off_time(std::size_t i) const;
  void predict_body(std::size_t i);
  void move_all_to(double t);
  void resolve(std::size_t i, std::size_t j, int axis);
  void free_body(std::size_t i);

  std::vector<Body> bodies_;
  Vector g_;
  double t_end_, now_ = 0.0;
  Options opt_;
  std::vector<int> support_;  // index of the body it rests on, or -1
  std::vector<std::uint32_t> version_;
  std::priority_queue<Queued, std::vector<Queued>, std::greater<>> queue_;
  std::vector<EventRecord> log_;
};

}  // namespace physics::reference
