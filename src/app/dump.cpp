#include "app/dump.hpp"

#include <charconv>
#include <cmath>
#include <ostream>

#include "engine/format.hpp"

namespace physics::Dump {
namespace {

// A body's row; its size as --dump has always written it ("%.17g", the
// files' precision), the other numbers shortest.
std::string row(const World& w, std::size_t e) {
  const Components& c = w.components;
  return std::to_string(e) + ',' + number(c.position[e].x) + ',' + number(c.position[e].y) + ',' +
         format_g(c.box[e].width, 17) + ',' + format_g(c.box[e].height, 17) + ',' + number(c.velocity[e].x) + ',' +
         number(c.velocity[e].y) + ',' + number(c.mass[e]) + '\n';
}

}  // namespace

std::string number(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc{} ? std::string(buf, end) : "nan";
}

std::string state(const World& w) { return header + std::string("\n") + rows(w); }

std::string rows(const World& w) {
  std::string out;
  for (std::size_t e = 0; e < w.components.size(); ++e)
    if (w.alive(static_cast<EntityId>(e))) out += row(w, e);
  return out;
}

std::string trace_rows(const World& w) {
  std::string out;
  for (std::size_t e = 0; e < w.components.size(); ++e)
    if (w.alive(static_cast<EntityId>(e))) out += std::to_string(w.frame) + ',' + row(w, e);
  return out;
}

std::string events(const World& w) {
  std::string out;
  for (const ContactEvent& e : w.events.events())
    out += std::to_string(e.frame) + ',' + (e.kind == EventKind::begin ? "begin" : "end") + ',' + std::to_string(e.a) +
           ',' + std::to_string(e.b) + ',' + number(e.normal.x) + ',' + number(e.normal.y) + ',' + number(e.depth) +
           ',' + number(e.jn) + ',' + number(e.jt) + '\n';
  return out;
}

void write_state(std::ostream& out, const World& w) { out << state(w); }
void write_header(std::ostream& out) { out << header << '\n'; }
void write_rows(std::ostream& out, const World& w) { out << rows(w); }
void write_trace_header(std::ostream& out) { out << trace_header << '\n'; }
void write_trace_rows(std::ostream& out, const World& w) { out << trace_rows(w); }
void write_events_header(std::ostream& out) { out << events_header << '\n'; }
void write_events(std::ostream& out, const World& w) { out << events(w); }

}  // namespace physics::Dump
