// The testbed's record and replay (testbed.hpp), apart from testbed.cpp:
// the input logs' ticks, and the one code path the window and the headless
// replay share (pump, called by advance, step and play).
#include "app/input_log.hpp"
#include "app/testbed.hpp"

namespace physics {

void Testbed::record_event(const InputEvent& e) { recording_->events.push_back({ticks_, e}); }

void Testbed::replay(InputLog log) {
  replay_ = std::make_shared<const InputLog>(std::move(log));
  replayed_ = 0;
}

// Every event logged at this tick, in order. An event may step (N): the
// events logged after it carry the next tick, so they wait for the loop to
// see it; the nested pump in step() finds nothing due. At the end tick, once
// its events are handled, the replay is over: the testbed pauses there (in a
// window the user takes over).
void Testbed::pump() {
  if (!replay_) return;
  const auto log = replay_;  // handle() may not end the replay, but keep it alive anyway
  while (replayed_ < log->events.size() && log->events[replayed_].tick <= ticks_) handle(log->events[replayed_++].event);
  if (replayed_ == log->events.size() && ticks_ >= log->end) {
    replay_.reset();
    paused_ = true;
    say("replay ended at tick " + std::to_string(ticks_) + " (frame " + std::to_string(world_->frame) + ")", false);
  }
}

// The window's events: the camera's first (live or replaying), then the
// rest with the mouse in world px, as handle() and the log take them.
Testbed::Action Testbed::live(const InputEvent& window_event) {
  if (camera_input(window_event)) return Action::none;
  const InputEvent e = in_world(window_event);
  if (!replay_) return handle(e);
  const bool quit = e.kind == InputEvent::Kind::quit ||
                    (e.kind == InputEvent::Kind::key && (e.key == key::escape || e.key == 'q' || e.key == 'Q'));
  return quit ? Action::quit : Action::none;
}

void Testbed::play(std::int64_t last_tick) {
  for (;;) {
    pump();
    // (A world stopped on a non-finite value steps no more: nothing to wait for.)
    if (!replay_ || paused_ || ticks_ >= last_tick || world_->health.non_finite) return;
    step();
  }
}

}  // namespace physics
