#include <algorithm>
#include <cmath>
#include <malloc.h>
#include <map>
#include <stdexcept>

#include "bench.hpp"

namespace bench {

namespace {

// splitmix64: a fixed generator, so every engine and every run sees the same
// scene whatever the standard library.
struct Random {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double uniform(double lo, double hi) { return lo + (hi - lo) * static_cast<double>(next() >> 11) * 0x1p-53; }
};

// Four walls 1 m thick around [0, w] x [0, h], overlapping at the corners.
void add_walls(Scene& s) {
  const double w = s.width, h = s.height;
  s.bodies.push_back({w / 2, -0.5, w / 2 + 1, 0.5, 0, 0, true});     // floor
  s.bodies.push_back({w / 2, h + 0.5, w / 2 + 1, 0.5, 0, 0, true});  // ceiling
  s.bodies.push_back({-0.5, h / 2, 0.5, h / 2 + 1, 0, 0, true});     // left
  s.bodies.push_back({w + 0.5, h / 2, 0.5, h / 2 + 1, 0, 0, true});  // right
}

}  // namespace

std::size_t Scene::dynamic_count() const {
  return static_cast<std::size_t>(std::count_if(bodies.begin(), bodies.end(), [](const Body& b) { return !b.fixed; }));
}

Scene make_gas(std::size_t n, std::uint64_t seed) {
  Scene s;
  s.name = "gas";
  // Area fraction 0.10: n m² of blocks in 10 n m² of box (rounded up to whole
  // metres, so that our engine's integer pixel sizes are exact).
  const double side = std::ceil(std::sqrt(10.0 * static_cast<double>(n)));
  s.width = s.height = side;
  s.gravity = 0;
  s.restitution = 1.0;
  add_walls(s);
  // One body per cell of a k x k grid, jittered inside its cell: cells are
  // >= sqrt(10) m wide, so jittered neighbours never overlap.
  const auto k = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
  const double cell = side / static_cast<double>(k);
  const double jitter = (cell - 1.0) / 2.0 - 0.05;
  Random rng{seed};
  for (std::size_t i = 0; i < n; ++i) {
    const double cx = (static_cast<double>(i % k) + 0.5) * cell + rng.uniform(-jitter, jitter);
    const double cy = (static_cast<double>(i / k) + 0.5) * cell + rng.uniform(-jitter, jitter);
    const double vx = rng.uniform(-5.0, 5.0), vy = rng.uniform(-5.0, 5.0);
    s.bodies.push_back({cx, cy, 0.5, 0.5, vx, vy, false});
  }
  return s;
}

Scene make_rain(std::size_t n) {
  Scene s;
  s.name = "rain";
  // k columns 2 m apart fill a 2k x 2k container from the top: n / (2k)² = 0.25.
  const auto k = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
  s.width = s.height = 2.0 * static_cast<double>(k);
  s.gravity = 10.0;
  s.restitution = 0.5;
  s.resting = true;
  add_walls(s);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t row = i / k, col = i % k;
    // Odd rows shifted by half a block: the pile is a brick wall, not columns.
    const double shift = row % 2 ? 0.25 : -0.25;
    const double cx = 1.0 + 2.0 * static_cast<double>(col) + shift;
    const double cy = s.height - 1.0 - 2.0 * static_cast<double>(row);
    s.bodies.push_back({cx, cy, 0.5, 0.5, 0, 0, false});
  }
  return s;
}

Scene make_rain_settled(std::size_t n) {
  Scene s = make_rain(n);
  s.name = "rain_settled";
  std::erase_if(s.bodies, [](const Body& b) { return !b.fixed; });  // the walls stay
  const auto per_row = static_cast<std::size_t>(std::lround(s.width));  // unit squares wall to wall
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t row = i / per_row, col = i % per_row;
    const std::size_t in_row = std::min(per_row, n - row * per_row);
    const double x0 = 0.5 * static_cast<double>(per_row - in_row);  // a short last row, centred
    s.bodies.push_back({x0 + 0.5 + static_cast<double>(col), 0.5 + static_cast<double>(row), 0.5, 0.5, 0, 0, false});
  }
  return s;
}

Scene make_pyramid(std::size_t base) {
  Scene s;
  s.name = "pyramid";
  s.width = static_cast<double>(base) + 20.0;
  s.height = static_cast<double>(base) + 10.0;
  s.gravity = 10.0;
  s.restitution = 0.0;
  s.resting = true;
  add_walls(s);
  // Box2D's large_pyramid: row i holds base - i squares, each resting on two
  // of the row below, starting exactly in contact.
  const double x0 = s.width / 2 - 0.5 * static_cast<double>(base);
  for (std::size_t i = 0; i < base; ++i)
    for (std::size_t j = i; j < base; ++j) {
      const double cx = x0 + 0.5 * static_cast<double>(i + 1) + static_cast<double>(j - i);
      const double cy = 0.5 + static_cast<double>(i);
      s.bodies.push_back({cx, cy, 0.5, 0.5, 0, 0, false});
    }
  s.tops.push_back(s.bodies.size() - 1);
  return s;
}

Scene make_pyramid_friction(std::size_t base) {
  Scene s = make_pyramid(base);
  s.name = "pyramid_friction";
  s.friction = 0.6;
  return s;
}

