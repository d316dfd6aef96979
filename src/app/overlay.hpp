// The testbed's picture over the blocks, drawn the same way by every front
// end: the window (app/window.cpp, SDL) and the browser (web/draw_commands,
// a list of commands for a <canvas>). Each gives a Painter; the layout, the
// colours and the order of drawing are here once.
#pragma once

#include <string>
#include <vector>

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
  virtual double char_width() const = 0;  // px: the HUD's font is monospace
  void fill_rect(Vector p, Rect r, Color c) override { fill_box(p.x, p.y, r.width, r.height, c); }
};

// The camera on another painter: boxes and lines given in world px are
// drawn at their place on the screen (those wholly outside the view are
// left out); text is the screen's, as given.
class CameraPainter final : public Painter {
 public:
  CameraPainter(const Camera& c, Painter& screen) : c_(c), p_(screen) {}
  void fill_box(double x, double y, double w, double h, Color c) override;
  void stroke_box(double x, double y, double w, double h, Color c) override;
  void line(Vector a, Vector b, Color c) override;
  int text(const std::string& s, int x, int y, Color c) override { return p_.text(s, x, y, c); }
  int line_height() const override { return p_.line_height(); }
  double char_width() const override { return p_.char_width(); }

 private:
  bool seen(double x, double y, double w, double h) const;
  const Camera& c_;
  Painter& p_;
};

namespace Overlay {

// Draw's part: the blocks in the view's style (Styles::draw_world), through
// the view's camera.
void bodies(const World& world, const View& view, Painter& p);
// Over them, in this order, through the camera: the boxes and velocities
// (when the world draws), the last step's contacts, the sling and its
// aiming preview, the ray; then on the screen: the HUD panel at the top
// left (with the speed style's key) and the key list's at the right, below
// it, both wrapped to the view's width.
void over(const World& world, const View& view, Painter& p);
// `s` broken into lines of at most `chars` characters, after a space where
// it can; the lines after the first start with two spaces.
std::vector<std::string> wrap(const std::string& s, std::size_t chars);

}  // namespace Overlay

}  // namespace physics
