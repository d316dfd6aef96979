#include "engine/tiles.hpp"

#include <algorithm>
#include <cmath>

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

void StripIndex::build(int lines, std::vector<std::vector<std::uint32_t>> by_line) {
  start_.assign(static_cast<std::size_t>(lines) + 1, 0);
  runs_.clear();
  for (int l = 0; l < lines; ++l) {
    const auto& runs = by_line[static_cast<std::size_t>(l)];
    runs_.insert(runs_.end(), runs.begin(), runs.end());
    start_[static_cast<std::size_t>(l) + 1] = static_cast<std::uint32_t>(runs_.size());
  }
  runs_.shrink_to_fit();  // grown by inserts: up to twice its size (a map's memory is its cells and strips)
}

TileLayer::TileLayer(EntityId body, TileGrid grid) : body_(body), grid_(std::move(grid)) {
  build_strips();
  proxy.assign(strips_.size(), no_proxy);
  listed.assign(strips_.size(), 0);
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

}  // namespace

// For each face, the runs of each row (up, down) or column (left, right).
// A strip that is the same box as one already made (the top and the bottom
// of a platform one cell thick, the four faces of a lone cell) is that one.
void TileLayer::build_strips() {
  const TileGrid& g = grid_;
  const auto runs = [&](bool rows, int dc, int dr) {
    const int lines = rows ? g.rows : g.columns, length = rows ? g.columns : g.rows;
    std::vector<std::vector<std::uint32_t>> by_line(static_cast<std::size_t>(lines));
    for (int l = 0; l < lines; ++l) {
      for (int i = 0; i < length;) {
        const int kind = rows ? face_kind(g, i, l, dc, dr) : face_kind(g, l, i, dc, dr);
        int j = i + 1;
        while (j < length && (rows ? face_kind(g, j, l, dc, dr) : face_kind(g, l, j, dc, dr)) == kind) ++j;
        if (kind != 0) {
          const Strip s = rows ? Strip{i, l, j - i, 1, kind == 2} : Strip{l, i, 1, j - i, kind == 2};
          by_line[static_cast<std::size_t>(l)].push_back(strip_id(s));
        }
        i = j;
      }
    }
    return by_line;
  };
  up_.build(g.rows, runs(true, 0, -1));
  down_.build(g.rows, runs(true, 0, 1));
  left_.build(g.columns, runs(false, -1, 0));
  right_.build(g.columns, runs(false, 1, 0));
  same_ = {};  // (clear() would keep its memory)
  strips_.shrink_to_fit();  // grown by push_back: up to twice its size
}

// The index of strip s, made unless the same box was made already (same_,
// while the strips are built): keyed by its first cell, whether it runs down
// a column, its kind and its length (a lone cell runs along a row both ways).
std::uint32_t TileLayer::strip_id(const Strip& s) {
  const bool down = s.rows > 1;
  const auto length = static_cast<std::uint64_t>(std::max(s.cols, s.rows) - 1);  // < 2^20
  const std::uint64_t key = static_cast<std::uint64_t>(s.row) << 43 | static_cast<std::uint64_t>(s.col) << 22 |
                            static_cast<std::uint64_t>(down) << 21 | static_cast<std::uint64_t>(s.one_way) << 20 | length;
  const auto [it, made] = same_.try_emplace(key, static_cast<std::uint32_t>(strips_.size()));
  if (made) strips_.push_back(s);
  return it->second;
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
                 std::max(p.x, q.x) + w + reach - o.x, std::max(p.y, q.y) + hh + reach - o.y, [&](std::uint32_t s) {
                   if (layer.listed[s] == gathers_) return;
                   layer.listed[s] = gathers_;
                   out.push_back(proxy_of(k, layer, s, created));
                 });
    }
  }
  std::sort(out.begin(), out.end());
}

// Strip s's proxy, made if it is the first time, and set from the layer's
// body as it is now (a game may move the layer or change its friction).
EntityId TileSet::proxy_of(Components& k, TileLayer& layer, std::uint32_t s, std::vector<EntityId>& created) {
  EntityId& e = layer.proxy[s];
  if (e == TileLayer::no_proxy) {
    e = k.create();
    k.mass[e] = infinity;
    // The ids made since the last proxy (bodies) stand for themselves.
    const std::size_t known = owner_.size();
    owner_.resize(k.size());
    for (std::size_t i = known; i < owner_.size(); ++i) owner_[i] = static_cast<EntityId>(i);
    owner_[e] = layer.body();
    created.push_back(e);
    ++proxy_count_;
  }
  const EntityId b = layer.body();
  const Strip& st = layer.strips()[s];
  const int cs = layer.grid().cell;
  k.position[e] = k.position[b] + Vector{static_cast<double>(st.col) * cs, static_cast<double>(st.row) * cs};
  k.box[e] = Rect{st.cols * cs, st.rows * cs};
  k.restitution[e] = k.restitution[b];
  k.friction[e] = k.friction[b];
  k.color[e] = k.color[b];
  ContactRules r = k.rules(b);
  r.one_way = st.one_way ? Face::up : Face::none;
  if (!(k.rules(e) == r)) k.set_rules(e, r);
  return e;
}

}  // namespace physics
