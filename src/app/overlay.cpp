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
constexpr Color preview_colour{120, 60, 0, 255};
constexpr Color beyond_colour{200, 200, 205, 255};  // the window outside the world
constexpr Color panel_colour{255, 255, 240, 225};
constexpr Color panel_edge{60, 60, 60, 255};
constexpr int margin = 8, pad = 6;  // px: a panel from the window's edge, its text from its own
constexpr Color ink{20, 20, 20, 255};
constexpr Color white{255, 255, 255, 255};

constexpr double velocity_scale = 100.0;   // px of arrow per px/ms: the distance covered in 100 ms
constexpr double normal_length = 24.0;     // px
constexpr double penetration_scale = 4.0;  // penetrations are a few px: drawn 4x

std::string top_speed_text() {
  char top[32];
  std::snprintf(top, sizeof top, ">= %g px/ms", Styles::top_speed);
  return top;
}

// Text metrics of the monospace HUD font.
int text_px(const Painter& p, std::size_t chars) { return static_cast<int>(std::ceil(chars * p.char_width())); }
std::size_t text_chars(const Painter& p, int width) {
  return static_cast<std::size_t>(std::max(0.0, (width - 2 * margin - 2 * pad) / p.char_width()));
}
std::vector<std::string> wrap_all(const std::vector<std::string>& lines, std::size_t chars) {
  std::vector<std::string> out;
  for (const std::string& l : lines)
    for (std::string& w : wrap(l, chars)) out.push_back(std::move(w));
  return out;
}
std::size_t longest(const std::vector<std::string>& lines) {
  std::size_t n = 0;
  for (const std::string& l : lines) n = std::max(n, l.size());
  return n;
}

struct Box {
  int x, y, w, h;
};
// `lines` on a panel with its top-left corner at (x, y), at least `min_w`
// wide, with `extra_h` px left free under them; returns the panel.
Box panel(Painter& p, const std::vector<std::string>& lines, int x, int y, int min_w, int extra_h) {
  const int lh = p.line_height();
  const Box b{x, y, std::max(min_w, text_px(p, longest(lines))) + 2 * pad,
              static_cast<int>(lines.size()) * lh + 2 * pad + extra_h};
  p.fill_box(b.x, b.y, b.w, b.h, panel_colour);
  p.stroke_box(b.x, b.y, b.w, b.h, panel_edge);
  int ty = y + pad;
  for (const std::string& s : lines) {
    p.text(s, x + pad, ty, ink);
    ty += lh;
  }
  return b;
}

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

// The speed style's key, in the HUD panel: the ramp (Styles::speed_color)
// as a bar from 0 to its top speed, with the end values. Returns the y below it.
constexpr int bar_w = 160, bar_h = 12;
int speed_legend(Painter& p, int x, int y) {
  const int left = p.text("speed 0", x, y, ink);
  const int bx = x + 70;
  for (int i = 0; i < bar_w; ++i)
    p.fill_rect({double(bx + i), double(y + 2)}, {1, bar_h}, Styles::speed_color(Styles::top_speed * i / (bar_w - 1)));
  const int right = p.text(top_speed_text(), bx + bar_w + 6, y, ink);
  return y + std::max({left, right, bar_h + 4}) + 2;
}

// `lines` cut to at most `room` lines, the last one then saying how many
// were left out and `how` to see them; none if not even one line fits.
std::vector<std::string> fitted(std::vector<std::string> lines, int room, const std::string& how) {
  if (room <= 0) return {};
  if (lines.size() <= static_cast<std::size_t>(room)) return lines;
  const std::size_t left = lines.size() - static_cast<std::size_t>(room - 1);
  lines.resize(static_cast<std::size_t>(room - 1));
  lines.push_back("... " + std::to_string(left) + " more line" + (left == 1 ? "" : "s") + how);
  return lines;
}

