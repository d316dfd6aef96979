#include "systems/draw.hpp"

#include <SDL.h>

#include <cmath>

namespace physics {

void Draw::update(const Components& c, SDL_Renderer* renderer) const {
  for (const EntityId e : entities_) {
    const Vector p = c.position[e];
    const Rect r = c.box[e];
    // Skip what cannot be drawn (NaN, or far outside int range) rather than
    // hand SDL an undefined conversion.
    if (!(std::abs(p.x) < 1e9 && std::abs(p.y) < 1e9)) continue;
    const Color col = c.color[e];
    SDL_SetRenderDrawColor(renderer, col.r, col.g, col.b, col.a);
    const SDL_FRect rect{static_cast<float>(p.x), static_cast<float>(p.y),
                         static_cast<float>(r.width), static_cast<float>(r.height)};
    SDL_RenderFillRectF(renderer, &rect);
  }
}

}  // namespace physics
