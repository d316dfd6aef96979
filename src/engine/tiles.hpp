// Tile layers (docs/game-physics.md, "Tile layers"): a fixed body holding a
// grid of cells, one byte a cell, whose collision geometry is its *strips*:
// each run of cells of a row (or a column) with the same exposed face, as one
// box one cell thick. A face between two solid cells is never a strip's face
// (but at a strip's end, where a perpendicular strip lies on it), so a box
// sliding along a floor or a wall of tiles meets no seam.
//
// The solvers know nothing of tiles: each substep, the strips near the moving
// bodies are given to them as fixed bodies (proxies, made the first time a
// strip is needed) listed before the Collision stage's bodies (World::
// before_move), and every stage solves them as it solves a wall.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "engine/components.hpp"

namespace physics {

// A cell's kind. The values 3 to 255 are reserved for more kinds.
enum class Tile : std::uint8_t { empty = 0, solid = 1, one_way_up = 2 };
inline constexpr int tile_kinds = 3;

struct TileGrid {
  int cell = 16;              // px, a side of a cell
  int columns = 0, rows = 0;  // cells
  std::vector<std::uint8_t> cells;  // row by row, top row first: a Tile each

  // Outside the grid every cell is empty.
  Tile at(int c, int r) const {
    if (c < 0 || r < 0 || c >= columns || r >= rows) return Tile::empty;
    return static_cast<Tile>(cells[static_cast<std::size_t>(r) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(c)]);
  }
};

// A cell of a layer, as queries name it.
struct TileCell {
  int column, row;
  Tile kind;
};

// What is wrong with the grid, in one line, or "" when it is fine: the cell
// size and counts, the extent (at most max_world_size px a side), the
// number of cells, unknown kinds.
std::string check(const TileGrid& g);

// A strip: cells [col, col + cols) x [row, row + rows), one of cols and rows 1.
struct Strip {
  int col, row, cols, rows;
  bool one_way;  // the top faces of one-way cells: stops bodies only from above
};

// The strips' index, by face: for each row (faces up and down) or column
// (faces left and right), the runs of that face in order, as strip indices.
// The runs of one face in one row never overlap, so they are sorted by both
// ends and a window's are found by a binary search.
class StripIndex {
 public:
  void build(int lines, std::vector<std::vector<std::uint32_t>> by_line);
  // Calls f(strip) for each run of line l whose cells [start, end) meet [lo, hi].
  template <class F>
  void each(std::span<const Strip> strips, bool rows, int l, int lo, int hi, F&& f) const;

 private:
  std::vector<std::uint32_t> start_;  // runs of line l: runs_[start_[l]] .. runs_[start_[l + 1]]
  std::vector<std::uint32_t> runs_;
};

class TileLayer {
 public:
  // The layer's body (fixed, its box the grid's extent) and its grid, which
  // check() accepts.
  TileLayer(EntityId body, TileGrid grid);

  EntityId body() const { return body_; }
  const TileGrid& grid() const { return grid_; }
  std::span<const Strip> strips() const { return strips_; }

  // Calls f(strip index) for the strips whose cells meet the box [x0, x1] x
  // [y0, y1] in px from the layer's corner (touching counts); a strip may
  // come more than once.
  template <class F>
  void near(double x0, double y0, double x1, double y1, F&& f) const;

  // By strip: its proxy body, or `no_proxy` until it is first needed; and
  // the last gather that listed it (so a gather lists each once).
  static constexpr EntityId no_proxy = ~EntityId{0};
  std::vector<EntityId> proxy;
  std::vector<std::uint32_t> listed;

