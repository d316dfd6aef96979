// Drawing styles (scene key "style", flag --style), the sheet's closing ideas:
// "changer le style graphique (en fonction de la vitesse par exemple)" and
// "dessiner un objet non rectangulaire à l'intérieur de la boîte ... mais les
// collisions utilisent la boîte". The one place that knows how a style looks:
// the window (window.cpp) and the offscreen pictures (offscreen.cpp) both call
// draw_world on their Canvas, so a headless screenshot shows what the window
// shows. Everything is drawn with Canvas::fill_rect (a disc is a run of one
// pixel high rectangles), so no SDL here: part of the physics library.
//
//   plain   the course's Draw system, unchanged (Game::draw)
//   speed   each movable block filled with speed_color(|v|); fixed bodies and
//           sensors as plain
//   sprite  a shape inside each box by its tag (BlockRole): player, coin,
//           goal, target, platform, crate, shot (a ball); an untagged movable block is a
//           crate; walls and fixed untagged blocks as plain
#pragma once

#include <span>
#include <string_view>

#include "scene/scene.hpp"
#include "engine/world.hpp"
#include "course/systems/draw.hpp"

namespace physics::Styles {

// The speed ramp: blue at rest, then green, yellow, and red at top_speed and
// above. 1 px/ms is a block crossing the 800 px window in under a second,
// faster than anything gravity gives in a built-in scene's fall (0.6 px/ms),
// and the sheet's launch speeds are 0.25-0.4 px/ms: those read as green.
inline constexpr double top_speed = 1.0;  // px/ms
Color speed_color(double speed);
inline constexpr Color slow_color{40, 90, 230, 255};   // speed_color(0)
inline constexpr Color fast_color{225, 35, 30, 255};   // speed_color(top_speed)

// The sprites' fixed colours (the tests look for them).
inline constexpr Color coin_gold{245, 200, 50, 255};
inline constexpr Color skin{250, 205, 160, 255};
inline constexpr Color trousers{45, 55, 125, 255};
inline constexpr Color crate_wood{205, 155, 90, 255};
inline constexpr Color target_red{220, 30, 30, 255};
inline constexpr Color white{255, 255, 255, 255};

// Draws the world's Draw bodies in `style` on `canvas` (nothing without a
// Draw system, as Game::draw). `roles`: each body's tag by entity id (a body
// beyond it, e.g. spawned later, is untagged); only sprite reads it.
void draw_world(const World& w, Style style, std::span<const BlockRole> roles, Canvas& canvas);

// One block's sprite for `tag` inside the box at p of size r, `c` its colour
// (the player's shirt, the goal's flag). False when the tag has no sprite
// ("wall", "", unknown tags): the caller draws the box as plain.
bool draw_sprite(std::string_view tag, Vector p, Rect r, Color c, Canvas& canvas);

}  // namespace physics::Styles
