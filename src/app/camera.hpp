// The testbed's camera: which part of the world the window shows, and how
// big. Picture only: the physics never sees it, and the testbed maps the
// mouse through it to world coordinates before handling (and logging) a
// click, so a replay lands on the same world point whatever the window.
//
// A world that fits the window is shown whole at scale 1 (centred when it is
// smaller); a larger one is scaled down to fit, or, in a game with a player,
// followed at scale 1 (the player kept inside a dead zone around the
// centre). The wheel zooms about the cursor; a drag pans. The view never
// leaves the world: on an axis where the world is narrower than the view it
// is centred, on the others clamped to its edges.
#pragma once

#include "course/utils/vect.hpp"

namespace physics {

struct Camera {
  static constexpr double max_scale = 8.0;   // screen px per world px
  static constexpr double dead_zone = 0.15;  // of the view's size, each side of its centre
  static constexpr double wheel_step = 1.25; // zoom factor per wheel notch

  Vector eye{};        // the world point at the view's top-left corner
  double scale = 1.0;  // screen px per world px
  Vector view{};       // the view's size, screen px
  Vector world{};      // the world's size, px

  // The whole world (scale at most 1), centred.
  static Camera fit(Vector world, Vector view);
  // Scale 1 centred on `focus` (clamped): a followed player.
  static Camera on(Vector focus, Vector world, Vector view);

  Vector to_screen(Vector w) const { return scale * (w - eye); }
  Vector to_world(Vector s) const { return eye + (1.0 / scale) * s; }
  double min_scale() const;  // half the fit's scale (at most 1/2)
  // Zooms by `factor` (clamped to [min_scale, max_scale]); the world point
  // under the screen point `at` stays under it (unless clamped at an edge).
  void zoom_about(Vector at, double factor);
  void pan(Vector screen_delta);  // the world moves with the drag
  // Moves just enough to bring `focus` back into the dead zone.
  void follow(Vector focus);
  void clamp();
};

// The window for a world, px: the world's size where the screen's usable
// area holds it, else that area; never smaller than min_window (the HUD and
// the key list need the room; a smaller world is centred in it).
inline constexpr Vector min_window{640, 480};
Vector window_size(Vector world, Vector usable);

}  // namespace physics
