// The browser's drawing: what Window::render (app/window.cpp) draws with SDL,
// as a list of commands that the page paints on its <canvas> (web/front.js).
// Everything is drawn by app/overlay.cpp, as in the window: this file only
// records its primitives.
//
// The list is floats, one command after another, each opcode first:
//   1 fill x y w h r g b a     2 stroke (1 px outline) x y w h r g b a
//   3 line x1 y1 x2 y2 r g b a  4 text x y r g b a: the next line of texts()
// Colours 0-255. Text is the HUD's (14 px monospace), on a pale backdrop.
#pragma once

#include <string>
#include <vector>

#include "app/overlay.hpp"

namespace physics::web {

enum Op { fill = 1, stroke = 2, line = 3, text = 4 };
inline constexpr int line_height = 17;  // px, 14 px DejaVu Sans Mono's line skip
inline constexpr double char_width = 8.5;  // px, its advance (8.43), rounded up

// The overlays' primitives (app/overlay.hpp) as commands.
class Commands final : public Painter {
 public:
  void clear() { ops_.clear(), texts_.clear(); }
  void fill_box(double x, double y, double w, double h, Color c) override { box(fill, x, y, w, h, c); }
  void stroke_box(double x, double y, double w, double h, Color c) override { box(stroke, x, y, w, h, c); }
  void line(Vector a, Vector b, Color c) override;
  int text(const std::string& s, int x, int y, Color c) override;
  int line_height() const override { return web::line_height; }
  double char_width() const override { return web::char_width; }
  const std::vector<float>& ops() const { return ops_; }
  const std::string& texts() const { return texts_; }  // one line per text command, '\n' after each

 private:
  void box(Op op, double x, double y, double w, double h, Color c);
  void colour(Color c);
  std::vector<float> ops_;
  std::string texts_;
};

// The window's picture of `world` and `view` (Window::render: app/overlay's
// drawing, through the view's camera) into `out` (cleared first).
void render(const World& world, const View& view, Commands& out);

}  // namespace physics::web
