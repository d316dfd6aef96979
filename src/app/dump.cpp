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
  out << header << '\n';
  for (std::size_t e = 0; e < w.components.size(); ++e) row(out, w, e);
}

void write_trace_header(std::ostream& out) { out << trace_header << '\n'; }

void write_trace_rows(std::ostream& out, const World& w) {
  for (std::size_t e = 0; e < w.components.size(); ++e) {
    out << w.frame << ',';
    row(out, w, e);
  }
}

}  // namespace physics::Dump
