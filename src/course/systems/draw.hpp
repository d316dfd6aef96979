// Draw system (course: systems/draw.ml): fills each block's box in its
// colour (and outlines it), on a Canvas: the course's Gfx layer. The window gives an SDL
// canvas (app/window.cpp), headless screenshots a pixel buffer
// (app/offscreen.cpp); the system itself needs no SDL.
#pragma once

#include <cmath>

#include "engine/components.hpp"

namespace physics {

class Canvas {
 public:
  virtual ~Canvas() = default;
  // Fills the box of size r whose top-left corner is at p.
  virtual void fill_rect(Vector p, Rect r, Color c) = 0;
};

// Each block also gets a 1 px outline inside its box, a darker shade of its
// colour, so that touching blocks of one colour (a stack, the cradle) read
// as separate blocks; not on blocks narrower than min_outlined px.
inline constexpr int min_outlined = 6;
Color outline_color(Color c);
void outline(Vector p, Rect r, Color c, Canvas& canvas);

// Beyond the sheet (docs/game-physics.md): a sensor is drawn as its outline
// only, 2 px in its colour (nothing stops there); a one-way platform gets
// its solid face drawn `solid_face` px thick in the outline's shade.
inline constexpr int solid_face = 4;
void draw_sensor(Vector p, Rect r, Color c, Canvas& canvas);
void draw_solid_face(Vector p, Rect r, Face face, Color c, Canvas& canvas);

// One body as Draw paints it, in colour `col` (its own, or a drawing
// style's: app/style.hpp): a sensor's outline, or the filled box, its
// outline and a one-way platform's solid face.
void draw_block(const Components& c, EntityId e, Color col, Canvas& canvas);
// Whether a body at p can be drawn: not NaN, nor far outside int range
// (what the canvas converts to pixels).
inline bool can_draw(Vector p) { return std::abs(p.x) < 1e9 && std::abs(p.y) < 1e9; }

class Draw : public System<component::position, component::box, component::color> {
 public:
  using System::System;  // bound to a world's list (course/system_defs.hpp)
  void update(const Components& c, Canvas& canvas) const;
};

}  // namespace physics
