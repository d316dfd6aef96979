#include "app/camera.hpp"

#include <algorithm>
#include <cmath>

namespace physics {

namespace {
// One axis of clamp(): centred when the world is narrower than the view
// (on a whole screen pixel, so that a block's edges stay sharp), else kept
// between the world's edges.
double clamp_axis(double eye, double extent, double world, double scale) {
  return extent >= world ? std::round((world - extent) / 2.0 * scale) / scale : std::clamp(eye, 0.0, world - extent);
}
double fit_scale(Vector world, Vector view) { return std::min({1.0, view.x / world.x, view.y / world.y}); }
}  // namespace

Camera Camera::fit(Vector world, Vector view) {
  Camera c{{}, fit_scale(world, view), view, world};
  c.clamp();
  return c;
}

Camera Camera::on(Vector focus, Vector world, Vector view) {
  Camera c{focus - 0.5 * view, 1.0, view, world};
  c.clamp();
  return c;
}

double Camera::min_scale() const { return 0.5 * fit_scale(world, view); }

void Camera::zoom_about(Vector at, double factor) {
  const Vector under = to_world(at);
  scale = std::clamp(scale * factor, min_scale(), max_scale);
  eye = under - (1.0 / scale) * at;
  clamp();
}

void Camera::pan(Vector screen_delta) {
  eye = eye - (1.0 / scale) * screen_delta;
  clamp();
}

void Camera::follow(Vector focus) {
  const Vector s = to_screen(focus), half = 0.5 * view, zone = dead_zone * view;
  const auto push = [](double at, double centre, double z) {
    return at > centre + z ? at - (centre + z) : at < centre - z ? at - (centre - z) : 0.0;
  };
  eye = eye + (1.0 / scale) * Vector{push(s.x, half.x, zone.x), push(s.y, half.y, zone.y)};
  clamp();
}

void Camera::clamp() {
  eye = {clamp_axis(eye.x, view.x / scale, world.x, scale), clamp_axis(eye.y, view.y / scale, world.y, scale)};
}

Vector window_size(Vector world, Vector usable) {
  const auto axis = [](double w, double u, double least) { return std::min(u, std::max(least, std::min(w, u))); };
  return {axis(world.x, usable.x, min_window.x), axis(world.y, usable.y, min_window.y)};
}

}  // namespace physics
