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

// One face's strips (up, down, left or right): for each line (a row for the
// faces up and down, a column for left and right) the runs of exposed faces
// along it, in order. 8 bytes a run, the line implied by where it is stored:
// a map's memory is its cells and little more. The runs of one line never
// overlap, so they are sorted by both ends and a window's are found by a
// binary search.
class StripIndex {
 public:
  struct Run {
    std::uint32_t start, length;  // cells [start, start + length) of the line
  };
  // Made line by line: add a line's runs in order, then end_line().
  void add(Run r) { runs_.push_back(r); }
  void end_line() { start_.push_back(static_cast<std::uint32_t>(runs_.size())); }
  void shrink() { runs_.shrink_to_fit(), start_.shrink_to_fit(); }

  std::uint32_t size() const { return static_cast<std::uint32_t>(runs_.size()); }
  int lines() const { return static_cast<int>(start_.size()) - 1; }
  Run run(std::uint32_t i) const { return runs_[i]; }
  // The index of line l's run with this start and length, or `none`.
  static constexpr std::uint32_t none = ~std::uint32_t{0};
  std::uint32_t find(int l, int start, int length) const;
  // Calls f(index, line) for each run of line l whose cells [start, end) meet [lo, hi].
  template <class F>
  void each(int l, int lo, int hi, F&& f) const;

 private:
  std::vector<std::uint32_t> start_{0};  // runs of line l: runs_[start_[l]] .. runs_[start_[l + 1]]
  std::vector<Run> runs_;
};

class TileLayer {
 public:
  // The layer's body (fixed, its box the grid's extent) and its grid, which
  // check() accepts.
  TileLayer(EntityId body, TileGrid grid);

  EntityId body() const { return body_; }
  const TileGrid& grid() const { return grid_; }

  // A strip is known by its run: the runs of the four faces numbered one
  // after the other (up, down, left, right). A box that is the run of more
  // than one face (the top and the bottom of a platform one cell thick, the
  // four faces of a lone cell) has that many numbers: twins, one box.
  std::uint32_t runs() const { return base_[4]; }
  // The number of distinct boxes (a twin counted once).
  std::size_t strip_count() const;

  // Calls f(run, strip) for the strips whose cells meet the box [x0, x1] x
  // [y0, y1] in px from the layer's corner (touching counts); a strip may
  // come more than once, and as more than one twin.
  template <class F>
  void near(double x0, double y0, double x1, double y1, F&& f) const;

  // By run: its strip's proxy body, or `no_proxy` until it is first needed
  // (kept in pages of 256 runs made on demand, so a map costs nothing here
  // where no body goes); a twin's proxy is its twins'.
  static constexpr EntityId no_proxy = ~EntityId{0};
  EntityId proxy(std::uint32_t run) const;
  void set_proxy(std::uint32_t run, EntityId e);
  // The proxy of a twin of run (strip s), or no_proxy.
  EntityId twins_proxy(std::uint32_t run, const Strip& s) const;

 private:
  void build_strips();
  Strip strip(int face, std::uint32_t i, int line) const;
  template <class F>
  void each_twin(const Strip& s, F&& f) const;
  static constexpr std::uint32_t page_size = 256;
  EntityId body_;
  TileGrid grid_;
  StripIndex faces_[4];   // up, down, left, right
  std::uint32_t base_[5];  // the first run of each face, then the count
  std::vector<std::vector<EntityId>> pages_;
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
  EntityId proxy_of(Components& k, TileLayer& layer, std::uint32_t run, const Strip& s, std::vector<EntityId>& created);
  static void set_from_layer(Components& k, const TileLayer& layer, EntityId e, const Strip& s);
  std::vector<TileLayer> layers_;
  std::vector<EntityId> owner_;
  std::vector<std::uint32_t> listed_;  // by proxy, the last gather that listed it (so a gather lists each once)
  std::size_t proxy_count_ = 0;
  std::uint32_t gathers_ = 0;
};

template <class F>
void StripIndex::each(int l, int lo, int hi, F&& f) const {
  const auto first = runs_.begin() + start_[static_cast<std::size_t>(l)];
  const auto last = runs_.begin() + start_[static_cast<std::size_t>(l) + 1];
  // The first run that ends after lo, then on while they start by hi.
  auto it = std::partition_point(first, last, [&](const Run& r) { return std::int64_t{r.start} + r.length <= lo; });
  for (; it != last && std::int64_t{it->start} <= hi; ++it) f(static_cast<std::uint32_t>(it - runs_.begin()), l);
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
  const auto on = [&](int face) {
    return [&, face](std::uint32_t i, int line) { f(base_[face] + i, strip(face, i, line)); };
  };
  for (int r = r0; r <= r1; ++r) {
    faces_[0].each(r, c0, c1, on(0));
    faces_[1].each(r, c0, c1, on(1));
  }
  for (int c = c0; c <= c1; ++c) {
    faces_[2].each(c, r0, r1, on(2));
    faces_[3].each(c, r0, r1, on(3));
  }
}

}  // namespace physics
