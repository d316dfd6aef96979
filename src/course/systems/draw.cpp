#include "course/systems/draw.hpp"

#include <algorithm>
#include <cmath>

namespace physics {

void Draw::update(const Components& c, Canvas& canvas) const {
  for (const EntityId e : entities_) {
    // Skip what cannot be drawn rather than hand the canvas an undefined conversion.
    if (can_draw(c.position[e])) draw_block(c, e, c.color[e], canvas);
  }
}

void draw_block(const Components& c, EntityId e, Color col, Canvas& canvas) {
  const Vector p = c.position[e];
  const Face face = c.any_rules() ? c.rules(e).one_way : Face::none;
  if (c.any_rules() && c.rules(e).sensor) {
    draw_sensor(p, c.box[e], col, canvas);
    return;
  }
  canvas.fill_rect(p, c.box[e], col);
  outline(p, c.box[e], col, canvas);
  if (face != Face::none) draw_solid_face(p, c.box[e], face, col, canvas);
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
