#include "app/overlay.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/style.hpp"

namespace physics::Overlay {

namespace {

// Overlay colours: distinct from the walls (blue/black) and the blocks.
constexpr Color aabb_colour{0, 170, 0, 255};
constexpr Color velocity_colour{200, 0, 200, 255};
constexpr Color normal_colour{230, 0, 0, 255};
constexpr Color penetration_colour{0, 120, 255, 255};
constexpr Color contact_colour{255, 200, 0, 255};  // the shared edge
constexpr Color ray_colour{0, 150, 150, 255};
constexpr Color sling_colour{255, 140, 0, 255};
constexpr Color ink{20, 20, 20, 255};
constexpr Color white{255, 255, 255, 255};

constexpr double velocity_scale = 100.0;   // px of arrow per px/ms: the distance covered in 100 ms
constexpr double normal_length = 24.0;     // px
constexpr double penetration_scale = 4.0;  // penetrations are a few px: drawn 4x

// Far-away bodies are not drawn (a renderer's float coordinates overflow).
bool drawable(Vector p) { return std::abs(p.x) < 1e6 && std::abs(p.y) < 1e6; }

void line(Painter& p, Vector a, Vector b, Color c) {
  if (drawable(a) && drawable(b)) p.line(a, b, c);
}

// A line with a small head, so the direction reads at a glance.
void arrow(Painter& p, Vector from, Vector to, Color c) {
  line(p, from, to, c);
  const Vector d = to - from;
  const double n = Vector::norm(d);
  if (n < 1e-9) return;
  const Vector u = Vector::mult(1.0 / n, d), side{-u.y, u.x};
  const double head = std::min(6.0, n / 2);
  line(p, to, to - head * u + (head / 2) * side, c);
  line(p, to, to - head * u - (head / 2) * side, c);
}

// An arrow on a white halo, so that it reads on a block of its own colour
// (a red normal on the red block).
void haloed_arrow(Painter& p, Vector from, Vector to, Color c) {
  for (const Vector d : {Vector{1, 0}, Vector{-1, 0}, Vector{0, 1}, Vector{0, -1}}) arrow(p, from + d, to + d, white);
  arrow(p, from, to, c);
}

Vector centre(const Components& c, EntityId e) {
  return c.position[e] + Vector{c.box[e].width / 2.0, c.box[e].height / 2.0};
}

void boxes_and_velocities(const World& world, const View& view, Painter& p) {
  const Components& c = world.components;
  const auto draw = world.bodies(SystemId::draw);
  if (view.overlays.aabb)
    for (const EntityId e : draw)
      if (drawable(c.position[e])) p.stroke_box(c.position[e].x, c.position[e].y, c.box[e].width, c.box[e].height, aabb_colour);
  if (view.overlays.velocity)
    for (const EntityId e : draw)
      if (!Vector::is_zero(c.velocity[e]))
        arrow(p, centre(c, e), centre(c, e) + velocity_scale * c.velocity[e], velocity_colour);
}

// The last step's contacts where the bodies met: the shared edge (a thick
// segment) and, from its middle, the normal and the penetration.
void contacts(const View& view, Painter& p) {
  for (std::size_t i = 0; i < view.contacts.size() && i < view.contact_regions.size(); ++i) {
    const Contact& k = view.contacts[i];
    const ContactRegion& g = view.contact_regions[i];
    if (!drawable(g.lo) || !drawable(g.hi)) continue;
    p.fill_box(g.lo.x - 1, g.lo.y - 1, g.hi.x - g.lo.x + 2, g.hi.y - g.lo.y + 2, contact_colour);
    const Vector at = g.middle();
    haloed_arrow(p, at, at + penetration_scale * k.penetration, penetration_colour);
    haloed_arrow(p, at, at + normal_length * k.normal, normal_colour);
  }
}

// The right drag's ray: solid up to the first body it enters, faint beyond
// (the whole drag solid when it hits nothing), a small square on the hit
// and the normal of the face hit.
void ray(const RayView& r, Painter& p) {
  const Vector end = r.hit ? r.hit->point : r.to;
  line(p, r.from, end, ray_colour);
  if (!r.hit || !drawable(end)) return;
  line(p, end, r.to, Color{ray_colour.r, ray_colour.g, ray_colour.b, 80});
  haloed_arrow(p, end, end + normal_length * r.hit->normal, ray_colour);
  // The square over the arrow's foot, so that the halo does not hide it.
  p.fill_box(end.x - 3, end.y - 3, 7, 7, ray_colour);
}

// The speed style's key, under the HUD lines: the ramp (Styles::speed_color)
// as a bar from 0 to its top speed, with the end values. Returns the y below it.
int speed_legend(Painter& p, int x, int y) {
  constexpr int bar_w = 160, bar_h = 12;
  const int left = p.text("speed 0", x, y, ink);
  const int bx = x + 70;
  for (int i = 0; i < bar_w; ++i)
    p.fill_rect({double(bx + i), double(y + 2)}, {1, bar_h}, Styles::speed_color(Styles::top_speed * i / (bar_w - 1)));
  char top[32];
  std::snprintf(top, sizeof top, ">= %g px/ms", Styles::top_speed);
  const int right = p.text(top, bx + bar_w + 6, y, ink);
  return y + std::max({left, right, bar_h + 4}) + 2;
}

// The HUD lines at the top left, then the key list in a panel at the right,
// below them, so that neither hides the other.
void texts(const View& view, int width, Painter& p) {
  int y = 44;
  for (const std::string& s : view.hud) y += p.text(s, 48, y, ink) + 2;
  if (view.style == Style::speed && view.overlays.hud) y = speed_legend(p, 48, y + 2);
  if (view.help.empty()) return;
  const int px = width - 460, py = y + 8, ph = static_cast<int>(view.help.size()) * p.line_height() + 16;
  p.fill_box(px, py, 410, ph, Color{255, 255, 240, 225});
  p.stroke_box(px, py, 410, ph, Color{60, 60, 60, 255});
  int hy = py + 8;
  for (const std::string& s : view.help) hy += p.text(s, px + 10, hy, ink);
}

}  // namespace

void bodies(const World& world, const View& view, Painter& p) { Styles::draw_world(world, view.style, view.roles, p); }

void over(const World& world, const View& view, int width, Painter& p) {
  if (world.declares(SystemId::draw)) boxes_and_velocities(world, view, p);
  contacts(view, p);
  if (view.sling) {
    const auto [from, to] = *view.sling;
    line(p, from, to, sling_colour);
    p.stroke_box(from.x - Testbed::spawn_size / 2.0, from.y - Testbed::spawn_size / 2.0, Testbed::spawn_size,
                 Testbed::spawn_size, sling_colour);
  }
  if (view.ray) ray(*view.ray, p);
  if (p.line_height() > 0) texts(view, width, p);
}

}  // namespace physics::Overlay