 private:
  void build_strips();
  std::uint32_t strip_id(const Strip& s);
  EntityId body_;
  TileGrid grid_;
  std::vector<Strip> strips_;
  StripIndex up_, down_, left_, right_;
  std::unordered_map<std::uint64_t, std::uint32_t> same_;  // while building
};

// A world's tile layers and their proxies.
class TileSet {
 public:
  bool empty() const { return layers_.empty(); }
  std::span<const TileLayer> layers() const { return layers_; }
  void add(TileLayer layer) { layers_.push_back(std::move(layer)); }
  // The layer of body e no longer collides (World::destroy); its proxies stay unlisted rows.
  void remove(EntityId e) {
    std::erase_if(layers_, [&](const TileLayer& l) { return l.body() == e; });
  }
  std::size_t proxy_count() const { return proxy_count_; }
  // By entity id, the id contact events name: a proxy's layer body, any
  // other id itself; ids past its end (bodies made since the last proxy)
  // stand for themselves too. Empty while there is no proxy.
  std::span<const EntityId> owners() const { return owner_; }
  // Whether e is a layer's body or a proxy: its box is not what collides.
  bool part_of_tiles(EntityId e) const {
    if (e < owner_.size() && owner_[e] != e) return true;
    return std::any_of(layers_.begin(), layers_.end(), [&](const TileLayer& l) { return l.body() == e; });
  }

  // The proxies of the strips near the finite bodies of `bodies` (each box
  // swept over h ms at its velocity, grown by `reach` px), in increasing id
  // order, into `out`; strips needed for the first time get their proxy
  // made in k and appended to `created`. Every proxy listed takes its
  // layer body's restitution, friction, colour and filter again.
  void gather(Components& k, std::span<const EntityId> bodies, double h, double reach, std::vector<EntityId>& out,
              std::vector<EntityId>& created);

 private:
  EntityId proxy_of(Components& k, TileLayer& layer, std::uint32_t s, std::vector<EntityId>& created);
  std::vector<TileLayer> layers_;
  std::vector<EntityId> owner_;
  std::size_t proxy_count_ = 0;
  std::uint32_t gathers_ = 0;
};

template <class F>
void StripIndex::each(std::span<const Strip> strips, bool rows, int l, int lo, int hi, F&& f) const {
  const auto first = runs_.begin() + start_[static_cast<std::size_t>(l)];
  const auto last = runs_.begin() + start_[static_cast<std::size_t>(l) + 1];
  const auto end_of = [&](std::uint32_t s) { return rows ? strips[s].col + strips[s].cols : strips[s].row + strips[s].rows; };
  const auto start_of = [&](std::uint32_t s) { return rows ? strips[s].col : strips[s].row; };
  // The first run that ends after lo, then on while they start by hi.
  auto it = std::partition_point(first, last, [&](std::uint32_t s) { return end_of(s) <= lo; });
  for (; it != last && start_of(*it) <= hi; ++it) f(*it);
}

template <class F>
void TileLayer::near(double x0, double y0, double x1, double y1, F&& f) const {
  const double cs = grid_.cell;
  if (!(x1 >= 0.0 && y1 >= 0.0 && x0 <= cs * grid_.columns && y0 <= cs * grid_.rows)) return;
  // Cells meeting the closed box: from the cell holding lo (one before it
  // too, which touches it when lo lies on its edge) to the cell holding hi.
  const auto clamp_cell = [](double v, int n) { return v < 0.0 ? 0 : v >= n - 1 ? n - 1 : static_cast<int>(v); };
  const int c0 = clamp_cell(std::floor(x0 / cs) - 1, grid_.columns), c1 = clamp_cell(std::floor(x1 / cs), grid_.columns);
  const int r0 = clamp_cell(std::floor(y0 / cs) - 1, grid_.rows), r1 = clamp_cell(std::floor(y1 / cs), grid_.rows);
  for (int r = r0; r <= r1; ++r) {
    up_.each(strips_, true, r, c0, c1, f);
    down_.each(strips_, true, r, c0, c1, f);
  }
  for (int c = c0; c <= c1; ++c) {
    left_.each(strips_, false, c, r0, r1, f);
    right_.each(strips_, false, c, r0, r1, f);
  }
}

}  // namespace physics
