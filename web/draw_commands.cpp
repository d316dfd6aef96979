#include "draw_commands.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/style.hpp"
#include "course/game.hpp"

namespace physics::web {

void Commands::colour(Color c) {
  for (const int v : {c.r, c.g, c.b, c.a}) ops_.push_back(static_cast<float>(v));
}

void Commands::box(Op op, double x, double y, double w, double h, Color c) {
  for (const double v : {double(op), x, y, w, h}) ops_.push_back(static_cast<float>(v));
  colour(c);
}

void Commands::segment(Vector a, Vector b, Color c) {
  for (const double v : {double(line), a.x, a.y, b.x, b.y}) ops_.push_back(static_cast<float>(v));
  colour(c);
}

void Commands::write(const std::string& s, double x, double y, Color c) {
  for (const double v : {double(text), x, y}) ops_.push_back(static_cast<float>(v));
  colour(c);
  texts_ += s;
  texts_ += '\n';
}

namespace {

// window.cpp's overlay colours and scales.
constexpr Color aabb_colour{0, 170, 0, 255};
constexpr Color velocity_colour{200, 0, 200, 255};
constexpr Color normal_colour{230, 0, 0, 255};
constexpr Color penetration_colour{0, 120, 255, 255};
constexpr Color contact_colour{255, 200, 0, 255};
constexpr Color ray_colour{0, 150, 150, 255};
constexpr Color ink{20, 20, 20, 255};
constexpr double velocity_scale = 100.0, normal_length = 24.0, penetration_scale = 4.0;

bool drawable(Vector p) { return std::abs(p.x) < 1e6 && std::abs(p.y) < 1e6; }

void line_to(Commands& out, Vector a, Vector b, Color c) {
  if (drawable(a) && drawable(b)) out.segment(a, b, c);
}

void arrow(Commands& out, Vector from, Vector to, Color c) {
  line_to(out, from, to, c);
  const Vector d = to - from;
  const double n = Vector::norm(d);
  if (n < 1e-9) return;
  const Vector u = Vector::mult(1.0 / n, d), side{-u.y, u.x};
  const double head = std::min(6.0, n / 2);
  line_to(out, to, to - head * u + (head / 2) * side, c);
  line_to(out, to, to - head * u - (head / 2) * side, c);
}

void haloed_arrow(Commands& out, Vector from, Vector to, Color c) {
  for (const Vector d : {Vector{1, 0}, Vector{-1, 0}, Vector{0, 1}, Vector{0, -1}})
    arrow(out, from + d, to + d, Color{255, 255, 255, 255});
  arrow(out, from, to, c);
}

Vector centre(const Components& c, EntityId e) {
  return c.position[e] + Vector{c.box[e].width / 2.0, c.box[e].height / 2.0};
}

void draw_contacts(Commands& out, const View& view) {
  for (std::size_t i = 0; i < view.contacts.size() && i < view.contact_regions.size(); ++i) {
    const Contact& k = view.contacts[i];
    const ContactRegion& g = view.contact_regions[i];
    if (!drawable(g.lo) || !drawable(g.hi)) continue;
    out.box(fill, g.lo.x - 1, g.lo.y - 1, g.hi.x - g.lo.x + 2, g.hi.y - g.lo.y + 2, contact_colour);
    const Vector at = g.middle();
    haloed_arrow(out, at, at + penetration_scale * k.penetration, penetration_colour);
    haloed_arrow(out, at, at + normal_length * k.normal, normal_colour);
  }
}

void draw_ray(Commands& out, const RayView& ray) {
  const Vector end = ray.hit ? ray.hit->point : ray.to;
  line_to(out, ray.from, end, ray_colour);
  if (!ray.hit || !drawable(end)) return;
  line_to(out, end, ray.to, Color{ray_colour.r, ray_colour.g, ray_colour.b, 80});
  haloed_arrow(out, end, end + normal_length * ray.hit->normal, ray_colour);
  out.box(fill, end.x - 3, end.y - 3, 7, 7, ray_colour);
}

void draw_bodies(Commands& out, const World& world, const View& view) {
  Styles::draw_world(world, view.style, view.roles, out);
  const Components& c = world.components;
  const auto draw = world.bodies(SystemId::draw);
  if (view.overlays.aabb)
    for (const EntityId e : draw)
      if (drawable(c.position[e]))
        out.box(stroke, c.position[e].x, c.position[e].y, c.box[e].width, c.box[e].height, aabb_colour);
  if (view.overlays.velocity)
    for (const EntityId e : draw)
      if (!Vector::is_zero(c.velocity[e]))
        arrow(out, centre(c, e), centre(c, e) + velocity_scale * c.velocity[e], velocity_colour);
}

// The speed style's key under the HUD (window.cpp's speed_legend).
int speed_legend(Commands& out, int x, int y) {
  constexpr int bar_w = 160, bar_h = 12;
  out.write("speed 0", x, y, ink);
  const int bx = x + 70;
  for (int i = 0; i < bar_w; ++i)
    out.fill_rect({double(bx + i), double(y + 2)}, {1, bar_h}, Styles::speed_color(Styles::top_speed * i / (bar_w - 1)));
  char top[32];
  std::snprintf(top, sizeof top, ">= %g px/ms", Styles::top_speed);
  out.write(top, bx + bar_w + 6, y, ink);
  return y + std::max(line_height, bar_h + 4) + 2;
}

void draw_text(Commands& out, const View& view, int width) {
  int y = 44;
  for (const std::string& s : view.hud) out.write(s, 48, y, ink), y += line_height + 2;
  if (view.style == Style::speed && view.overlays.hud) y = speed_legend(out, 48, y + 2);
  if (view.help.empty()) return;
  const double px = width - 460, py = y + 8, ph = double(view.help.size()) * line_height + 16;
  out.box(fill, px, py, 410, ph, Color{255, 255, 240, 225});
  out.box(stroke, px, py, 410, ph, Color{60, 60, 60, 255});
  double hy = py + 8;
  for (const std::string& s : view.help) out.write(s, px + 10, hy, ink), hy += line_height;
}

}  // namespace

void render(const World& world, const View& view, int width, Commands& out) {
  out.clear();
  if (world.declares(SystemId::draw)) draw_bodies(out, world, view);
  draw_contacts(out, view);
  if (view.sling) {
    const auto [from, to] = *view.sling;
    const Color orange{255, 140, 0, 255};
    line_to(out, from, to, orange);
    out.box(stroke, from.x - Testbed::spawn_size / 2.0, from.y - Testbed::spawn_size / 2.0, Testbed::spawn_size,
            Testbed::spawn_size, orange);
  }
  if (view.ray) draw_ray(out, *view.ray);
  draw_text(out, view, width);
}

}  // namespace physics::web
