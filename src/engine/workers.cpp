#include "engine/workers.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cstdint>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#if PHYSICS_HAS_THREADS
#include <thread>
#endif

namespace physics {

namespace {

#if defined(__x86_64__) || defined(__i386__)
inline void pause() { __builtin_ia32_pause(); }
#else
inline void pause() {}
#endif

// How long a thread spins on a value before it sleeps on it: the stages of a
// substep follow each other within microseconds, a futex wake takes tens.
constexpr auto spin_time = std::chrono::microseconds(2000);
constexpr unsigned pauses = 256;

// What a spinning thread does after its i-th look (from 1): a pause, and
// after `pauses` looks it gives its core away instead (with more threads
// than free cores, the thread it waits for may need this one's: 2 000 runs
// of a team of 3 on 2 cores took 8 s with pauses alone).
inline void back_off(unsigned i) {
  if (i < pauses) return pause();
#if PHYSICS_HAS_THREADS
  std::this_thread::yield();
#endif
}

// Waits until `a` holds something other than `old`, and returns it. Spins
// (back_off()), then sleeps.
template <class T>
T wait_change(const std::atomic<T>& a, T old) {
  const auto until = std::chrono::steady_clock::now() + spin_time;
  for (unsigned i = 1;; ++i) {
    const T now = a.load(std::memory_order_acquire);
    if (now != old) return now;
    back_off(i);
    if (i >= pauses && i % 16 == 0 && std::chrono::steady_clock::now() > until) break;
  }
  for (;;) {
    a.wait(old, std::memory_order_acquire);
    const T now = a.load(std::memory_order_acquire);
    if (now != old) return now;
  }
}

}  // namespace

// A task's parts are claimed from one word, `state`: the task's number
// (its generation) in the high 32 bits, its parts' count and the next part
// to claim in the low ones. A claim is a compare-and-swap that holds only
// for the task it was made for, so a helper that wakes late, after the
// calling thread has done the parts and gone on, claims nothing of a task
// that is over. The task and its context are read only after a claim
// (start() publishes no other task until every part is done).
struct Workers::Team {
#if PHYSICS_HAS_THREADS
  std::atomic<std::uint64_t> state{0};  // generation << 32 | parts << 16 | next part
  std::atomic<int> done{0};             // parts of the task returned
  std::atomic<bool> stop{false};
  std::uint32_t generation = 0;         // the calling thread's count of tasks
  void (*task)(void*, int) = nullptr;
  void* context = nullptr;
  bool together = false;  // each helper takes one part at most (Workers::run_together)
  std::chrono::steady_clock::time_point published;  // when the task was
  std::atomic<bool> came{false};  // some helper claimed a part within late_after of `published`
  std::uint32_t late = 0;         // the last tasks long enough to tell, a bit each (the newest lowest): no helper came
  std::vector<std::thread> helpers;
  std::vector<std::exception_ptr> errors;  // by part: what it threw

