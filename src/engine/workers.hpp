// The engine's threads (WorldDef::threads, --threads N): a fixed team whose
// threads share each task's parts, for the loops of a step whose items are
// independent (each writes its own results), so a step's results are the
// same bits for any number of threads.
//
// A team of our own rather than a task scheduler's pool (oneTBB's): the
// solver's stages come in bursts of a few microseconds each, many per
// substep, and a task scheduler promises no concurrency (its tasks may run
// one after the other on one thread), which a loop whose threads wait for
// each other cannot live with. Here every thread of the team may take part in
// every task (and run_together() has each part on a thread of its own at
// once); between tasks the helpers spin for a short while (the next
// stage is usually microseconds away), then sleep on an atomic wait. As
// Box2D v3 leaves its task system to the game, a game that wants a pool of
// its own keeps threads at 1.
//
// A build without threads (WebAssembly under WASI) has a team of one only:
// asking for more throws std::invalid_argument.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace physics {

// A build without threads (WebAssembly under WASI) compiles the one-thread
// path alone: the loops' bodies are not instantiated a second time for the
// team, nor the joins of the ranges' results (4.8 KB of the browser's module).
#if defined(__wasi__)
#define PHYSICS_HAS_THREADS 0
#else
#define PHYSICS_HAS_THREADS 1
#endif
inline constexpr bool has_threads = PHYSICS_HAS_THREADS;
inline constexpr int max_threads = 64;
// Fewer items than this run on one thread: a loop over them takes a few
// microseconds, about what waking the team costs.
inline constexpr std::size_t min_parallel_items = 4096;

class Workers {
 public:
  // Throws std::invalid_argument unless 1 <= threads <= max_threads (and 1
  // in a build without threads).
  explicit Workers(int threads = 1);
  // A copy has a team of its own, of the same size.
  Workers(const Workers& other) : Workers(other.threads()) {}
  Workers& operator=(const Workers& other);
  Workers(Workers&&) noexcept;
  Workers& operator=(Workers&&) noexcept;
  ~Workers();

  int threads() const { return has_threads ? threads_ : 1; }

  // Runs task(t) for every part t in [0, threads()), and returns when every
  // one has returned. The parts are claimed in turn by the calling thread
  // and the helpers as they come: a helper that a busy machine keeps off
  // its core leaves its part to the calling thread, which would otherwise
  // wait for it (the same results: part t does the same work on any
  // thread; no two parts may wait for each other). If the task throws in
  // some parts (an allocation that fails in a range), run() throws the
  // lowest t's exception once every part has returned, and the team stays
  // usable.
  template <class Task>
  void run(Task&& task) {
    if constexpr (has_threads) {
      if (threads_ > 1) return start(+[](void* context, int t) { (*static_cast<Task*>(context))(t); }, &task, false);
    }
    task(0);
  }
  // run(), with every part on a thread of its own at once, part 0 on the
  // calling thread: for parts that wait for each other (TeamProgress), which
  // must not throw (the others would wait on; SweepPipeline::run's is
  // noexcept).
  template <class Task>
  void run_together(Task&& task) {
    if constexpr (has_threads) {
      if (threads_ > 1) return start(+[](void* context, int t) { (*static_cast<Task*>(context))(t); }, &task, true);
    }
    task(0);
  }

  // Runs a() and b() as two parts of one task (run(): side by side when a
  // helper comes, one after the other on the calling thread when none does
  // or on a team of one), then returns. Two pieces of a stage that do not
  // touch each other's data; neither may use the team.
  template <class A, class B>
  void side_by_side(A&& a, B&& b) {
    if constexpr (has_threads) {
      if (threads_ > 1) return run([&](int t) { t == 0 ? a() : t == 1 ? b() : void(); });
    }
    a(), b();
  }

