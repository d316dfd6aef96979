// Input logs: every input event the testbed received, with the tick (physics
// steps run) it arrived at, so that a session can be replayed with the same
// physics bit for bit (--record FILE, --replay FILE). SDL-free.
//
// The file is text, one event a line, CSV with a header; '#' lines are
// comments, and "# scene: NAME" names the scene it was recorded on:
//
//   # physics input log v1
//   # scene: stack
//   tick,kind,key,x,y,button
//   0,key,1073741903,0,0,0
//   35,key_up,1073741903,0,0,0
//   812,end,0,0,0,0
//
// x, y: a mouse event's world point, px (the testbed maps the window's
// through its camera first: Testbed::live). kind: key, key_up, mouse_down,
// mouse_up, mouse_move, quit (never wheel: the camera's); the last line is
// `end`, the tick the recording stopped at. Ticks never decrease, and are at
// most max_log_ticks.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "app/testbed.hpp"

namespace physics {

// The largest tick a log may hold: 10^7 steps, 46 hours of a window at
// 60 Hz, which a headless replay of a small scene runs in about a minute (a
// log ending at tick 2^53 ran for ever). A longer session is recorded in
// parts.
inline constexpr std::int64_t max_log_ticks = 10'000'000;

struct LoggedEvent {
  std::int64_t tick = 0;  // Testbed::ticks() when the event was handled
  InputEvent event;
  bool operator==(const LoggedEvent& o) const;
};

struct InputLog {
  std::string scene;  // the "# scene:" line (empty if none)
  std::vector<LoggedEvent> events;  // in the order handled; ticks never decrease
  std::int64_t end = 0;             // the tick the recording stopped at (>= every event's)
};

// A malformed or unreadable log: "FILE:LINE: problem" (or "FILE: problem").
struct InputLogError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// `text` is the log's; `name` is the file name the messages give.
InputLog parse_input_log(std::string_view text, const std::string& name);
InputLog read_input_log(const std::string& path);  // throws InputLogError

void write_input_log(std::ostream& out, const InputLog& log);
// Throws std::runtime_error when the file cannot be written.
void write_input_log(const std::string& path, const InputLog& log);

}  // namespace physics
