#include "round_trip.hpp"

#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

namespace bench {

namespace {

bool pin_to(int core) {
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(core, &set);
  return pthread_setaffinity_np(pthread_self(), sizeof set, &set) == 0;
}

// The mean round trip of `rounds` exchanges, in ns: the thread on core 0
// writes an odd count, the one on core 1 answers with the next even one.
// Both are threads of their own: the calling thread keeps its cores (a
// child process started later inherits them: pinning it here ran every
// later two-thread run of the bench on one core).
double measure(int rounds) {
  alignas(64) std::atomic<int> flag{0};
  std::atomic<bool> pinned{true};
  double ns = 0;
  std::thread answer([&] {
    if (!pin_to(1)) pinned = false;
    for (int i = 0; i < rounds && pinned; ++i) {
      while (flag.load(std::memory_order_acquire) != 2 * i + 1 && pinned) {}
      flag.store(2 * i + 2, std::memory_order_release);
    }
  });
  std::thread ask([&] {
    if (!pin_to(0)) pinned = false;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < rounds && pinned; ++i) {
      flag.store(2 * i + 1, std::memory_order_release);
      while (flag.load(std::memory_order_acquire) != 2 * i + 2 && pinned) {}
    }
    ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() / rounds;
  });
  ask.join();
  answer.join();
  if (!pinned) throw std::runtime_error("--round-trip needs cores 0 and 1 (this process may not run on both)");
  return ns;
}

}  // namespace

double core_round_trip_ns() {
  if (std::thread::hardware_concurrency() < 2) throw std::runtime_error("--round-trip needs two cores");
  std::array<double, 5> ns{};
  for (double& x : ns) x = measure(100000);
  std::nth_element(ns.begin(), ns.begin() + 2, ns.end());
  return ns[2];
}

}  // namespace bench