namespace {

// One of many_pyramids' pyramids, as Box2D's CreateSmallPyramid places it:
// row i of `base - i` unit squares, its first centred at left + i/2, on a
// shelf whose top is at y = floor.
void add_small_pyramid(Scene& s, std::size_t base, double left, double floor) {
  for (std::size_t i = 0; i < base; ++i)
    for (std::size_t j = i; j < base; ++j) {
      const double cx = left + 0.5 * static_cast<double>(i) + static_cast<double>(j - i);
      s.bodies.push_back({cx, floor + 0.5 + static_cast<double>(i), 0.5, 0.5, 0, 0, false});
    }
  s.tops.push_back(s.bodies.size() - 1);
}

}  // namespace

Scene make_many_pyramids(std::size_t rows, std::size_t columns, std::size_t base) {
  Scene s;
  s.name = "many_pyramids";
  // Box2D's geometry, shifted right by `margin` so it lies inside the walls:
  // shelves 11 m apart (a pyramid's 10 m plus 1), each 220 m wide
  // (columns x 11 m), pyramids 11 m apart, the first 1 m in from the shelf's end.
  const double pitch = static_cast<double>(base + 1), margin = 10.0;
  const double shelf_width = static_cast<double>(columns) * pitch;
  s.width = shelf_width + 2 * margin;
  s.height = static_cast<double>(rows) * pitch + margin;
  s.gravity = 10.0;
  s.restitution = 0.0;
  s.resting = true;
  add_walls(s);
  // Box2D's shelves are segments (no thickness); here they are fixed boxes
  // 0.5 m thick under each shelf line, clear of the pyramid below (whose top
  // is 1 m under it). The floor is the first shelf.
  for (std::size_t r = 1; r < rows; ++r)
    s.bodies.push_back({margin + shelf_width / 2, static_cast<double>(r) * pitch - 0.25, shelf_width / 2, 0.25, 0, 0, true});
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t c = 0; c < columns; ++c)
      add_small_pyramid(s, base, margin + 1.0 + static_cast<double>(c) * pitch, static_cast<double>(r) * pitch);
  return s;
}

Scene make_tiles(int side) {
  constexpr int room = 20, rooms_used = 10;  // 10 x 10 rooms of 100 bodies
  if (side < room * rooms_used || side % room != 0)
    throw std::invalid_argument("tiles_" + std::to_string(side) + ": the map's side must be a multiple of 20, at least 200");
  Scene s;
  s.name = "tiles_" + std::to_string(side);
  s.width = s.height = side;
  s.gravity = 10.0;
  s.restitution = 0.5;
  s.resting = true;
  TileMap& m = s.map;
  m.columns = m.rows = side;
  m.cells.assign(static_cast<std::size_t>(side) * static_cast<std::size_t>(side), 0);
  // Walls two cells thick between rooms (one at the map's border), so that
  // every room is the same 18 x 18 cells inside; a ledge of 8 cells in each.
  for (int r = 0; r < side; ++r)
    for (int c = 0; c < side; ++c) {
      const int rr = r % room, cc = c % room;
      const bool wall = rr == 0 || rr == room - 1 || cc == 0 || cc == room - 1;
      const bool ledge = rr == 12 && cc >= 6 && cc < 14;
      m.cells[static_cast<std::size_t>(r) * static_cast<std::size_t>(side) + static_cast<std::size_t>(c)] = wall || ledge;
    }
  // 10 rows of 10 squares in the top of each room, above its ledge (the
  // lowest square's bottom 0.5 m over it), odd rows shifted by 0.3 m.
  for (int R = 0; R < rooms_used; ++R)
    for (int C = 0; C < rooms_used; ++C) {
      const double left = room * C + 1.0, top = s.height - (room * R + 1.0);
      for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j)
          s.bodies.push_back({left + 0.5 + 1.7 * j + (i % 2 ? 0.3 : 0.0), top - 0.55 - 1.05 * i, 0.5, 0.5, 0, 0, false});
    }
  return s;
}

std::vector<Body> map_boxes(const Scene& s) {
  const TileMap& m = s.map;
  std::vector<Body> out;
  // Rows [r0, r1) of the run [c0, c1), as a fixed box in the scene's units.
  const auto box = [&](int c0, int c1, int r0, int r1) {
    const double hx = (c1 - c0) * m.cell / 2, hy = (r1 - r0) * m.cell / 2;
    out.push_back({c0 * m.cell + hx, s.height - r0 * m.cell - hy, hx, hy, 0, 0, true});
  };
  std::map<std::pair<int, int>, int> open;  // the runs of the row above, by [c0, c1): their first row
  for (int r = 0; r <= m.rows; ++r) {
    std::map<std::pair<int, int>, int> next;
    for (int c = 0; r < m.rows && c < m.columns;) {
      if (!m.solid(c, r)) {
        ++c;
        continue;
      }
      int e = c;
      while (e < m.columns && m.solid(e, r)) ++e;
      const auto it = open.find({c, e});
      next[{c, e}] = it == open.end() ? r : it->second;
      if (it != open.end()) open.erase(it);
      c = e;
    }
    for (const auto& [run, r0] : open) box(run.first, run.second, r0, r);
    open = std::move(next);
  }
  return out;
}

std::size_t heap_bytes() {
  const struct mallinfo2 mi = mallinfo2();
  return mi.uordblks + mi.hblkhd;  // small blocks in use, and the blocks mapped on their own
}

}  // namespace bench
