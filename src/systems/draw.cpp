#include "systems/draw.hpp"

#include <algorithm>
#include <cmath>

namespace physics {

void Draw::update(const Components& c, Canvas& canvas) const {
  for (const EntityId e : entities_) {
    const Vector p = c.position[e];
    // Skip what cannot be drawn (NaN, or far outside int range) rather than
    // hand the canvas an undefined conversion.
    if (!(std::abs(p.x) < 1e9 && std::abs(p.y) < 1e9)) continue;
    const Face face = c.any_rules() ? c.rules(e).one_way : Face::none;
    if (c.any_rules() && c.rules(e).sensor) {
      draw_sensor(p, c.box[e], c.color[e], canvas);
      continue;
    }
    canvas.fill_rect(p, c.box[e], c.color[e]);
    outline(p, c.box[e], c.color[e], canvas);
    if (face != Face::none) draw_solid_face(p, c.box[e], face, c.color[e], canvas);
  }
}

void draw_sensor(Vector p, Rect r, Color c, Canvas& canvas) {
  const int t = std::min({2, r.width, r.height});
  canvas.fill_rect(p, {r.width, t}, c);
  canvas.fill_rect({p.x, p.y + r.height - t}, {r.width, t}, c);
  canvas.fill_rect(p, {t, r.height}, c);
  canvas.fill_rect({p.x + r.width - t, p.y}, {t, r.height}, c);
}

void draw_solid_face(Vector p, Rect r, Face face, Color c, Canvas& canvas) {
  const Color o = outline_color(c);
  const int th = std::min(solid_face, r.height), tw = std::min(solid_face, r.width);
  switch (face) {
    case Face::none: return;
    case Face::up: canvas.fill_rect(p, {r.width, th}, o); return;
    case Face::down: canvas.fill_rect({p.x, p.y + r.height - th}, {r.width, th}, o); return;
    case Face::left: canvas.fill_rect(p, {tw, r.height}, o); return;
    case Face::right: canvas.fill_rect({p.x + r.width - tw, p.y}, {tw, r.height}, o); return;
  }
}

Color outline_color(Color c) {
  const auto dark = [](std::uint8_t v) { return static_cast<std::uint8_t>(v * 11 / 20); };
  return {dark(c.r), dark(c.g), dark(c.b), c.a};
}

void outline(Vector p, Rect r, Color c, Canvas& canvas) {
  if (r.width < min_outlined || r.height < min_outlined) return;
  const Color o = outline_color(c);
  canvas.fill_rect(p, {r.width, 1}, o);
  canvas.fill_rect({p.x, p.y + r.height - 1}, {r.width, 1}, o);
  canvas.fill_rect({p.x, p.y + 1}, {1, r.height - 2}, o);
  canvas.fill_rect({p.x + r.width - 1, p.y + 1}, {1, r.height - 2}, o);
}

}  // namespace physics
