// Gauss-Seidel sweeps on two threads, one sweep behind the other.
//
// A sweep goes over items (the relaxation's rows, the projection's
// contacts) in order, each reading and changing a few bodies' values only:
// any order that keeps, for every body, the order of its items gives the
// same bits as the given one. Here the items come in blocks, and each block
// knows its reach, the last block whose items share a body with its own.
// Thread t takes the sweeps t, t + 2..., block by block, and starts a block
// once the other thread's sweep (the one before its own) is past the
// block's reach: every body then meets its items sweep after sweep in the
// given order, the same bits as one thread. Each thread's progress is one
// count, its blocks done over its sweeps (TeamProgress).
//
// It pays when the reach stays close to the block (a pile whose items come
// in an order that keeps neighbours together): a block that reaches the
// last one waits for the whole sweep before it.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/workers.hpp"

namespace physics {

#if PHYSICS_HAS_THREADS  // (not in the browser's build: no threads)
class SweepPipeline {
 public:
  // Blocks of about `block` items of [0, items), item i and i + 1 kept in
  // one block when together(i); bodies(i, f) calls f(body) for each body
  // (below `body_count`) whose values item i reads or changes.
  template <class Bodies, class Together>
  void plan(std::size_t items, std::size_t body_count, std::size_t block, Bodies&& bodies, Together&& together);
  bool planned() const { return planned_; }
  std::uint32_t reach(std::size_t block) const { return reach_[block]; }  // (the plan's)
  void forget() { planned_ = false; }

  // `items` (in their sweep order) with each item that has one moving end
  // moved to just before that body's next item with two (or to the end):
  // ends(item) is {c, b, moving} (bodies below `body_count`; bit 0 of
  // `moving`, c's values change; bit 1, b's). Every item keeps its order
  // with the items it shares a moving body with, so the sweeps give the
  // same bits; a fixed body's items, which come together in an order by
  // pair (the floor's first, with bodies from all over a pile), no longer
  // tie the first block to the last.
  struct Ends {
    std::uint32_t c, b;
    unsigned moving;
  };
  template <class EndsOf>
  void defer_one_ended(std::span<std::uint32_t> items, std::size_t body_count, EndsOf&& ends);
  // The ends of the last defer_one_ended()'s items, in the items' new order
  // (each asked once, there): a plan may read its items' bodies here.
  std::span<const Ends> ends() const { return ends_; }

  // `sweeps` sweeps over the planned items on a team of two or more (its
  // first two threads), or up to the first sweep whose blocks' bits
  // (sweep_block(from, count)'s, OR-ed) have none of `going_on`: the
  // caller's sweeps after such a one must change nothing (both threads
  // stop at it; blocks of the next sweep may have run). Returns the bits
  // of the last sweep that counts. sweep_block must not throw.
  template <class SweepBlock>
  std::uint8_t run(Workers& w, int sweeps, std::uint8_t going_on, SweepBlock&& sweep_block);
  // The same sweeps (at least one) on this thread alone, in waves: sweep
  // s + 1 takes each block as soon as sweep s is past its reach, and the
  // first sweep not done leads by at most `lead` blocks. The blocks between
  // the last sweep and the first (a few reaches a sweep) stay in the cache
  // from sweep to sweep, where whole sweeps one after the other read every
  // block from the level-3 cache or memory again once the items outgrow the
  // level 2. The same bits (each body meets its items sweep after sweep in
  // the given order), the same stop and the same result as run().
  template <class SweepBlock>
  std::uint8_t run_in_waves(int sweeps, std::uint8_t going_on, SweepBlock&& sweep_block);
  static constexpr std::uint32_t lead = 4;
  // How many sweeps of the last run() or run_in_waves() counted: up to the
  // first that found none of going_on, or all. (Blocks of later sweeps may
  // have run: in waves, most of every later sweep's.)
  int sweeps_counted() const { return counted_; }

