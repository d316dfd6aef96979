// Crates: a small SDL game on the public API, to copy and grow (docs/api.md).
// Crates fall from the sky; run (← →) and jump (Space or ↑) to climb the pile
// they make. The HUD is the window's title: your best height. Esc quits.
//   crates                 in a window
//   crates --headless N    N frames with a scripted player, no window: prints the result
#include <SDL.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include <physics/physics.hpp>

namespace {

constexpr int width = 800, height = 600;
constexpr double run_speed = 0.25, jump_speed = 0.75;  // px/ms
constexpr int crate_every = 45;                         // frames
constexpr std::size_t max_crates = 80;

struct Input {
  bool left = false, right = false, jump = false;
};

class Game {
 public:
  Game() : world_(physics::create_world(world_def())) {
    add({0, height - 40.0}, {width, 40}, physics::fixed_mass, {60, 60, 60, 255});  // the floor
    add({0, 0}, {20, height - 40.0}, physics::fixed_mass, {60, 60, 60, 255});      // the walls
    add({width - 20.0, 0}, {20, height - 40.0}, physics::fixed_mass, {60, 60, 60, 255});
    player_ = add({380, 500}, {24, 32}, 1.0, {40, 120, 255, 255});
  }
  ~Game() { physics::destroy_world(world_); }
  Game(const Game&) = delete;
  Game& operator=(const Game&) = delete;

  void step(const Input& in) {
    if (++frame_ % crate_every == 0 && crates() < max_crates) drop_crate();
    physics::Vec2 v = physics::velocity(player_);
    v.x = run_speed * ((in.right ? 1 : 0) - (in.left ? 1 : 0));
    if (in.jump && on_ground()) v.y = -jump_speed;
    physics::set_velocity(player_, v);
    physics::step(world_);
    best_ = std::max(best_, height - 40.0 - physics::bounds(player_).upper.y);
  }

  void draw(SDL_Renderer* r) const {
    SDL_SetRenderDrawColor(r, 235, 235, 225, 255);
    SDL_RenderClear(r);
    for (const physics::BodyId b : physics::bodies(world_)) {
      const physics::Aabb box = physics::bounds(b);
      const physics::Color c = physics::color(b);
      const SDL_Rect rect{int(box.lower.x), int(box.lower.y), int(box.size().x), int(box.size().y)};
      SDL_SetRenderDrawColor(r, c.r, c.g, c.b, c.a);
      SDL_RenderFillRect(r, &rect);
      SDL_SetRenderDrawColor(r, c.r / 2, c.g / 2, c.b / 2, c.a);  // an outline, so that crates stand apart
      SDL_RenderDrawRect(r, &rect);
    }
    SDL_RenderPresent(r);
  }

  double best() const { return best_; }
  int frame() const { return frame_; }
  std::size_t crates() const { return physics::body_count(world_) - 4; }

 private:
  static physics::WorldDef world_def() {
    physics::WorldDef d = physics::default_world_def();
    d.gravity = {0.0, 0.002};
    d.solver = physics::SolverKind::stable;  // piles rest instead of sinking
    return d;
  }

  physics::BodyId add(physics::Vec2 at, physics::Vec2 size, double mass, physics::Color color) {
    physics::BodyDef d = physics::default_body_def();
    d.position = at;
    d.size = size;
    d.mass = mass;
    d.color = color;
    d.restitution = 0.0;
    d.friction = 0.6;
    return physics::create_body(world_, d);
  }

  void drop_crate() {
    const double side = 30 + std::rand() % 30;
    const double x = 30 + std::rand() % int(width - 60 - side);
    add({x, -side}, {side, side}, 1.0 + side / 30, {190, 130, 60, 255});
  }

  // Something right under the player's feet: a thin box below it.
  bool on_ground() const {
    const physics::Aabb feet = physics::bounds(player_);
    const auto under = physics::query_box(world_, {{feet.lower.x + 1, feet.upper.y}, {feet.upper.x - 1, feet.upper.y + 2}});
    return std::any_of(under.begin(), under.end(), [&](physics::BodyId b) { return !(b == player_); });
  }

  physics::WorldId world_;
  physics::BodyId player_;
  int frame_ = 0;
  double best_ = 0.0;
};

// The scripted player of --headless: runs one way then the other, jumping.
Input scripted(int frame) { return {(frame / 120) % 2 == 1, (frame / 120) % 2 == 0, frame % 40 == 0}; }

int headless(int frames) {
  std::srand(1);
  Game game;
  for (int i = 0; i < frames; ++i) game.step(scripted(i));
  std::printf("crates: %d frames, %zu crates fell, best height %.0f px\n", game.frame(), game.crates(), game.best());
  return 0;
}

int windowed() {
  if (SDL_Init(SDL_INIT_VIDEO) != 0) {
    std::fprintf(stderr, "crates: no window (%s); try --headless 600\n", SDL_GetError());
    return 1;
  }
  const std::unique_ptr<SDL_Window, void (*)(SDL_Window*)> window(
      SDL_CreateWindow("crates", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width, height, 0), SDL_DestroyWindow);
  const std::unique_ptr<SDL_Renderer, void (*)(SDL_Renderer*)> renderer(
      window ? SDL_CreateRenderer(window.get(), -1, SDL_RENDERER_PRESENTVSYNC) : nullptr, SDL_DestroyRenderer);
  if (!renderer) {
    std::fprintf(stderr, "crates: %s\n", SDL_GetError());
    SDL_Quit();
    return 1;
  }
  std::srand(static_cast<unsigned>(SDL_GetTicks()));
  Game game;
  for (bool quit = false; !quit;) {
    for (SDL_Event e; SDL_PollEvent(&e);)
      quit = quit || e.type == SDL_QUIT || (e.type == SDL_KEYDOWN && e.key.keysym.sym == SDLK_ESCAPE);
    const Uint8* keys = SDL_GetKeyboardState(nullptr);
    game.step({keys[SDL_SCANCODE_LEFT] != 0, keys[SDL_SCANCODE_RIGHT] != 0,
               keys[SDL_SCANCODE_SPACE] != 0 || keys[SDL_SCANCODE_UP] != 0});
    game.draw(renderer.get());
    const std::string title = "crates: best height " + std::to_string(int(game.best())) + " px";
    SDL_SetWindowTitle(window.get(), title.c_str());
    SDL_Delay(16);  // about 60 frames a second, the engine's dt
  }
  SDL_Quit();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc >= 2 && std::string(argv[1]) == "--headless") {
    const int frames = argc >= 3 ? std::atoi(argv[2]) : 600;
    if (frames <= 0) {
      std::fprintf(stderr, "crates: --headless takes a number of frames > 0\n");
      return 2;
    }
    return headless(frames);
  }
  if (argc >= 2) {
    std::fprintf(stderr, "usage: crates [--headless FRAMES]\n");
    return 2;
  }
  return windowed();
}
