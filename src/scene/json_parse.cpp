#include "scene/json_parse.hpp"

#include <algorithm>
#include <cmath>

namespace physics::scene_io {

// Reader::number's conversion: the number's value as a double, finite.
bool PlainBlock::number(const Event& e, double& out) {
  switch (e.kind) {
    case Kind::integer: out = static_cast<double>(e.i); break;
    case Kind::natural: out = static_cast<double>(e.u); break;
    case Kind::real: out = e.d; break;
    default: return false;
  }
  return std::isfinite(out);
}

// e: the start of an array of exactly two numbers. The events are in one
// vector and every array in it is closed, so reading in order, each event
// looked at exists: e[1] since e[0] opens an array, e[2] since e[1] is not
// its end, and so on.
bool PlainBlock::vec(const Event* e, Vector& out) {
  return e[0].kind == Kind::start_array && number(e[1], out.x) && number(e[2], out.y) &&
         e[3].kind == Kind::end_array;
}

// A side, an integer in [1, max_block_size]; a real one (4.0) is left to
// the document's reader, which takes it too: rare, and it has rules of its own.
bool PlainBlock::side(const Event& e, int& out) {
  if (e.kind == Kind::natural && e.u >= 1 && e.u <= static_cast<std::uint64_t>(max_block_size)) {
    out = static_cast<int>(e.u);
    return true;
  }
  return false;  // negative integers (nlohmann's "integer"): out of range
}

bool PlainBlock::mass(const Event& e, double& out) const {
  if (e.kind == Kind::string) {
    if (text(e) != "inf") return false;
    out = infinity;
    return true;
  }
  return number(e, out);  // > 0: validate() (scene.hpp), as for the document
}

bool PlainBlock::color(const Event& e, Color& out) const {
  if (e.kind != Kind::string) return false;
  const std::string& s = text(e);
  if (s.size() != 7 || s[0] != '#') return false;
  const auto digit = [](char c) {
    return c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
  };
  std::uint8_t rgb[3];
  for (int i = 0; i < 3; ++i) {
    const int hi = digit(s[1 + 2 * i]), lo = digit(s[2 + 2 * i]);
    if (hi < 0 || lo < 0) return false;
    rgb[i] = static_cast<std::uint8_t>(hi * 16 + lo);
  }
  out = {rgb[0], rgb[1], rgb[2], 255};
  return true;
}

// The block read_block would make of these events, or false if it would
// not make one (it then says why) or might make it differently.
bool PlainBlock::to_spec(BlockSpec& out) const {
  std::array<const Event*, names.size()> at{};  // each key's value (a scalar, or the start of its array)
  for (std::size_t i = 0; i + 1 < events_.size(); ++i)
    if (events_[i].kind == Kind::key) at[events_[i].id] = &events_[i + 1];
  const Event *pos = at[0], *size = at[1], *mass_ = at[2];
  if (!pos || !size || !mass_ || !vec(pos, out.pos) || !mass(*mass_, out.mass)) return false;
  const bool sides = size[0].kind == Kind::start_array && side(size[1], out.width) && side(size[2], out.height) &&
                     size[3].kind == Kind::end_array;  // in this order: see vec()
  if (!sides) return false;
  for (std::size_t k = 3; k < 6; ++k) {
    Vector& v = k == 3 ? out.velocity : k == 4 ? out.force : out.impulse;
    if (at[k] && !vec(at[k], v)) return false;
  }
  if (at[6] && !color(*at[6], out.color)) return false;
  if (at[7]) {
    double e;
    if (!number(*at[7], e)) return false;
    out.restitution = e;  // in [0, 1]: validate()
  }
  return true;
}

}  // namespace physics::scene_io