 private:
  std::vector<std::uint32_t> start_;       // block b: items [start_[b], start_[b + 1])
  std::vector<std::uint32_t> reach_;       // block b: the last block sharing a body with it
  std::vector<std::uint32_t> last_block_;  // by body: the last block it is in (plan())
  std::vector<std::uint32_t> next_pair_;   // by body: defer_one_ended()'s scratch
  std::vector<std::uint64_t> deferred_;    // defer_one_ended()'s: (where it goes) << 32 | item's place
  std::vector<std::uint32_t> kept_;        // defer_one_ended()'s: the items as they came
  std::vector<Ends> ends_, kept_ends_;     // defer_one_ended()'s: by item, then as they came
  bool planned_ = false;
  int counted_ = 0;
};

template <class Bodies, class Together>
void SweepPipeline::plan(std::size_t items, std::size_t body_count, std::size_t block, Bodies&& bodies,
                         Together&& together) {
  start_.clear();
  for (std::size_t at = 0; at < items;) {
    start_.push_back(static_cast<std::uint32_t>(at));
    at = std::min(items, at + block);
    while (at < items && together(at - 1)) ++at;
  }
  const std::size_t blocks = start_.size();
  start_.push_back(static_cast<std::uint32_t>(items));
  // (No clearing: each body read below is written here first.)
  last_block_.resize(body_count);
  for (std::uint32_t b = 0; b < blocks; ++b)
    for (std::size_t i = start_[b]; i < start_[b + 1]; ++i) bodies(i, [&](std::size_t body) { last_block_[body] = b; });
  reach_.resize(blocks);
  for (std::uint32_t b = 0; b < blocks; ++b) {
    std::uint32_t reach = b;
    for (std::size_t i = start_[b]; i < start_[b + 1]; ++i)
      bodies(i, [&](std::size_t body) { reach = std::max(reach, last_block_[body]); });
    reach_[b] = reach;
  }
  planned_ = true;
}

template <class EndsOf>
void SweepPipeline::defer_one_ended(std::span<std::uint32_t> items, std::size_t body_count, EndsOf&& ends) {
  const auto n = static_cast<std::uint32_t>(items.size());
  next_pair_.resize(body_count);
  ends_.resize(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const Ends e = ends_[i] = ends(items[i]);
    next_pair_[e.c] = next_pair_[e.b] = n;  // (n: the end)
  }
  deferred_.clear();
  for (std::uint32_t i = n; i-- > 0;) {
    const Ends e = ends_[i];
    if (e.moving == 3)
      next_pair_[e.c] = next_pair_[e.b] = i;
    else if (e.moving != 0)
      deferred_.push_back(std::uint64_t{next_pair_[e.moving & 1 ? e.c : e.b]} << 32 | i);
  }
  if (deferred_.empty()) return;
  std::sort(deferred_.begin(), deferred_.end());
  kept_.assign(items.begin(), items.end());
  kept_ends_.swap(ends_);
  ends_.resize(n);
  auto d = deferred_.begin();
  std::size_t out = 0;
  const auto put = [&](std::uint32_t i) { items[out] = kept_[i], ends_[out++] = kept_ends_[i]; };
  for (std::uint32_t i = 0; i <= n; ++i) {
    for (; d != deferred_.end() && *d >> 32 == i; ++d) put(static_cast<std::uint32_t>(*d));
    if (i == n) break;
    const unsigned moving = kept_ends_[i].moving;
    if (moving == 0 || moving == 3) put(i);
  }
}

template <class SweepBlock>
std::uint8_t SweepPipeline::run(Workers& w, int sweeps, std::uint8_t going_on, SweepBlock&& sweep_block) {
  const std::uint64_t blocks = reach_.size();
  std::vector<std::uint8_t> found(static_cast<std::size_t>(sweeps), 0);
  std::atomic<int> stop{sweeps};  // the first sweep that found none of going_on, once one has
  TeamProgress progress;          // thread t has done blocks [0, step) of sweep after sweep (its sweeps' blocks in a row)
  constexpr std::uint64_t done = ~std::uint64_t{0};
  w.run_together([&](int t) noexcept {
    const int other = 1 - t;
    for (int sweep = t; t < 2 && sweep < sweeps && sweep <= stop.load(std::memory_order_acquire); sweep += 2) {
      const std::uint64_t before = static_cast<std::uint64_t>(sweep / 2) * blocks;  // its blocks of its earlier sweeps
      std::uint8_t bits = 0;
      for (std::uint64_t b = 0; b < blocks; ++b) {
        // The other thread's sweep (sweep - 1) past block reach_[b]: its count, over its earlier sweeps too.
        if (sweep > 0) progress.wait_for(other, static_cast<std::uint64_t>((sweep - 1) / 2) * blocks + reach_[b] + 1);
        if (stop.load(std::memory_order_acquire) < sweep) break;
        bits |= sweep_block(std::size_t{start_[b]}, std::size_t{start_[b + 1] - start_[b]});
        progress.reach(t, before + b + 1);
      }
      if (stop.load(std::memory_order_acquire) < sweep) break;
      found[static_cast<std::size_t>(sweep)] = bits;
      if (!(bits & going_on)) {
        for (int was = stop.load(); sweep < was && !stop.compare_exchange_weak(was, sweep);) {}
        break;
      }
    }
    progress.reach(t, done);  // (what the other waits for comes no more)
  });
  counted_ = std::min(stop.load(), sweeps - 1) + 1;
  return found[static_cast<std::size_t>(counted_ - 1)];
}

template <class SweepBlock>
std::uint8_t SweepPipeline::run_in_waves(int sweeps, std::uint8_t going_on, SweepBlock&& sweep_block) {
  const auto blocks = static_cast<std::uint32_t>(reach_.size());
  const auto n = static_cast<std::size_t>(sweeps);
  std::vector<std::uint32_t> done(n, 0);  // by sweep: its blocks [0, done) are swept
  std::vector<std::uint8_t> found(n, 0);  // by sweep: its blocks' bits so far, OR-ed
  for (std::size_t first = 0, front = lead;; front += lead) {  // first: the first sweep not done
    for (std::size_t s = first; s < n; ++s) {
      const std::uint32_t limit = s == first ? static_cast<std::uint32_t>(std::min<std::size_t>(front, blocks)) : blocks;
      std::uint32_t& b = done[s];
      for (; b < limit && (s == first || done[s - 1] > reach_[b]); ++b)
        found[s] |= sweep_block(std::size_t{start_[b]}, std::size_t{start_[b + 1] - start_[b]});
      if (b == 0) break;  // (the sweeps after it have not started either)
    }
    for (; done[first] == blocks; ++first)
      if (!(found[first] & going_on) || first + 1 == n) return counted_ = static_cast<int>(first) + 1, found[first];
  }
}
#endif

}  // namespace physics
