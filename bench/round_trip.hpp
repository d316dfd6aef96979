// How long a cache line takes to go from one core to the other and back
// (`build/bench --round-trip`): two threads, pinned to cores 0 and 1, hand
// one atomic back and forth. On this project's 2-core virtual machine it
// reads about 90 ns in some hours and 360-410 ns in others (the two virtual
// cores placed farther apart on the host), and two-thread runs are slow in
// the second case: docs/performance.md, "Threads".
#pragma once

namespace bench {

// The median of 5 measures, each the mean of 100 000 round trips, in ns.
// Throws std::runtime_error when the process cannot run on cores 0 and 1.
double core_round_trip_ns();

}  // namespace bench
