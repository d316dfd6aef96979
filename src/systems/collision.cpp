#include "systems/collision.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace physics {

Vector Collision::penetration(Vector p, Rect s) {
  const Vector candidates[4] = {
      {p.x, 0.0}, {p.x + s.width, 0.0}, {0.0, p.y}, {0.0, p.y + s.height}};
  Vector best = candidates[0];
  double best_len = std::abs(p.x);
  for (int i = 1; i < 4; ++i) {
    const double len = std::abs(candidates[i].x) + std::abs(candidates[i].y);  // one is 0
    if (len < best_len) {
      best = candidates[i];
      best_len = len;
    }
  }
  return best;
}

bool Collision::resolve(Components& k, EntityId c, EntityId b, Contact* out) {
  const double mc = k.mass[c];
  const double mb = k.mass[b];
  // Two walls never collide (sheet: "deux murs ne font pas de collision").
  if (!std::isfinite(mc) && !std::isfinite(mb)) return false;

  const auto [s_pos, s] = Rect::mdiff(k.position[c], k.box[c], k.position[b], k.box[b]);
  if (!Rect::has_origin(s_pos, s)) return false;

  Vector n = penetration(s_pos, s);

  // Share the position correction in proportion to the speeds (N_c, N_b).
  // A fixed body is never moved, even a moving one (a platform): the sheet's
  // ratio would otherwise push a wall out of a block resting against it.
  const double vc = Vector::norm(k.velocity[c]);
  const double vb = Vector::norm(k.velocity[b]);
  double nc, nb;
  if (!std::isfinite(mb)) {
    nc = 1.0, nb = 0.0;
  } else if (!std::isfinite(mc)) {
    nc = 0.0, nb = 1.0;
  } else if (vc + vb == 0.0) {
    // Both at rest: the heavier ejects the lighter; equal masses: b moves.
    if (mb > mc) nc = 1.0, nb = 0.0;
    else nc = 0.0, nb = 1.0;
  } else {
    nc = vc / (vc + vb);
    nb = vb / (vc + vb);
  }
  k.position[c] = k.position[c] + nc * n;
  k.position[b] = k.position[b] - nb * n;

  const Vector pen = n;
  n = Vector::normalize(n);
  const Vector v = k.velocity[c] - k.velocity[b];
  const double vn = Vector::dot(v, n);
  // Only bodies that approach along n exchange an impulse. A pair already
  // separating (it was pushed apart last frame but still overlaps) gets the
  // position correction alone: applying j there would pull it back together.
  const bool approaching = vn < 0.0;
  if (approaching) {
    // The pair's restitution is the smaller of the two materials': a body made
    // of clay stays dead whatever it hits. Default 1 (the sheet's e).
    const double e = std::min(k.restitution[c], k.restitution[b]);
    const double wc = 1.0 / mc, wb = 1.0 / mb;  // 1/∞ = 0
    // The sheet's j = -(1+e)(v·n)/(1/M_c + 1/M_b) and v_c += n j/M_c,
    // v_b -= n j/M_b, with j/M_c written as
    // -(1+e)(v·n)·w_c/(w_c+w_b): the same value, but exact when b is fixed
    // (ratio 1) or the masses are equal (ratio 1/2), so a wall reverses the
    // normal velocity bit for bit.
    //
    // The sheet says to add these changes to sum_forces; the course's
    // correction sets the velocities. We set them: they are velocity changes
    // (impulse / mass), not forces, and Forces would scale them by dt/m a
    // frame late. Setting them now also means a body touching two others in
    // one pass meets the second one with the velocity the first gave it
    // (sequential impulses), so nothing is counted twice.
    const double dv = -(1.0 + e) * vn;
    k.velocity[c] = k.velocity[c] + (dv * (wc / (wc + wb))) * n;
    k.velocity[b] = k.velocity[b] - (dv * (wb / (wc + wb))) * n;
  }
  if (out) *out = Contact{c, b, pen, n, approaching};
  return true;
}

void Collision::update_all_pairs(Components& k) {
  contacts_.clear();
  contact_count_ = 0;
  const std::size_t count = entities_.size();
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t jdx = i + 1; jdx < count; ++jdx) {
      Contact contact;
      if (resolve(k, entities_[i], entities_[jdx], record_contacts ? &contact : nullptr)) {
        ++contact_count_;
        if (record_contacts) contacts_.push_back(contact);
      }
    }
  }
}

