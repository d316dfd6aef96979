#include "api/registry.hpp"

#include <limits>

namespace physics::api {

namespace {
struct Slot {
  std::unique_ptr<Live> live;   // null while the slot is free
  std::uint16_t generation = 0;  // bumped when the slot is freed
};

std::vector<Slot>& slots() {
  static std::vector<Slot> s;
  return s;
}

Slot* find(WorldId id) {
  auto& s = slots();
  if (id.index1 == 0 || id.index1 > s.size()) return nullptr;
  Slot& slot = s[id.index1 - 1];
  return slot.live && slot.generation == id.generation ? &slot : nullptr;
}
}  // namespace

std::string describe(WorldId id) {
  return "world id (index " + std::to_string(id.index1) + ", generation " + std::to_string(id.generation) + ")";
}

std::string describe(BodyId id) {
  return "body id (index " + std::to_string(id.index1) + ", generation " + std::to_string(id.generation) + ") of " +
         describe(id.world);
}

void Live::sync() {
  const std::size_t n = world->components.size();
  if (table.generation.size() < n) {
    table.generation.resize(n, 1);
    table.user_data.resize(n, 0);
  }
  if (issued.size() < n) issued.resize(n, 1);
}

std::uint16_t Live::issue(EntityId e) {
  if (issued.size() <= e) issued.resize(e + 1, 0);
  // 65 535 generations a slot; then it wraps, skipping 0 (never a valid id's).
  if (++issued[e] == 0) issued[e] = 1;
  return issued[e];
}

bool live(WorldId id) { return find(id) != nullptr; }

Live& world(WorldId id) {
  if (id.index1 == 0) throw Error("null world id");
  Slot* s = find(id);
  if (!s) throw Error(describe(id) + " is stale or was never made: no such world");
  s->live->sync();
  return *s->live;
}

namespace {
// Whether the non-null id names a live body of the synced world w.
bool names(const Live& w, BodyId id) {
  const EntityId e = id.index1 - 1;
  return e < w.table.generation.size() && w.table.generation[e] == id.generation && w.world->alive(e);
}
}  // namespace

bool live(BodyId id) {
  Slot* s = find(id.world);
  if (!s || id.index1 == 0) return false;
  s->live->sync();
  return names(*s->live, id);
}

Named body(BodyId id) {
  if (id.index1 == 0) throw Error("null body id");
  Live& w = world(id.world);  // synced
  if (!names(w, id)) throw Error(describe(id) + " is stale (the body was destroyed) or was never made");
  return {w, id.index1 - 1};
}

BodyId id_of(WorldId world, const Live& w, EntityId e) { return {e + 1, world, w.table.generation[e]}; }

WorldId add(Live live) {
  auto w = std::make_unique<Live>(std::move(live));
  auto& s = slots();
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!s[i].live) {
      s[i].live = std::move(w);
      return {static_cast<std::uint16_t>(i + 1), s[i].generation};
    }
  }
  if (s.size() >= std::numeric_limits<std::uint16_t>::max()) throw Error("too many worlds (65535 live at most)");
  s.push_back({std::move(w), 1});
  return {static_cast<std::uint16_t>(s.size()), 1};
}

void remove(WorldId id) {
  world(id);  // throws on a bad id
  Slot& slot = slots()[id.index1 - 1];
  slot.live.reset();
  // Generation 0 is never handed out, so a default-constructed id never names a world.
  if (++slot.generation == 0) slot.generation = 1;
}

}  // namespace physics::api
