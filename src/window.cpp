#include "window.hpp"

#include <SDL.h>
#include <SDL_ttf.h>

#include <cstdlib>
#include <vector>

#include "utils/png.hpp"

namespace physics {
namespace {

struct SdlDeleter {
  void operator()(SDL_Window* w) const { SDL_DestroyWindow(w); }
  void operator()(SDL_Renderer* r) const { SDL_DestroyRenderer(r); }
  void operator()(TTF_Font* f) const { TTF_CloseFont(f); }
  void operator()(SDL_Surface* s) const { SDL_FreeSurface(s); }
  void operator()(SDL_Texture* t) const { SDL_DestroyTexture(t); }
};
template <class T>
using Owned = std::unique_ptr<T, SdlDeleter>;

// SDL_Init / TTF_Init paired with their Quit, in construction order.
struct SdlVideo {
  SdlVideo() {
    if (SDL_Init(SDL_INIT_VIDEO) != 0) throw WindowError(std::string("cannot start SDL video: ") + SDL_GetError());
  }
  ~SdlVideo() { SDL_Quit(); }
  SdlVideo(const SdlVideo&) = delete;
  SdlVideo& operator=(const SdlVideo&) = delete;
};
struct SdlTtf {
  bool ok = TTF_Init() == 0;
  ~SdlTtf() {
    if (ok) TTF_Quit();
  }
};

std::string find_font() {
  if (const char* env = std::getenv("PHYSICS_FONT")) return env;
  return "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf";
}

}  // namespace

struct Window::Impl {
  SdlVideo video;
  SdlTtf ttf;
  Owned<SDL_Window> window;
  Owned<SDL_Renderer> renderer;
  Owned<TTF_Font> font;
  std::string hud_warning;
  int width, height;
};

Window::Window(int width, int height, const std::string& title) : impl_(std::make_unique<Impl>()) {
  Impl& w = *impl_;
  w.width = width;
  w.height = height;
  w.window.reset(SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width, height,
                                  SDL_WINDOW_SHOWN));
  if (!w.window) throw WindowError(std::string("cannot open a window: ") + SDL_GetError());
  w.renderer.reset(SDL_CreateRenderer(w.window.get(), -1, SDL_RENDERER_ACCELERATED | SDL_RENDERER_PRESENTVSYNC));
  if (!w.renderer) w.renderer.reset(SDL_CreateRenderer(w.window.get(), -1, SDL_RENDERER_SOFTWARE));
  if (!w.renderer) throw WindowError(std::string("cannot create a renderer: ") + SDL_GetError());
  if (!w.ttf.ok) {
    w.hud_warning = std::string("SDL_ttf failed to start (") + TTF_GetError() + "); HUD off";
  } else {
    const std::string path = find_font();
    w.font.reset(TTF_OpenFont(path.c_str(), 14));
    if (!w.font) w.hud_warning = "font " + path + " not found (" + TTF_GetError() + "); HUD off";
  }
}

Window::~Window() = default;

const std::string& Window::hud_warning() const { return impl_->hud_warning; }

double Window::seconds() const {
  return static_cast<double>(SDL_GetPerformanceCounter()) / static_cast<double>(SDL_GetPerformanceFrequency());
}

std::vector<InputEvent> Window::poll_events() {
  std::vector<InputEvent> out;
  SDL_Event ev;
  while (SDL_PollEvent(&ev)) {
    switch (ev.type) {
      case SDL_QUIT: out.push_back({InputEvent::Kind::quit}); break;
      case SDL_KEYDOWN: out.push_back({InputEvent::Kind::key, ev.key.keysym.sym}); break;
      case SDL_MOUSEBUTTONDOWN:
        out.push_back({InputEvent::Kind::mouse_down, 0, ev.button.x, ev.button.y, ev.button.button});
        break;
      case SDL_MOUSEBUTTONUP:
        out.push_back({InputEvent::Kind::mouse_up, 0, ev.button.x, ev.button.y, ev.button.button});
        break;
      case SDL_MOUSEMOTION: out.push_back({InputEvent::Kind::mouse_move, 0, ev.motion.x, ev.motion.y}); break;
      default: break;
    }
  }
  return out;
}

void Window::render(const World& world, const std::vector<std::string>& hud) {
  SDL_Renderer* r = impl_->renderer.get();
  SDL_SetRenderDrawColor(r, 255, 255, 255, 255);
  SDL_RenderClear(r);
  if (world.systems.draw) world.systems.draw->update(world.components, r);
  if (!impl_->font) return;
  int y = 44;
  for (const std::string& line : hud) {
    Owned<SDL_Surface> surf(TTF_RenderUTF8_Blended(impl_->font.get(), line.c_str(), SDL_Color{20, 20, 20, 255}));
    if (!surf) continue;
    Owned<SDL_Texture> tex(SDL_CreateTextureFromSurface(r, surf.get()));
    if (!tex) continue;
    const SDL_Rect dst{48, y, surf->w, surf->h};
    SDL_RenderCopy(r, tex.get(), nullptr, &dst);
    y += surf->h + 2;
  }
}

void Window::present() { SDL_RenderPresent(impl_->renderer.get()); }

void Window::screenshot(const std::string& path) {
  const int w = impl_->width, h = impl_->height;
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(w) * h * 3);
  if (SDL_RenderReadPixels(impl_->renderer.get(), nullptr, SDL_PIXELFORMAT_RGB24, rgb.data(), w * 3) != 0)
    throw WindowError(std::string("cannot read the window's pixels: ") + SDL_GetError());
  if (!Png::write_rgb(path, w, h, rgb)) throw WindowError("cannot write " + path);
}

bool display_available() {
  const auto set = [](const char* v) {
    const char* s = std::getenv(v);
    return s != nullptr && *s != '\0';
  };
  return set("DISPLAY") || set("WAYLAND_DISPLAY") || set("SDL_VIDEODRIVER");
}

}  // namespace physics
