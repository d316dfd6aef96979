// CSV state of a world, for --dump (final state) and --trace (every frame).
//   id,x,y,w,h,vx,vy,mass            one row per entity in creation order
//                                    (a destroyed body has none; ids are kept)
//   frame,id,x,y,w,h,vx,vy,mass      the trace: the same, for frame 0 (the
//                                    initial state) and after every step
// Numbers are the shortest text that reads back as the same double (so a
// dump is exact and two runs compare with diff); infinite mass is `inf`.
#pragma once

#include <iosfwd>
#include <string>

#include "engine/world.hpp"

namespace physics::Dump {

inline constexpr const char* header = "id,x,y,w,h,vx,vy,mass";
inline constexpr const char* trace_header = "frame,id,x,y,w,h,vx,vy,mass";

// The shortest round-trip decimal text of v; "inf", "-inf", "nan" otherwise.
std::string number(double v);

// The text of each (the browser build, which links no stream, writes that:
// docs/web.md), and the same written to a stream.
std::string state(const World& w);  // header + rows
std::string rows(const World& w);
std::string trace_rows(const World& w);  // rows of w.frame
void write_state(std::ostream& out, const World& w);
void write_header(std::ostream& out);
void write_rows(std::ostream& out, const World& w);
void write_trace_header(std::ostream& out);
void write_trace_rows(std::ostream& out, const World& w);   // rows of w.frame

// --events: the contact events of each step (engine/events.hpp).
//   frame,event,a,b,nx,ny,depth,jn,jt   event: begin or end; ids as in the dump
inline constexpr const char* events_header = "frame,event,a,b,nx,ny,depth,jn,jt";
std::string events(const World& w);  // the last step's
void write_events_header(std::ostream& out);
void write_events(std::ostream& out, const World& w);  // the last step's

}  // namespace physics::Dump
