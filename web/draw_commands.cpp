#include "draw_commands.hpp"

namespace physics::web {

void Commands::colour(Color c) {
  for (const int v : {c.r, c.g, c.b, c.a}) ops_.push_back(static_cast<float>(v));
}

void Commands::box(Op op, double x, double y, double w, double h, Color c) {
  for (const double v : {double(op), x, y, w, h}) ops_.push_back(static_cast<float>(v));
  colour(c);
}

void Commands::line(Vector a, Vector b, Color c) {
  for (const double v : {double(Op::line), a.x, a.y, b.x, b.y}) ops_.push_back(static_cast<float>(v));
  colour(c);
}

int Commands::text(const std::string& s, int x, int y, Color c) {
  for (const double v : {double(Op::text), double(x), double(y)}) ops_.push_back(static_cast<float>(v));
  colour(c);
  texts_ += s;
  texts_ += '\n';
  return web::line_height;
}

void render(const World& world, const View& view, Commands& out) {
  out.clear();
  if (world.declares(SystemId::draw)) Overlay::bodies(world, view, out);
  Overlay::over(world, view, out);
}

}  // namespace physics::web
