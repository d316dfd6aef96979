#include "engine/tiles.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/limits.hpp"

namespace physics {

std::string check(const TileGrid& g) {
  if (g.cell < 1 || g.cell > max_block_size)
    return "the cell size must be whole pixels in [1, 1048576] (got " + std::to_string(g.cell) + ")";
  if (g.columns < 1 || g.rows < 1)
    return "a tile layer needs at least one column and one row (got " + std::to_string(g.columns) + " x " +
           std::to_string(g.rows) + ")";
  if (std::int64_t{g.cell} * g.columns > max_world_size || std::int64_t{g.cell} * g.rows > max_world_size)
    return "a tile layer's extent must be at most 1048576 px a side (got " + std::to_string(g.columns) + " x " +
           std::to_string(g.rows) + " cells of " + std::to_string(g.cell) + " px)";
  if (g.cells.size() != static_cast<std::size_t>(g.columns) * static_cast<std::size_t>(g.rows))
    return "a tile layer of " + std::to_string(g.columns) + " x " + std::to_string(g.rows) + " cells needs " +
           std::to_string(std::int64_t{g.columns} * g.rows) + " cells (got " + std::to_string(g.cells.size()) + ")";
  for (std::size_t i = 0; i < g.cells.size(); ++i)
    if (g.cells[i] >= tile_kinds)
      return "unknown tile kind " + std::to_string(g.cells[i]) + " at column " +
             std::to_string(i % static_cast<std::size_t>(g.columns)) + ", row " +
             std::to_string(i / static_cast<std::size_t>(g.columns)) + " (0 empty, 1 solid, 2 one-way up)";
  return "";
}

std::uint32_t StripIndex::find(int l, int start, int length) const {
  const auto first = runs_.begin() + start_[static_cast<std::size_t>(l)];
  const auto last = runs_.begin() + start_[static_cast<std::size_t>(l) + 1];
  const auto it = std::partition_point(first, last, [&](const Run& r) { return std::int64_t{r.start} < start; });
  if (it == last || std::int64_t{it->start} != start || std::int64_t{it->length} != length) return none;
  return static_cast<std::uint32_t>(it - runs_.begin());
}

TileLayer::TileLayer(EntityId body, TileGrid grid) : body_(body), grid_(std::move(grid)) {
  build_strips();
  base_[0] = 0;
  for (int f = 0; f < 4; ++f) base_[f + 1] = base_[f] + faces_[f].size();
  pages_.resize((base_[4] + page_size - 1) / page_size);
}

namespace {

// The kind of strip the face of cell (c, r) towards (dc, dr) belongs to:
// 0 none (not exposed), 1 solid, 2 one-way. A solid cell's face is exposed
// where its neighbour is not solid; a one-way cell has its top face only,
// exposed where the cell above is empty.
int face_kind(const TileGrid& g, int c, int r, int dc, int dr) {
  const Tile t = g.at(c, r), n = g.at(c + dc, r + dr);
  if (t == Tile::solid) return n != Tile::solid ? 1 : 0;
  if (t == Tile::one_way_up && dr == -1) return n == Tile::empty ? 2 : 0;
  return 0;
}

// The faces in the order runs are numbered: up, down (along rows), left,
// right (along columns), as the step to the neighbour a face looks at.
constexpr int face_dc[4] = {0, 0, -1, 1}, face_dr[4] = {-1, 1, 0, 0};

}  // namespace

// For each face, the runs of each row (up, down) or column (left, right).
void TileLayer::build_strips() {
  const TileGrid& g = grid_;
  for (int f = 0; f < 4; ++f) {
    const bool rows = f < 2;
    const int lines = rows ? g.rows : g.columns, length = rows ? g.columns : g.rows;
    const auto kind = [&](int l, int i) { return rows ? face_kind(g, i, l, face_dc[f], face_dr[f]) : face_kind(g, l, i, face_dc[f], face_dr[f]); };
    for (int l = 0; l < lines; ++l) {
      for (int i = 0; i < length;) {
        const int k = kind(l, i);
        int j = i + 1;
        while (j < length && kind(l, j) == k) ++j;
        if (k != 0) faces_[f].add({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j - i)});
        i = j;
      }
      faces_[f].end_line();
    }
    faces_[f].shrink();  // grown by push_back: up to twice its size
  }
}

// Run i of face f, on line `line`. Only an up face's run can be of one-way
// cells (one-way cells have no other face), and its cells are all of a kind.
Strip TileLayer::strip(int face, std::uint32_t i, int line) const {
  const StripIndex::Run r = faces_[face].run(i);
  const int a = static_cast<int>(r.start), n = static_cast<int>(r.length);
  if (face < 2) return Strip{a, line, n, 1, face == 0 && grid_.at(a, line) == Tile::one_way_up};
  return Strip{line, a, 1, n, false};
}

