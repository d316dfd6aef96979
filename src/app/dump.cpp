#include "app/dump.hpp"

#include <charconv>
#include <cmath>
#include <ostream>

namespace physics::Dump {
namespace {

void row(std::ostream& out, const World& w, std::size_t e) {
  const Components& c = w.components;
  out << e << ',' << number(c.position[e].x) << ',' << number(c.position[e].y) << ',' << c.box[e].width << ','
      << c.box[e].height << ',' << number(c.velocity[e].x) << ',' << number(c.velocity[e].y) << ','
      << number(c.mass[e]) << '\n';
}

}  // namespace

std::string number(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc{} ? std::string(buf, end) : "nan";
}

void write_state(std::ostream& out, const World& w) {
  write_header(out);
  write_rows(out, w);
}

void write_header(std::ostream& out) { out << header << '\n'; }

void write_rows(std::ostream& out, const World& w) {
  for (std::size_t e = 0; e < w.components.size(); ++e)
    if (w.alive(static_cast<EntityId>(e))) row(out, w, e);
}

void write_trace_header(std::ostream& out) { out << trace_header << '\n'; }

void write_trace_rows(std::ostream& out, const World& w) {
  for (std::size_t e = 0; e < w.components.size(); ++e) {
    if (!w.alive(static_cast<EntityId>(e))) continue;
    out << w.frame << ',';
    row(out, w, e);
  }
}

void write_events_header(std::ostream& out) { out << events_header << '\n'; }

void write_events(std::ostream& out, const World& w) {
  for (const ContactEvent& e : w.events.events())
    out << e.frame << ',' << (e.kind == EventKind::begin ? "begin" : "end") << ',' << e.a << ',' << e.b << ','
        << number(e.normal.x) << ',' << number(e.normal.y) << ',' << number(e.depth) << ',' << number(e.jn) << ','
        << number(e.jt) << '\n';
}

}  // namespace physics::Dump
