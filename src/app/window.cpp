#include "app/window.hpp"

#include <SDL.h>
#include <SDL_ttf.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "app/png.hpp"
#include "app/style.hpp"
#include "course/game.hpp"

namespace physics {

// input/keys.hpp's key codes are SDL's.
static_assert(key::escape == SDLK_ESCAPE && key::tab == SDLK_TAB && key::space == SDLK_SPACE &&
              key::enter == SDLK_RETURN && key::right == SDLK_RIGHT && key::left == SDLK_LEFT && key::up == SDLK_UP &&
              'a' == SDLK_a && '1' == SDLK_1);

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
      case SDL_KEYUP: out.push_back({InputEvent::Kind::key_up, ev.key.keysym.sym}); break;
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

namespace {

// Overlay colours: distinct from the walls (blue/black) and the blocks.
constexpr SDL_Color aabb_colour{0, 170, 0, 255};
constexpr SDL_Color velocity_colour{200, 0, 200, 255};
constexpr SDL_Color normal_colour{230, 0, 0, 255};
constexpr SDL_Color penetration_colour{0, 120, 255, 255};
constexpr SDL_Color contact_colour{255, 200, 0, 255};  // the shared edge
constexpr SDL_Color ray_colour{0, 150, 150, 255};
constexpr double velocity_scale = 100.0;    // px of arrow per px/ms: the distance covered in 100 ms
constexpr double normal_length = 24.0;      // px
constexpr double penetration_scale = 4.0;   // penetrations are a few px: drawn 4x

void set_colour(SDL_Renderer* r, SDL_Color c) { SDL_SetRenderDrawColor(r, c.r, c.g, c.b, c.a); }

bool drawable(Vector p) { return std::abs(p.x) < 1e6 && std::abs(p.y) < 1e6; }

void line(SDL_Renderer* r, Vector a, Vector b) {
  if (!drawable(a) || !drawable(b)) return;
  SDL_RenderDrawLineF(r, float(a.x), float(a.y), float(b.x), float(b.y));
}

// A line with a small head, so the direction reads at a glance.
void arrow(SDL_Renderer* r, Vector from, Vector to) {
  line(r, from, to);
  const Vector d = to - from;
  const double n = Vector::norm(d);
  if (n < 1e-9) return;
  const Vector u = Vector::mult(1.0 / n, d), side{-u.y, u.x};
  const double head = std::min(6.0, n / 2);
  line(r, to, to - head * u + (head / 2) * side);
  line(r, to, to - head * u - (head / 2) * side);
}

Vector centre(const Components& c, EntityId e) {
  return c.position[e] + Vector{c.box[e].width / 2.0, c.box[e].height / 2.0};
}

// An arrow on a white halo, so that it reads on a block of its own colour
// (a red normal on the red block).
void haloed_arrow(SDL_Renderer* r, Vector from, Vector to, SDL_Color col) {
  set_colour(r, SDL_Color{255, 255, 255, 255});
  for (const Vector d : {Vector{1, 0}, Vector{-1, 0}, Vector{0, 1}, Vector{0, -1}}) arrow(r, from + d, to + d);
  set_colour(r, col);
  arrow(r, from, to);
}

// The last step's contacts where the bodies met: the shared edge (a thick
// segment) and, from its middle, the normal and the penetration.
void draw_contacts(SDL_Renderer* r, const View& view) {
  for (std::size_t i = 0; i < view.contacts.size() && i < view.contact_regions.size(); ++i) {
    const Contact& k = view.contacts[i];
    const ContactRegion& g = view.contact_regions[i];
    if (!drawable(g.lo) || !drawable(g.hi)) continue;
    set_colour(r, contact_colour);
    const SDL_FRect edge{float(g.lo.x - 1), float(g.lo.y - 1), float(g.hi.x - g.lo.x + 2), float(g.hi.y - g.lo.y + 2)};
    SDL_RenderFillRectF(r, &edge);
    const Vector at = g.middle();
    haloed_arrow(r, at, at + penetration_scale * k.penetration, penetration_colour);
    haloed_arrow(r, at, at + normal_length * k.normal, normal_colour);
  }
}

// The right drag's ray: solid up to the first body it enters, faint beyond
// (the whole drag solid when it hits nothing), a small square on the hit
// and the normal of the face hit.
void draw_ray(SDL_Renderer* r, const RayView& ray) {
  const Vector end = ray.hit ? ray.hit->point : ray.to;
  set_colour(r, ray_colour);
  line(r, ray.from, end);
  if (!ray.hit || !drawable(end)) return;
  set_colour(r, SDL_Color{ray_colour.r, ray_colour.g, ray_colour.b, 80});
  line(r, end, ray.to);
  haloed_arrow(r, end, end + normal_length * ray.hit->normal, ray_colour);
  // The square over the arrow's foot, so that the halo does not hide it.
  set_colour(r, ray_colour);
  const SDL_FRect mark{float(end.x - 3), float(end.y - 3), 7, 7};
  SDL_RenderFillRectF(r, &mark);
}

// Draw's bodies and the overlays drawn over them (boxes, velocities).
// Returns Draw's time, ms: the renderer batches its commands, so they are
// flushed inside the timed span (otherwise the time is only the queuing).
// The course's Draw system on the window's renderer.
class SdlCanvas final : public Canvas {
 public:
  explicit SdlCanvas(SDL_Renderer* r) : r_(r) {}
  void fill_rect(Vector p, Rect box, Color col) override {
    SDL_SetRenderDrawColor(r_, col.r, col.g, col.b, col.a);
    const SDL_FRect rect{static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(box.width),
                         static_cast<float>(box.height)};
    SDL_RenderFillRectF(r_, &rect);
  }