// Calls f(run) for every run whose strip is box s, s's own included: a row
// strip can be the up and the down face's run, a cell alone all four.
template <class F>
void TileLayer::each_twin(const Strip& s, F&& f) const {
  const auto look = [&](int face, int line, int start, int length) {
    const std::uint32_t i = faces_[face].find(line, start, length);
    if (i != StripIndex::none) f(base_[face] + i);
  };
  if (s.rows == 1) look(0, s.row, s.col, s.cols), look(1, s.row, s.col, s.cols);
  if (s.cols == 1) look(2, s.col, s.row, s.rows), look(3, s.col, s.row, s.rows);
}

std::size_t TileLayer::strip_count() const {
  std::size_t n = 0;
  for (int f = 0; f < 4; ++f)
    for (int l = 0; l < faces_[f].lines(); ++l)
      faces_[f].each(l, 0, std::numeric_limits<int>::max(), [&](std::uint32_t i, int line) {
        const std::uint32_t run = base_[f] + i;
        bool first = true;  // no twin numbered before it
        each_twin(strip(f, i, line), [&](std::uint32_t t) { first = first && t >= run; });
        n += first;
      });
  return n;
}

EntityId TileLayer::proxy(std::uint32_t run) const {
  const auto& page = pages_[run / page_size];
  return page.empty() ? no_proxy : page[run % page_size];
}

void TileLayer::set_proxy(std::uint32_t run, EntityId e) {
  auto& page = pages_[run / page_size];
  if (page.empty()) page.assign(page_size, no_proxy);
  page[run % page_size] = e;
}

EntityId TileLayer::twins_proxy(std::uint32_t run, const Strip& s) const {
  EntityId e = no_proxy;
  each_twin(s, [&](std::uint32_t t) {
    if (t != run && e == no_proxy) e = proxy(t);
  });
  return e;
}

void TileSet::gather(Components& k, std::span<const EntityId> bodies, double h, double reach,
                     std::vector<EntityId>& out, std::vector<EntityId>& created) {
  out.clear();
  ++gathers_;
  for (TileLayer& layer : layers_) {
    const Vector o = k.position[layer.body()];
    for (const EntityId e : bodies) {
      if (!std::isfinite(k.mass[e])) continue;  // two fixed bodies never collide
      const Vector p = k.position[e], q = p + h * k.velocity[e];
      const double w = k.box[e].width, hh = k.box[e].height;
      layer.near(std::min(p.x, q.x) - reach - o.x, std::min(p.y, q.y) - reach - o.y,
                 std::max(p.x, q.x) + w + reach - o.x, std::max(p.y, q.y) + hh + reach - o.y,
                 [&](std::uint32_t run, const Strip& s) {
                   const EntityId x = proxy_of(k, layer, run, s, created);
                   if (listed_[x] == gathers_) return;
                   listed_[x] = gathers_;
                   set_from_layer(k, layer, x, s);
                   out.push_back(x);
                 });
    }
  }
  std::sort(out.begin(), out.end());
}

// The proxy of strip s (run `run` of the layer): its twins' when one has
// been made, else made now.
EntityId TileSet::proxy_of(Components& k, TileLayer& layer, std::uint32_t run, const Strip& s,
                           std::vector<EntityId>& created) {
  EntityId e = layer.proxy(run);
  if (e != TileLayer::no_proxy) return e;
  e = layer.twins_proxy(run, s);
  if (e == TileLayer::no_proxy) {
    e = k.create();
    k.mass[e] = infinity;
    // The ids made since the last proxy (bodies) stand for themselves.
    const std::size_t known = owner_.size();
    owner_.resize(k.size());
    for (std::size_t i = known; i < owner_.size(); ++i) owner_[i] = static_cast<EntityId>(i);
    owner_[e] = layer.body();
    listed_.resize(k.size(), 0);
    created.push_back(e);
    ++proxy_count_;
  }
  layer.set_proxy(run, e);
  return e;
}

// Proxy e of strip s set from the layer's body as it is now (a game may move
// the layer or change its friction).
void TileSet::set_from_layer(Components& k, const TileLayer& layer, EntityId e, const Strip& s) {
  const EntityId b = layer.body();
  const int cs = layer.grid().cell;
  k.position[e] = k.position[b] + Vector{static_cast<double>(s.col) * cs, static_cast<double>(s.row) * cs};
  k.box[e] = Rect{s.cols * cs, s.rows * cs};
  k.restitution[e] = k.restitution[b];
  k.friction[e] = k.friction[b];
  k.color[e] = k.color[b];
  ContactRules r = k.rules(b);
  r.one_way = s.one_way ? Face::up : Face::none;
  if (!(k.rules(e) == r)) k.set_rules(e, r);
}

}  // namespace physics
