#include "app/style.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "course/game.hpp"

namespace physics::Styles {

namespace {

constexpr Color rim_gold{190, 140, 20, 255};
constexpr Color shine{255, 240, 165, 255};
constexpr Color eye{30, 30, 30, 255};
constexpr Color iron{70, 70, 70, 255};
constexpr Color dark_wood{125, 85, 45, 255};
constexpr Color plank_wood{175, 125, 70, 255};
constexpr Color plank_light{210, 165, 105, 255};

// Shapes are drawn as runs of whole pixels: each rectangle handed to the
// canvas has integer corners, so the window (SDL) and the offscreen buffer
// colour exactly the same pixels. A pixel belongs to a span when its centre
// lies inside it, as in the offscreen renderer.
long first_pixel(double lo) { return static_cast<long>(std::ceil(lo - 0.5)); }

// Fills the pixels whose centres lie in [x0, x1) x [y0, y1).
void fill_pixels(Canvas& c, double x0, double y0, double x1, double y1, Color col) {
  const long i0 = first_pixel(x0), i1 = first_pixel(x1), j0 = first_pixel(y0), j1 = first_pixel(y1);
  if (i1 <= i0 || j1 <= j0) return;
  c.fill_rect({double(i0), double(j0)}, {int(i1 - i0), int(j1 - j0)}, col);
}

// One shape's frame: the box at p of size w x h, drawn in fractions of it,
// so every shape scales with its box. Every run is clipped to the box: the
// collisions use the box, so nothing of a sprite lies outside it.
struct Frame {
  Canvas& canvas;
  Vector p;
  double w, h;