  // Splits [0, n) into threads() contiguous ranges, in order, and runs
  // body(t, begin, end) on each as a part of one task (run()); one range [0, n) on the calling
  // thread when n < min_items (a few microseconds of work is not worth
  // waking the team for).
  template <class Body>
  void for_ranges(std::size_t n, std::size_t min_items, Body&& body) {
    if constexpr (has_threads) {
      if (splits(n, min_items))
        return run([&](int t) { body(t, range_start(n, t), range_start(n, t + 1)); });
    }
    body(0, std::size_t{0}, n);
  }
  // for_ranges, where body(t, begin, end) returns bits about its range:
  // their OR over the ranges (any corner, any fixed body that moves...).
  template <class Body>
  std::uint8_t or_over_ranges(std::size_t n, std::size_t min_items, Body&& body) {
    if (!splits(n, min_items)) return body(0, std::size_t{0}, n);
    std::array<std::uint8_t, max_threads> bits{};
    for_ranges(n, min_items, [&](int t, std::size_t begin, std::size_t end) {
      bits[static_cast<std::size_t>(t)] = body(t, begin, end);
    });
    std::uint8_t all = 0;
    for (const std::uint8_t b : bits) all |= b;
    return all;
  }
  // for_ranges, where body(t, begin, end, list) appends its range's items
  // to `list`: they reach `out` in range order (the first range's appended
  // there, the others' in lists of their own, then appended), the list one
  // range would have made. part(t) (for t >= 1, asked on the calling thread
  // before the ranges run, only when [0, n) is split) is range t's list, a
  // std::vector<T>& the caller keeps for its memory; it is cleared first.
  template <class T, class Part, class Body>
  void append_over_ranges(std::size_t n, std::size_t min_items, std::vector<T>& out, Part&& part, Body&& body) {
    if constexpr (has_threads) {
      if (splits(n, min_items)) {
        std::array<std::vector<T>*, max_threads> list{&out};
        for (int t = 1; t < threads(); ++t) {
          list[static_cast<std::size_t>(t)] = &part(t);
          list[static_cast<std::size_t>(t)]->clear();
        }
        run([&](int t) { body(t, range_start(n, t), range_start(n, t + 1), *list[static_cast<std::size_t>(t)]); });
        for (int t = 1; t < threads(); ++t)
          out.insert(out.end(), list[static_cast<std::size_t>(t)]->begin(), list[static_cast<std::size_t>(t)]->end());
        return;
      }
    }
    body(0, std::size_t{0}, n, out);
  }
  // Whether for_ranges(n, min_items) splits [0, n) over the team.
  bool splits(std::size_t n, std::size_t min_items) const { return threads() > 1 && n >= min_items; }

  // Whether the helpers came at once (within late_after of its start) to
  // most of the team's last tasks long enough to tell: parts that wait for
  // each other (run_together) are then worth running. On a machine whose
  // other load keeps a helper off its core, each such part waits for it a
  // time slice at a time (the landing rain of 30 000 beside a busy loop:
  // 6.2-6.8 ms a step with the pipelined sweeps, 2.3-2.4 without, on one
  // thread 2.3), while run()'s parts go to whoever comes.
#if PHYSICS_HAS_THREADS  // (the browser's build has no helpers)
  bool prompt() const;
  static constexpr auto late_after = std::chrono::microseconds(200);
  // What prompt() says: measured (the default), or, for tests, always yes or no.
  enum class Helpers : std::uint8_t { measured, prompt, late };
  void assume(Helpers h) { assumed_ = h; }
#endif
  // Where range t of for_ranges(n) starts (range threads() starts at n).
  std::size_t range_start(std::size_t n, int t) const {
    const auto count = static_cast<std::size_t>(threads());
    return n / count * static_cast<std::size_t>(t) + std::min(n % count, static_cast<std::size_t>(t));
  }

 private:
  struct Team;  // the helpers (threads - 1 of them) and what they share
  void start(void (*task)(void*, int), void* context, bool together);
  int threads_ = 1;
#if PHYSICS_HAS_THREADS
  Helpers assumed_ = Helpers::measured;
#endif
  std::unique_ptr<Team> team_;
};

// How far each thread of one task of the team (Workers::run) has gone
// through numbered steps, for threads that wait for some of each other's
// results (the pipelined sweeps, engine/sweep_pipeline.hpp: a block of a
// sweep waits until the other thread's sweep before it is past the blocks
// that share its bodies). Each thread writes its own count, on a cache
// line of its own, and reads the others' only when it waits.
class TeamProgress {
 public:
  // Thread t has done every step before `step`.
  void reach(int t, std::uint64_t step) {
    slots_[static_cast<std::size_t>(t)].step.store(step, std::memory_order_release);
  }
  // Returns once thread u has reached `step`.
  void wait_for(int u, std::uint64_t step) const;

 private:
  struct alignas(64) Slot {
    std::atomic<std::uint64_t> step{0};
  };
  std::array<Slot, max_threads> slots_{};
};

// parts[t] of a caller's per-range scratch (append_over_ranges' part(t)),
// with `parts` grown to a team of `threads` first: every range's element
// then stays where it is while the others are asked for. Not from the
// ranges' tasks.
template <class T>
T& part_of(std::vector<T>& parts, int t, int threads) {
  if (parts.size() < static_cast<std::size_t>(threads)) parts.resize(static_cast<std::size_t>(threads));
  return parts[static_cast<std::size_t>(t)];
}

// *w, or a team of one when there is none.
inline Workers& workers_or_one(Workers* w) {
  static Workers one;  // (no helpers: nothing to share between callers)
  return w ? *w : one;
}

}  // namespace physics
