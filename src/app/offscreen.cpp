#include "app/offscreen.hpp"

#include <algorithm>
#include <cmath>

#include "app/png.hpp"
#include "app/style.hpp"
#include "course/game.hpp"

namespace physics::Offscreen {

namespace {
// The course's Draw system on a pixel buffer: pixel (i, j) has its centre at
// (i + 0.5, j + 0.5) and belongs to the boxes that contain it.
class PixelCanvas final : public Canvas {
 public:
  PixelCanvas(int width, int height)
      : width_(width), height_(height), rgb_(static_cast<std::size_t>(width) * height * 3, 255) {}
  void fill_rect(Vector p, Rect r, Color col) override {
    const auto first = [](double lo) { return static_cast<long>(std::ceil(lo - 0.5)); };
    const long x0 = std::max(0L, first(p.x)), x1 = std::min<long>(width_, first(p.x + r.width));
    const long y0 = std::max(0L, first(p.y)), y1 = std::min<long>(height_, first(p.y + r.height));
    for (long y = y0; y < y1; ++y)
      for (long x = x0; x < x1; ++x) {
        std::uint8_t* px = &rgb_[(static_cast<std::size_t>(y) * width_ + x) * 3];
        px[0] = col.r, px[1] = col.g, px[2] = col.b;
      }
  }
  std::vector<std::uint8_t> take() { return std::move(rgb_); }

 private:
  int width_, height_;
  std::vector<std::uint8_t> rgb_;
};
}  // namespace

std::vector<std::uint8_t> render(const World& w, int width, int height) {
  PixelCanvas canvas(width, height);
  Game::draw(w, canvas);
  return canvas.take();
}

std::vector<std::uint8_t> render(const World& w, int width, int height, Style style, std::span<const BlockRole> roles) {
  PixelCanvas canvas(width, height);
  Styles::draw_world(w, style, roles, canvas);
  return canvas.take();
}

bool screenshot(const World& w, int width, int height, const std::string& path, Style style,
                std::span<const BlockRole> roles) {
  return Png::write_rgb(path, width, height, render(w, width, height, style, roles));
}

}  // namespace physics::Offscreen
