// The testbed's picture over the blocks, drawn the same way by every front
// end: the window (app/window.cpp, SDL) and the browser (web/draw_commands,
// a list of commands for a <canvas>). Each gives a Painter; the layout, the
// colours and the order of drawing are here once.
#pragma once

#include <string>

#include "app/testbed.hpp"

namespace physics {

// What a front end draws with: the course's Canvas (Draw's fill_rect) and the
// overlays' primitives. Coordinates in px, y down.
class Painter : public Canvas {
 public:
  virtual void fill_box(double x, double y, double w, double h, Color c) = 0;
  virtual void stroke_box(double x, double y, double w, double h, Color c) = 0;  // a 1 px outline
  virtual void line(Vector a, Vector b, Color c) = 0;
  // s with its top-left corner at (x, y), on a pale backdrop; returns its
  // height in px (0 if it cannot draw text).
  virtual int text(const std::string& s, int x, int y, Color c) = 0;
  virtual int line_height() const = 0;  // 0: no text at all (no font)
  void fill_rect(Vector p, Rect r, Color c) override { fill_box(p.x, p.y, r.width, r.height, c); }
};

namespace Overlay {

// Draw's part: the blocks in the view's style (Styles::draw_world).
void bodies(const World& world, const View& view, Painter& p);
// Over them, in this order: the boxes and velocities (when the world draws),
// the last step's contacts, the sling, the ray, the HUD lines, the speed
// style's key and the key list (at the right of a `width`-wide window).
void over(const World& world, const View& view, int width, Painter& p);

}  // namespace Overlay

}  // namespace physics
