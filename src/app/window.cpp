#include "app/window.hpp"

#include <SDL.h>
#include <SDL_ttf.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "app/overlay.hpp"
#include "app/png.hpp"
#include "app/style.hpp"
#include "course/game.hpp"

namespace physics {

// input/keys.hpp's key codes are SDL's.
static_assert(key::escape == SDLK_ESCAPE && key::tab == SDLK_TAB && key::space == SDLK_SPACE &&
              key::enter == SDLK_RETURN && key::right == SDLK_RIGHT && key::left == SDLK_LEFT && key::down == SDLK_DOWN && key::up == SDLK_UP &&
              'a' == SDLK_a && '1' == SDLK_1 && key::lshift == SDLK_LSHIFT && key::rshift == SDLK_RSHIFT);

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

// The screen's room for a window: its usable bounds (without the task
// bars), less a title bar's height; unknown, the world's size.
Vector usable_area(int world_width, int world_height) {
  SDL_Rect r;
  if (SDL_GetDisplayUsableBounds(0, &r) != 0 || r.w <= 0 || r.h <= 0) return {double(world_width), double(world_height)};
  constexpr int title_bar = 32;
  return {double(r.w), double(std::max(1, r.h - title_bar))};
}

Window::Window(int world_width, int world_height, const std::string& title) : impl_(std::make_unique<Impl>()) {
  Impl& w = *impl_;
  const Vector size = window_size({double(world_width), double(world_height)}, usable_area(world_width, world_height));
  w.width = static_cast<int>(size.x);
  w.height = static_cast<int>(size.y);
  w.window.reset(SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, w.width, w.height,
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
int Window::width() const { return impl_->width; }
int Window::height() const { return impl_->height; }

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
      case SDL_KEYUP: out.push_back({InputEvent::Kind::key_up, ev.key.keysym.sym}); break;
      case SDL_MOUSEBUTTONDOWN:
        out.push_back({InputEvent::Kind::mouse_down, 0, ev.button.x, ev.button.y, ev.button.button});
        break;
      case SDL_MOUSEBUTTONUP:
        out.push_back({InputEvent::Kind::mouse_up, 0, ev.button.x, ev.button.y, ev.button.button});
        break;
      case SDL_MOUSEMOTION: out.push_back({InputEvent::Kind::mouse_move, 0, ev.motion.x, ev.motion.y}); break;
      case SDL_MOUSEWHEEL: {
        int x = 0, y = 0;  // the wheel's event has no position before SDL 2.26
        SDL_GetMouseState(&x, &y);
        const int notches = ev.wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -ev.wheel.y : ev.wheel.y;
        if (notches != 0) out.push_back({InputEvent::Kind::wheel, notches, x, y});
        break;
      }
      default: break;
    }
  }
  return out;
}

namespace {

SDL_Color sdl(Color c) { return SDL_Color{c.r, c.g, c.b, c.a}; }

// The overlays' primitives (app/overlay.hpp) on the window's renderer, with
// the HUD font (none: no text).
class SdlPainter final : public Painter {
 public:
  SdlPainter(SDL_Renderer* r, TTF_Font* font) : r_(r), font_(font) {}
  void fill_box(double x, double y, double w, double h, Color c) override {
    colour(c);
    const SDL_FRect rect{float(x), float(y), float(w), float(h)};
    SDL_RenderFillRectF(r_, &rect);
  }
  void stroke_box(double x, double y, double w, double h, Color c) override {
    colour(c);
    const SDL_FRect rect{float(x), float(y), float(w), float(h)};
    SDL_RenderDrawRectF(r_, &rect);
  }
  void line(Vector a, Vector b, Color c) override {
    colour(c);
    SDL_RenderDrawLineF(r_, float(a.x), float(a.y), float(b.x), float(b.y));
  }
  int text(const std::string& s, int x, int y, Color c) override {
    if (!font_) return 0;
    Owned<SDL_Surface> surf(TTF_RenderUTF8_Blended(font_, s.c_str(), sdl(c)));
    if (!surf) return 0;
    Owned<SDL_Texture> tex(SDL_CreateTextureFromSurface(r_, surf.get()));
    if (!tex) return 0;
    // On a pale backdrop, readable over a crowded scene.
    const SDL_Rect dst{x, y, surf->w, surf->h};
    SDL_SetRenderDrawColor(r_, 255, 255, 255, 170);
    SDL_RenderFillRect(r_, &dst);
    SDL_RenderCopy(r_, tex.get(), nullptr, &dst);
    return surf->h;
  }
  int line_height() const override { return font_ ? TTF_FontLineSkip(font_) : 0; }
  double char_width() const override {
    int advance = 0;
    if (!font_ || TTF_GlyphMetrics(font_, 'M', nullptr, nullptr, nullptr, nullptr, &advance) != 0) return 9.0;
    return advance;
  }

 private:
  void colour(Color c) { SDL_SetRenderDrawColor(r_, c.r, c.g, c.b, c.a); }
  SDL_Renderer* r_;
  TTF_Font* font_;
};

}  // namespace

double Window::render(const World& world, const View& view) {
  SDL_Renderer* r = impl_->renderer.get();
  SDL_SetRenderDrawBlendMode(r, SDL_BLENDMODE_BLEND);
  SDL_SetRenderDrawColor(r, 255, 255, 255, 255);
  SDL_RenderClear(r);
  SdlPainter painter(r, impl_->font.get());
  // A scene without Draw shows no body, but the HUD, key list and contacts
  // still show (the HUD says "draw off"). Draw's time: the renderer batches
  // its commands, so they are flushed inside the timed span (otherwise the
  // time is only the queuing).
  double draw_ms = 0.0;
  if (world.declares(SystemId::draw)) {
    const Uint64 t0 = SDL_GetPerformanceCounter();
    Overlay::bodies(world, view, painter);
    SDL_RenderFlush(r);
    draw_ms = 1000.0 * static_cast<double>(SDL_GetPerformanceCounter() - t0) /
              static_cast<double>(SDL_GetPerformanceFrequency());
  }
  Overlay::over(world, view, painter);
  return draw_ms;
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
