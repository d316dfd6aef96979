// Draw system (course: systems/draw.ml): fills each block's box in its
// colour, on a Canvas: the course's Gfx layer. The window gives an SDL
// canvas (app/window.cpp), headless screenshots a pixel buffer
// (app/offscreen.cpp); the system itself needs no SDL.
#pragma once

#include "component_defs.hpp"

namespace physics {

class Canvas {
 public:
  virtual ~Canvas() = default;
  // Fills the box of size r whose top-left corner is at p.
  virtual void fill_rect(Vector p, Rect r, Color c) = 0;
};

class Draw : public System<component::position, component::box, component::color> {
 public:
  void update(const Components& c, Canvas& canvas) const;
};

}  // namespace physics
