// The SDL front end: a window, its renderer and the HUD font, owned RAII-style.
// This header names no SDL type, so game.cpp and the tests need no SDL headers;
// window.cpp is built into the game program only.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/testbed.hpp"
#include "engine/world.hpp"

namespace physics {

struct WindowError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Window {
 public:
  // Opens a window for a world of the given size: that size if the
  // screen's usable area holds it, else one that fits (window_size, app/
  // camera.hpp). Throws WindowError when no display can be opened (the
  // caller falls back to a headless run). A missing font is not an error:
  // the HUD is then off and `hud_warning()` says why.
  Window(int world_width, int world_height, const std::string& title);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  std::vector<InputEvent> poll_events();
  // Clears, draws the world through its Draw system and the view's camera,
  // then the overlays the view asks for (AABBs, velocities, contacts, the
  // slingshot), the HUD and the key list. Returns the Draw system's time, ms.
  double render(const World& world, const View& view);
  void present();
  // Saves what the last render() drew, as PNG.
  void screenshot(const std::string& path);
  const std::string& hud_warning() const;
  int width() const;  // px, the window's (its renderer's output)
  int height() const;
  // Monotonic seconds, from SDL's high resolution counter.
  double seconds() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// True when a display looks available (DISPLAY or WAYLAND_DISPLAY set, or an
// explicit SDL_VIDEODRIVER). Checked before touching SDL at all, so a headless
// machine never initialises it.
bool display_available();

}  // namespace physics
