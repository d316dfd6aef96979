#include "app/dump.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <ostream>

#include "engine/format.hpp"

namespace physics::Dump {
namespace {

// The rows are appended to one string, without a temporary per number: a
// trace writes a row per body per frame.
std::string& put(std::string& out, double v) {  // shortest, as number()
  if (std::isnan(v)) return out += "nan";
  if (std::isinf(v)) return out += v > 0 ? "inf" : "-inf";
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc{} ? out.append(buf, end) : out += "nan";
}

std::string& put(std::string& out, std::int64_t n) {
  char buf[24];
  return out.append(buf, std::to_chars(buf, buf + sizeof buf, n).ptr);
}

// A body's row; its size as --dump has always written it ("%.17g", the
// files' precision), the other numbers shortest.
void row(std::string& out, const World& w, std::size_t e) {
  const Components& c = w.components;
  put(out, static_cast<std::int64_t>(e));
  for (const double v : {c.position[e].x, c.position[e].y}) put(out += ',', v);
  out += ',' + format_g(c.box[e].width, 17) + ',' + format_g(c.box[e].height, 17);
  for (const double v : {c.velocity[e].x, c.velocity[e].y, c.mass[e]}) put(out += ',', v);
  out += '\n';
}

}  // namespace

std::string number(double v) {
  std::string out;
  put(out, v);
  return out;
}

std::string state(const World& w) { return header + std::string("\n") + rows(w); }

std::string rows(const World& w) {
  std::string out;
  for (std::size_t e = 0; e < w.components.size(); ++e)
    if (w.alive(static_cast<EntityId>(e))) row(out, w, e);
  return out;
}

std::string trace_rows(const World& w) {
  std::string out;
  for (std::size_t e = 0; e < w.components.size(); ++e)
    if (w.alive(static_cast<EntityId>(e))) row(put(out, w.frame) += ',', w, e);
  return out;
}

std::string events(const World& w) {
  std::string out;
  for (const ContactEvent& e : w.events.events()) {
    put(out, e.frame);
    out += e.kind == EventKind::begin ? ",begin," : ",end,";
    put(out, std::int64_t{e.a});
    put(out += ',', std::int64_t{e.b});
    for (const double v : {e.normal.x, e.normal.y, e.depth, e.jn, e.jt}) put(out += ',', v);
    out += '\n';
  }
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
