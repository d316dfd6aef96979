// The browser's drawing: what Window::render (app/window.cpp) draws with SDL,
// as a list of commands that the page paints on its <canvas> (web/front.js).
// The blocks go through the same Styles::draw_world as the window and the
// offscreen pictures (a Canvas whose fill_rect records a command); the
// overlays, the HUD and the key list follow window.cpp's layout.
//
// The list is floats, one command after another, each opcode first:
//   1 fill x y w h r g b a     2 stroke (1 px outline) x y w h r g b a
//   3 line x1 y1 x2 y2 r g b a  4 text x y r g b a: the next line of texts()
// Colours 0-255. Text is the HUD's (14 px monospace), on a pale backdrop.
#pragma once

#include <string>
#include <vector>

#include "app/testbed.hpp"

namespace physics::web {

enum Op { fill = 1, stroke = 2, line = 3, text = 4 };
inline constexpr int line_height = 17;  // px, 14 px DejaVu Sans Mono's line skip

class Commands final : public Canvas {
 public:
  void clear() { ops_.clear(), texts_.clear(); }
  void fill_rect(Vector p, Rect r, Color c) override { box(fill, p.x, p.y, r.width, r.height, c); }
  void box(Op op, double x, double y, double w, double h, Color c);
  void segment(Vector a, Vector b, Color c);
  void write(const std::string& s, double x, double y, Color c);
  const std::vector<float>& ops() const { return ops_; }
  const std::string& texts() const { return texts_; }  // one line per text command, '\n' after each

 private:
  void colour(Color c);
  std::vector<float> ops_;
  std::string texts_;
};

// The window's picture of `world` and `view` (app/window.cpp's Window::render)
// on a width-wide canvas, into `out` (cleared first).
void render(const World& world, const View& view, int width, Commands& out);

}  // namespace physics::web