  double x(double f) const { return p.x + f * w; }
  double y(double f) const { return p.y + f * h; }
  // The pixels whose centres lie in [x0, x1) x [y0, y1) and in the box.
  void span(double x0, double y0, double x1, double y1, Color col) const {
    fill_pixels(canvas, std::max(x0, p.x), std::max(y0, p.y), std::min(x1, p.x + w), std::min(y1, p.y + h), col);
  }
  // The part [fx0, fx1) x [fy0, fy1) of the box.
  void rect(double fx0, double fy0, double fx1, double fy1, Color col) const { span(x(fx0), y(fy0), x(fx1), y(fy1), col); }
  // A disc of radius r px centred at (cx, cy) px: one pixel row at a time.
  void disc(double cx, double cy, double r, Color col) const {
    for (long j = first_pixel(cy - r); j < first_pixel(cy + r); ++j) {
      const double dy = j + 0.5 - cy;
      if (std::abs(dy) >= r) continue;
      const double half = std::sqrt(r * r - dy * dy);
      span(cx - half, j, cx + half, j + 1, col);
    }
  }
  // A segment from a to b (px, a.y < b.y) `t` px thick, one row at a time;
  // each row's run is widened by the slope so the stroke keeps its thickness.
  void stroke(Vector a, Vector b, double t, Color col) const {
    const Vector d = b - a;
    if (d.y <= 0) return;
    const double half = 0.5 * t * Vector::norm(d) / d.y;
    for (long j = first_pixel(a.y); j < first_pixel(b.y); ++j) {
      const double xc = a.x + (j + 0.5 - a.y) * d.x / d.y;
      span(xc - half, j, xc + half, j + 1, col);
    }
  }
};

// A little character standing in the box: head with eyes, body in the
// block's colour, arms, legs.
void player(const Frame& f, Color shirt) {
  const double r = std::min(0.18 * f.h, 0.3 * f.w), cx = f.x(0.5), cy = f.y(0.04) + r;
  const double neck = (cy + r - f.p.y) / f.h;  // the head's bottom, as a fraction
  f.rect(0.28, neck, 0.72, 0.7, shirt);
  f.rect(0.12, neck + 0.03, 0.26, 0.58, outline_color(shirt));
  f.rect(0.74, neck + 0.03, 0.88, 0.58, outline_color(shirt));
  f.rect(0.3, 0.7, 0.47, 1.0, trousers);
  f.rect(0.53, 0.7, 0.7, 1.0, trousers);
  f.disc(cx, cy, r, skin);
  const double e = std::max(1.0, 0.3 * r);
  for (const double side : {-1.0, 1.0}) {
    const double ex = cx + side * 0.4 * r, ey = cy - 0.15 * r;
    f.span(ex - e / 2, ey - e / 2, ex + e / 2, ey + e / 2, eye);
  }
}

// A gold disc with a darker rim and a glint.
void coin(const Frame& f) {
  const double r = 0.5 * std::min(f.w, f.h), cx = f.x(0.5), cy = f.y(0.5);
  f.disc(cx, cy, r, rim_gold);
  f.disc(cx, cy, 0.78 * r, coin_gold);
  f.disc(cx - 0.35 * r, cy - 0.35 * r, 0.18 * r, shine);
}

// A heavy ball in the block's colour, lit from the top left (the target
// game's shots).
void shot(const Frame& f, Color c) {
  const double r = 0.5 * std::min(f.w, f.h), cx = f.x(0.5), cy = f.y(0.5);
  f.disc(cx, cy, r, c);
  f.disc(cx - 0.3 * r, cy - 0.3 * r, 0.25 * r, shine);
}

// A flag in the block's colour on a pole, on a small base.
void goal(const Frame& f, Color flag) {
  const double pole = std::max(2.0, 0.08 * f.w) / f.w;
  f.rect(0.18, 0.04, 0.18 + pole, 1.0, iron);
  f.rect(0.06, 0.92, 0.18 + pole + 0.12, 1.0, iron);
  // A pennant pointing right: each row as long as it is far from the tips.
  const double top = f.y(0.04), bottom = f.y(0.46), mid = 0.5 * (top + bottom), half = 0.5 * (bottom - top);
  const double from = f.x(0.18 + pole), length = std::min(0.7 * f.w, f.x(1) - from);
  for (long j = first_pixel(top); j < first_pixel(bottom); ++j)
    f.span(from, j, from + length * (1 - std::abs(j + 0.5 - mid) / half), j + 1, flag);
}

// Concentric rings, red and white, red outside and in the middle.
void target(const Frame& f) {
  const double r = 0.5 * std::min(f.w, f.h);
  for (int k = 0; k < 5; ++k) f.disc(f.x(0.5), f.y(0.5), r * (5 - k) / 5.0, k % 2 == 0 ? target_red : white);
}

// Planks laid end to end, a light top edge and dark seams between them.
void platform(const Frame& f, Vector p, Rect box) {
  f.rect(0, 0, 1, 1, plank_wood);
  f.rect(0, 0, 1, std::max(1.0, 0.2 * f.h) / f.h, plank_light);
  const double plank = std::max(3.0 * f.h, 24.0);
  for (double x = plank; x < f.w - 2; x += plank) f.span(f.p.x + x, f.p.y, f.p.x + x + 1, f.p.y + f.h, dark_wood);
  outline(p, box, plank_wood, f.canvas);
}

// A wooden crate: a frame and a diagonal brace.
void crate(const Frame& f) {
  const double t = std::max(1.0, std::min(f.w, f.h) / 7);
  f.rect(0, 0, 1, 1, crate_wood);
  f.span(f.p.x, f.p.y, f.x(1), f.p.y + t, dark_wood);
  f.span(f.p.x, f.y(1) - t, f.x(1), f.y(1), dark_wood);
  f.span(f.p.x, f.p.y, f.p.x + t, f.y(1), dark_wood);
  f.span(f.x(1) - t, f.p.y, f.x(1), f.y(1), dark_wood);
  f.stroke({f.p.x + t, f.p.y + t}, {f.x(1) - t, f.y(1) - t}, t, dark_wood);
}

bool movable(const Components& c, EntityId e) {
  return std::isfinite(c.mass[e]) && !(c.any_rules() && c.rules(e).sensor);
}

void sprite_block(const Components& c, EntityId e, std::string_view tag, Canvas& canvas) {
  const Vector p = c.position[e];
  const Rect box = c.box[e];
  // A movable block whose tag has no sprite (none, or another game's) is a crate.
  const bool drawn = draw_sprite(tag, p, box, c.color[e], canvas) ||
                     (movable(c, e) && draw_sprite("crate", p, box, c.color[e], canvas));
  if (!drawn) {
    draw_block(c, e, c.color[e], canvas);
    return;
  }
  // A one-way platform keeps its solid face: where it can be stood on.
  if (c.any_rules() && c.rules(e).one_way != Face::none) draw_solid_face(p, box, c.rules(e).one_way, c.color[e], canvas);
}

}  // namespace

Color speed_color(double speed) {
  // Stops at 0, 1/3, 2/3 and 1 of top_speed: blue, green, yellow, red.
  static constexpr std::array<Color, 4> stops{slow_color, Color{40, 185, 70, 255}, Color{245, 210, 40, 255}, fast_color};
  if (!(speed > 0)) return slow_color;  // also NaN: a broken body is not "fast"
  const double s = std::min(speed / top_speed, 1.0) * (stops.size() - 1);
  const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(s), stops.size() - 2);
  const double f = s - static_cast<double>(i);
  const auto mix = [f](std::uint8_t a, std::uint8_t b) { return static_cast<std::uint8_t>(std::lround(a + f * (b - a))); };
  const Color a = stops[i], b = stops[i + 1];
  return {mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b), 255};
}