 private:
  SDL_Renderer* r_;
};

// The speed style's key, under the HUD lines: the ramp (Styles::speed_color)
// as a bar from 0 to its top speed, with the end values. Returns the y below it.
template <class Text>
int speed_legend(SDL_Renderer* r, int x, int y, const Text& text) {
  constexpr int bar_w = 160, bar_h = 12;
  const int left = text("speed 0", x, y, SDL_Color{20, 20, 20, 255});
  const int bx = x + 70;
  SdlCanvas canvas(r);
  for (int i = 0; i < bar_w; ++i)
    canvas.fill_rect({double(bx + i), double(y + 2)}, {1, bar_h},
                     Styles::speed_color(Styles::top_speed * i / (bar_w - 1)));
  char top[32];
  std::snprintf(top, sizeof top, ">= %g px/ms", Styles::top_speed);
  const int right = text(top, bx + bar_w + 6, y, SDL_Color{20, 20, 20, 255});
  return y + std::max({left, right, bar_h + 4}) + 2;
}

double render_bodies(const World& world, const View& view, SDL_Renderer* r) {
  const auto draw = world.bodies(SystemId::draw);
  const Uint64 t0 = SDL_GetPerformanceCounter();
  SdlCanvas canvas(r);
  Styles::draw_world(world, view.style, view.roles, canvas);
  SDL_RenderFlush(r);
  const double draw_ms =
      1000.0 * static_cast<double>(SDL_GetPerformanceCounter() - t0) / static_cast<double>(SDL_GetPerformanceFrequency());

  const Components& c = world.components;
  if (view.overlays.aabb) {
    set_colour(r, aabb_colour);
    for (const EntityId e : draw) {
      if (!drawable(c.position[e])) continue;
      const SDL_FRect box{float(c.position[e].x), float(c.position[e].y), float(c.box[e].width),
                          float(c.box[e].height)};
      SDL_RenderDrawRectF(r, &box);
    }
  }
  if (view.overlays.velocity) {
    set_colour(r, velocity_colour);
    for (const EntityId e : draw)
      if (!Vector::is_zero(c.velocity[e])) arrow(r, centre(c, e), centre(c, e) + velocity_scale * c.velocity[e]);
  }
  return draw_ms;
}

}  // namespace

double Window::render(const World& world, const View& view) {
  SDL_Renderer* r = impl_->renderer.get();
  SDL_SetRenderDrawBlendMode(r, SDL_BLENDMODE_BLEND);
  SDL_SetRenderDrawColor(r, 255, 255, 255, 255);
  SDL_RenderClear(r);
  // A scene without Draw shows no body, but the HUD, key list and contacts
  // still show (the HUD says "draw off").
  double draw_ms = 0.0;
  if (world.declares(SystemId::draw)) draw_ms = render_bodies(world, view, r);
  draw_contacts(r, view);
  if (view.sling) {
    const auto [from, to] = *view.sling;
    set_colour(r, SDL_Color{255, 140, 0, 255});
    line(r, from, to);
    const SDL_FRect ghost{float(from.x - Testbed::spawn_size / 2.0), float(from.y - Testbed::spawn_size / 2.0),
                          float(Testbed::spawn_size), float(Testbed::spawn_size)};
    SDL_RenderDrawRectF(r, &ghost);
  }
  if (view.ray) draw_ray(r, *view.ray);

  if (!impl_->font) return draw_ms;
  // Text on a pale backdrop, readable over a crowded scene.
  const auto text = [&](const std::string& s, int x, int y, SDL_Color col) {
    Owned<SDL_Surface> surf(TTF_RenderUTF8_Blended(impl_->font.get(), s.c_str(), col));
    if (!surf) return 0;
    Owned<SDL_Texture> tex(SDL_CreateTextureFromSurface(r, surf.get()));
    if (!tex) return 0;
    const SDL_Rect dst{x, y, surf->w, surf->h};
    SDL_SetRenderDrawColor(r, 255, 255, 255, 170);
    SDL_RenderFillRect(r, &dst);
    SDL_RenderCopy(r, tex.get(), nullptr, &dst);
    return surf->h;
  };
  int y = 44;
  for (const std::string& s : view.hud) y += text(s, 48, y, SDL_Color{20, 20, 20, 255}) + 2;
  if (view.style == Style::speed && view.overlays.hud) y = speed_legend(r, 48, y + 2, text);
  if (!view.help.empty()) {
    const int line_h = TTF_FontLineSkip(impl_->font.get());
    // Below the HUD, so that neither hides the other.
    const SDL_Rect panel{impl_->width - 460, y + 8, 410, static_cast<int>(view.help.size()) * line_h + 16};
    SDL_SetRenderDrawColor(r, 255, 255, 240, 225);
    SDL_RenderFillRect(r, &panel);
    SDL_SetRenderDrawColor(r, 60, 60, 60, 255);
    SDL_RenderDrawRect(r, &panel);
    int hy = panel.y + 8;
    for (const std::string& s : view.help) hy += text(s, panel.x + 10, hy, SDL_Color{20, 20, 20, 255});
  }
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