void Collision::build_broadphase(const Components& k, double grow) {
  const std::size_t n = entities_.size();
  boxes_.resize(n);
  fixed_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const EntityId e = entities_[i];
    boxes_[i] = Aabb::around(k.position[e], k.box[e], grow);
    // The same test as resolve's "two walls never collide".
    fixed_[i] = !std::isfinite(k.mass[e]);
  }
  grid_.build(boxes_, fixed_);
}

bool Collision::refresh(const Components& k, std::uint32_t i, PairKey current) {
  const EntityId e = entities_[i];
  if (boxes_[i].contains(k.position[e], k.box[e])) return false;
  // Pushed out of its box: the pairs found when the pass began may no longer
  // hold all of its contacts. Give it a new box and queue the pairs it may
  // now form that the pass has not reached yet (the earlier ones are behind
  // us in the sheet's loop too).
  const Aabb box = Aabb::around(k.position[e], k.box[e], margin);
  boxes_[i] = box;
  grid_.move(i, box);
  grid_.query(box, [&](std::uint32_t j) {
    if (j == i || (fixed_[i] && fixed_[j])) return;
    const PairKey key = pair_key(i, j);
    if (key <= current) return;
    found_late_.push_back(key);
    std::push_heap(found_late_.begin(), found_late_.end(), std::greater<>());
  });
  ++stats_.requeries;
  return true;
}

void Collision::update(Components& k) {
  contacts_.clear();
  contact_count_ = 0;
  stats_ = {};
  found_late_.clear();
  // Every body gets a box `margin` px larger than itself, and the pass takes
  // the pairs of overlapping boxes in the sheet's order. A pair whose boxes
  // do not overlap cannot collide while both bodies stay in their boxes;
  // corrections may push a body out of its box, and refresh() then finds
  // its new pairs. So the pass resolves exactly the pairs that the all-pairs
  // loop finds overlapping, in the same order, with the same values.
  build_broadphase(k, margin);
  stats_.candidates = grid_.pairs().size();
  // Past this many bodies out of their boxes (a crowded or overlapping
  // start), rebuilding at the current positions is cheaper than querying on.
  const std::size_t rebuild_after = std::max<std::size_t>(256, entities_.size() / 4);
  std::size_t moved = 0, next = 0;
  PairKey last = ~PairKey{0};  // never a pair: i < j < 2^32 - 1
  for (;;) {
    const std::vector<PairKey>& listed = grid_.pairs();
    const bool in_list = next < listed.size();
    if (!in_list && found_late_.empty()) break;
    PairKey key;
    if (!found_late_.empty() && (!in_list || found_late_.front() < listed[next])) {
      std::pop_heap(found_late_.begin(), found_late_.end(), std::greater<>());
      key = found_late_.back();
      found_late_.pop_back();
    } else {
      key = listed[next++];
    }
    if (key == last) continue;  // found both when the pass began and later
    last = key;

    const std::uint32_t i = pair_first(key), j = pair_second(key);
    Contact contact;
    if (!resolve(k, entities_[i], entities_[j], record_contacts ? &contact : nullptr)) continue;
    ++contact_count_;
    if (record_contacts) contacts_.push_back(contact);
    moved += refresh(k, i, key) + refresh(k, j, key);
    if (moved > rebuild_after) {
      build_broadphase(k, margin);
      const std::vector<PairKey>& rebuilt = grid_.pairs();
      next = static_cast<std::size_t>(std::upper_bound(rebuilt.begin(), rebuilt.end(), key) - rebuilt.begin());
      found_late_.clear();
      moved = 0;
      ++stats_.rebuilds;
    }
  }
}

std::vector<std::pair<EntityId, EntityId>> Collision::candidate_pairs(const Components& k, double grow) {
  if (!(grow >= 0.0)) throw std::invalid_argument("candidate_pairs: margin must be >= 0");
  build_broadphase(k, grow);
  std::vector<std::pair<EntityId, EntityId>> out;
  out.reserve(grid_.pairs().size());
  for (const PairKey key : grid_.pairs()) out.emplace_back(entities_[pair_first(key)], entities_[pair_second(key)]);
  return out;
}

}  // namespace physics