  static constexpr std::uint64_t generation_of(std::uint64_t s) { return s >> 32; }
  // The next part of task `gen` in `part`, if it has one left.
  bool claim(std::uint64_t gen, int& part) {
    std::uint64_t s = state.load(std::memory_order_acquire);
    for (;;) {
      const auto next = static_cast<int>(s & 0xFFFF), parts = static_cast<int>(s >> 16 & 0xFFFF);
      if (generation_of(s) != gen || next >= parts) return false;
      if (state.compare_exchange_weak(s, s + 1, std::memory_order_acq_rel, std::memory_order_acquire)) {
        part = next;
        return true;
      }
    }
  }
  // Part t of the task; what it throws is kept for start() to throw.
  void run_part(int t) {
    try {
      task(context, t);
    } catch (...) {
      errors[static_cast<std::size_t>(t)] = std::current_exception();
    }
    if (done.fetch_add(1, std::memory_order_acq_rel) + 1 == static_cast<int>(helpers.size()) + 1) done.notify_one();
  }
  void serve() {
    std::uint64_t seen = 0;  // the state last looked at
    for (;;) {
      const std::uint64_t gen = generation_of(seen);
      while (generation_of(seen) == gen) seen = wait_change(state, seen);
      if (stop.load(std::memory_order_acquire)) return;
      for (int part; claim(generation_of(seen), part);) {
        const bool once = together;  // (read before the part is done: then start() may write the next task's)
        if (std::chrono::steady_clock::now() - published < late_after) came.store(true, std::memory_order_relaxed);
        run_part(part);
        if (once) break;
      }
    }
  }
#endif
};

Workers::Workers(int threads) : threads_(threads) {
  constexpr int most = has_threads ? max_threads : 1;
  if (threads < 1 || threads > most)
    throw std::invalid_argument("threads must be in [1, " + std::to_string(most) + "] (got " + std::to_string(threads) +
                                (has_threads ? ")" : "): this build has no threads"));
#if PHYSICS_HAS_THREADS
  if (threads == 1) return;
  team_ = std::make_unique<Team>();
  team_->errors.resize(static_cast<std::size_t>(threads));
  for (int t = 1; t < threads; ++t) team_->helpers.emplace_back([team = team_.get()] { team->serve(); });
#endif
}

Workers& Workers::operator=(const Workers& other) {
  if (this != &other) *this = Workers(other.threads());
  return *this;
}

Workers::Workers(Workers&& other) noexcept : threads_(other.threads_), team_(std::move(other.team_)) {
#if PHYSICS_HAS_THREADS
  assumed_ = other.assumed_;
#endif
  other.threads_ = 1;
}

Workers& Workers::operator=(Workers&& other) noexcept {
  if (this != &other) {
    Workers old(std::move(*this));  // its helpers stop when it goes
    threads_ = other.threads_, team_ = std::move(other.team_);
#if PHYSICS_HAS_THREADS
    assumed_ = other.assumed_;
#endif
    other.threads_ = 1;
  }
  return *this;
}

Workers::~Workers() {
#if PHYSICS_HAS_THREADS
  if (!team_) return;
  team_->stop.store(true, std::memory_order_release);
  team_->state.store(std::uint64_t{++team_->generation} << 32, std::memory_order_release);  // (no part to claim)
  team_->state.notify_all();
  for (std::thread& t : team_->helpers) t.join();
#endif
}

void Workers::start(void (*task)(void*, int), void* context, [[maybe_unused]] bool together) {
#if PHYSICS_HAS_THREADS
  Team& team = *team_;
  team.task = task, team.context = context, team.together = together;
  team.done.store(0, std::memory_order_relaxed);
  team.came.store(false, std::memory_order_relaxed);
  team.published = std::chrono::steady_clock::now();
  const std::uint64_t gen = ++team.generation;
  // Together: part 0 is this thread's, the helpers claim the others.
  team.state.store(gen << 32 | static_cast<std::uint64_t>(threads_) << 16 | (together ? 1 : 0), std::memory_order_release);
  team.state.notify_all();
  if (together) team.run_part(0);
  for (int part; !together && team.claim(gen, part);) team.run_part(part);
  for (int done = team.done.load(std::memory_order_acquire); done != threads_;) done = wait_change(team.done, done);
  if (team.came.load(std::memory_order_relaxed))
    team.late <<= 1;
  else if (std::chrono::steady_clock::now() - team.published >= late_after)
    team.late = team.late << 1 | 1;
  // (The first thread's exception that there is; the others' dropped, for the next task.)
  const auto thrown =
      std::find_if(team.errors.begin(), team.errors.end(), [](const std::exception_ptr& e) { return e != nullptr; });
  if (thrown == team.errors.end()) return;
  const std::exception_ptr first = *thrown;
  std::fill(team.errors.begin(), team.errors.end(), nullptr);
  std::rethrow_exception(first);
#else
  task(context, 0);
#endif
}

// At most 3 late of the last 16 tasks that could tell (a helper asleep
// after a pause of the world wakes in tens of microseconds; a helper that
// shares its core with a busy process waits for its time slice, some
// milliseconds, at about every other task).
#if PHYSICS_HAS_THREADS
bool Workers::prompt() const {
  if (assumed_ != Helpers::measured) return assumed_ == Helpers::prompt;
  return team_ && std::popcount(team_->late & 0xFFFFu) <= 3;
}
#endif

// Spins only (back_off()): the threads go through the steps side by side,
// so the waits are short, and nobody would wake a sleeper.
void TeamProgress::wait_for(int u, std::uint64_t step) const {
  const std::atomic<std::uint64_t>& theirs = slots_[static_cast<std::size_t>(u)].step;
  for (unsigned i = 1; theirs.load(std::memory_order_acquire) < step; ++i) back_off(i);
}

}  // namespace physics