// The HUD panel at the top left, then the key list's at the right, below
// it, so that neither hides the other; both inside the view. The key list
// (asked for with H) is whole if the window holds it; the HUD gets the room
// left above it, cut with a last line that says so (a long note or stage
// times in a small window would push the keys past its bottom edge).
void texts(const View& view, Painter& p) {
  const int width = static_cast<int>(view.camera.view.x), height = static_cast<int>(view.camera.view.y);
  const std::size_t chars = text_chars(p, width);
  const int lh = p.line_height();
  const auto lines_in = [&](int px) { return (px - 2 * pad) / lh; };  // the lines a panel px high holds
  const std::vector<std::string> keys = fitted(wrap_all(view.help, chars), lines_in(height - 2 * margin), "");
  const int keys_h = keys.empty() ? 0 : static_cast<int>(keys.size()) * lh + 2 * pad + margin;
  const bool legend = view.style == Style::speed && view.overlays.hud;
  const int legend_h = legend ? lh + 6 : 0;
  const int room = lines_in(height - 2 * margin - keys_h - legend_h);
  int y = margin;
  if ((!view.hud.empty() || legend) && room > 0) {
    const std::vector<std::string> lines =
        fitted(wrap_all(view.hud, chars), room, keys.empty() ? "" : " (H hides the key list)");
    const int lw = legend ? 76 + bar_w + text_px(p, top_speed_text().size()) : 0;
    const Box b = panel(p, lines, margin, y, lw, legend_h);
    if (legend) speed_legend(p, margin + pad, b.y + b.h - pad - lh - 4);
    y = b.y + b.h + margin;
  }
  if (keys.empty()) return;
  const int w = std::min(width - 2 * margin, text_px(p, longest(keys)) + 2 * pad);
  panel(p, keys, width - margin - w, y, 0, 0);
}

// The drag: the rubber band from the sling's two prongs to the pull, the
// pouch there, and the dots of the aiming preview (a few screen px each,
// whatever the zoom).
void sling(const View& view, Painter& world, Painter& screen) {
  const auto [from, to] = *view.sling;
  const double half = Testbed::spawn_size / 2.0;
  world.stroke_box(from.x - half, from.y - half, Testbed::spawn_size, Testbed::spawn_size, sling_colour);
  line(world, from + Vector{-half, -half}, to, sling_colour);
  line(world, from + Vector{half, -half}, to, sling_colour);
  const Vector pouch = view.camera.to_screen(to);
  if (drawable(pouch)) screen.fill_box(pouch.x - 3, pouch.y - 3, 7, 7, sling_colour);
  for (const Vector d : view.preview)
    if (const Vector s = view.camera.to_screen(d); drawable(s)) screen.fill_box(s.x - 2, s.y - 2, 4, 4, preview_colour);
}

}  // namespace

std::vector<std::string> wrap(const std::string& text, std::size_t chars) {
  chars = std::max<std::size_t>(chars, 16);  // a continuation always moves on past its indent
  std::vector<std::string> out;
  std::string s = text;
  while (s.size() > chars) {
    std::size_t cut = s.rfind(' ', chars);
    if (cut == std::string::npos || cut <= 2) cut = chars;
    out.push_back(s.substr(0, cut));
    s = "  " + s.substr(s[cut] == ' ' ? cut + 1 : cut);
  }
  out.push_back(s);
  return out;
}

void bodies(const World& world, const View& view, Painter& p) {
  // Around a world smaller than the view (centred), its edges show.
  const Camera& c = view.camera;
  const Vector lo = c.to_screen({0, 0}), hi = c.to_screen(c.world);
  if (lo.x > 0 || lo.y > 0 || hi.x < c.view.x || hi.y < c.view.y) {
    p.fill_box(0, 0, c.view.x, c.view.y, beyond_colour);
    p.fill_box(lo.x, lo.y, hi.x - lo.x, hi.y - lo.y, white);
  }
  CameraPainter cp(view.camera, p);
  Styles::draw_world(world, view.style, view.roles, cp);
}

void over(const World& world, const View& view, Painter& p) {
  CameraPainter cp(view.camera, p);
  if (world.declares(SystemId::draw)) boxes_and_velocities(world, view, cp);
  contacts(view, cp);
  if (view.sling) sling(view, cp, p);
  if (view.ray) ray(*view.ray, cp);
  if (p.line_height() > 0) texts(view, p);
}

}  // namespace physics::Overlay

namespace physics {

bool CameraPainter::seen(double x, double y, double w, double h) const {
  return x + w >= 0 && y + h >= 0 && x <= c_.view.x && y <= c_.view.y;
}

void CameraPainter::fill_box(double x, double y, double w, double h, Color c) {
  const Vector s = c_.to_screen({x, y});
  if (seen(s.x, s.y, w * c_.scale, h * c_.scale)) p_.fill_box(s.x, s.y, w * c_.scale, h * c_.scale, c);
}

void CameraPainter::stroke_box(double x, double y, double w, double h, Color c) {
  const Vector s = c_.to_screen({x, y});
  if (seen(s.x, s.y, w * c_.scale, h * c_.scale)) p_.stroke_box(s.x, s.y, w * c_.scale, h * c_.scale, c);
}

void CameraPainter::line(Vector a, Vector b, Color c) {
  const Vector sa = c_.to_screen(a), sb = c_.to_screen(b);
  if (seen(std::min(sa.x, sb.x), std::min(sa.y, sb.y), std::abs(sb.x - sa.x), std::abs(sb.y - sa.y))) p_.line(sa, sb, c);
}

}  // namespace physics