bool draw_sprite(std::string_view tag, Vector p, Rect r, Color c, Canvas& canvas) {
  const Frame f{canvas, p, double(r.width), double(r.height)};
  if (tag == "player") player(f, c);
  else if (tag == "coin") coin(f);
  else if (tag == "shot") shot(f, c);
  else if (tag == "goal") goal(f, c);
  else if (tag == "target") target(f);
  else if (tag == "platform") platform(f, p, r);
  else if (tag == "crate") crate(f);
  else return false;
  return true;
}

// Tile layers, under the blocks in every style: each row's runs of solid
// cells as one box in the layer's colour, of one-way cells as their top face
// (drawn as a one-way block's). A run per draw call, not a cell: a floor of
// 1000 cells is one box.
void draw_tiles(const World& w, Canvas& canvas) {
  for (const TileLayer& l : w.tiles.layers()) {
    const Vector o = w.components.position[l.body()];
    if (!can_draw(o)) continue;
    const Color col = w.components.color[l.body()];
    const TileGrid& g = l.grid();
    const int cs = g.cell;
    for (int r = 0; r < g.rows; ++r)
      for (int c = 0; c < g.columns;) {
        const Tile t = g.at(c, r);
        int end = c + 1;
        while (end < g.columns && g.at(end, r) == t) ++end;
        const Vector p = o + Vector{static_cast<double>(c) * cs, static_cast<double>(r) * cs};
        if (t == Tile::solid) canvas.fill_rect(p, Rect{(end - c) * cs, cs}, col);
        if (t == Tile::one_way_up) canvas.fill_rect(p, Rect{(end - c) * cs, std::min(solid_face, cs)}, outline_color(col));
        c = end;
      }
  }
}

void draw_world(const World& w, Style style, std::span<const BlockRole> roles, Canvas& canvas) {
  if (w.declares(SystemId::draw)) draw_tiles(w, canvas);
  // plain is the course's own Draw::update, untouched (the look of the sheet).
  if (style == Style::plain || !w.declares(SystemId::draw)) {
    Game::draw(w, canvas);
    return;
  }
  const Components& c = w.components;
  for (const EntityId e : w.bodies(SystemId::draw)) {
    if (!can_draw(c.position[e])) continue;  // as Draw: nothing undefined to the canvas
    if (style == Style::speed) {
      // Fixed bodies and sensors do not move: their own colour says more.
      draw_block(c, e, movable(c, e) ? speed_color(Vector::norm(c.velocity[e])) : c.color[e], canvas);
    } else {
      sprite_block(c, e, e < roles.size() ? std::string_view(roles[e].tag) : std::string_view(), canvas);
    }
  }
}

}  // namespace physics::Styles
