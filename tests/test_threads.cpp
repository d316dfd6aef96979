// The engine's threads (engine/workers.hpp, WorldDef::threads, --threads):
// the team's ranges, and the same bits for any number of threads on worlds
// big enough for every parallel loop to split (min_parallel_items).
#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cstdint>
#include <new>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "helpers.hpp"
#include "api/registry.hpp"
#include "engine/sweep_pipeline.hpp"
#include "engine/workers.hpp"
#include "physics/physics.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_threads {

namespace {

using namespace physics;

BOOST_AUTO_TEST_SUITE(threads)

// Every index once, in contiguous ranges in order, one per thread.
BOOST_AUTO_TEST_CASE(ranges_cover_every_item_once_in_order) {
  for (const int threads : {1, 2, 3, 7}) {
    Workers w(threads);
    BOOST_TEST(w.threads() == threads);
    for (const std::size_t n : {std::size_t{0}, std::size_t{5}, std::size_t{4096}, std::size_t{10001}}) {
      std::vector<int> seen(n, 0);
      std::vector<std::size_t> starts(static_cast<std::size_t>(threads), n + 1), ends(starts);
      w.for_ranges(n, 1, [&](int t, std::size_t begin, std::size_t end) {
        starts[static_cast<std::size_t>(t)] = begin, ends[static_cast<std::size_t>(t)] = end;
        for (std::size_t i = begin; i < end; ++i) ++seen[i];
      });
      for (std::size_t i = 0; i < n; ++i) BOOST_TEST_REQUIRE(seen[i] == 1);
      for (int t = 0; t < threads && n > 0; ++t) {  // (n = 0 < min_items: one empty range)
        BOOST_TEST(starts[static_cast<std::size_t>(t)] == w.range_start(n, t));
        BOOST_TEST(ends[static_cast<std::size_t>(t)] == w.range_start(n, t + 1));
      }
      BOOST_TEST(w.range_start(n, threads) == n);
    }
  }
}

// Every part of the task runs once per run, many runs in a row (the helpers
// spinning between them, then asleep).
BOOST_AUTO_TEST_CASE(every_part_runs_once_per_task) {
  Workers w(3);
  std::vector<int> runs(3, 0);
  for (int r = 0; r < 2000; ++r) w.run([&](int t) { ++runs[static_cast<std::size_t>(t)]; });
  BOOST_TEST(runs == std::vector<int>(3, 2000), boost::test_tools::per_element());
  Workers copy(w);  // a team of its own, as large
  BOOST_TEST(copy.threads() == 3);
  copy.run([&](int t) { ++runs[static_cast<std::size_t>(t)]; });
  BOOST_TEST(runs == std::vector<int>(3, 2001), boost::test_tools::per_element());
}

// run_together() puts every part on a thread of its own at once, part 0 on
// the caller's, even when the helpers are asleep (between runs here) and
// part 0 is over at once: parts 1 and 2 wait until all three have started,
// which a thread that took two parts would wait for on (the deadline turns
// that into a failure). run() would give the caller a sleeping helper's
// part.
BOOST_AUTO_TEST_CASE(parts_run_together_are_on_threads_of_their_own) {
  Workers w(3);
  for (int r = 0; r < 40; ++r) {
    std::this_thread::sleep_for(std::chrono::milliseconds(r % 2 == 0 ? 3 : 0));  // (past the helpers' spinning)
    std::atomic<int> started{0};
    std::atomic<bool> late{false};
    std::vector<std::thread::id> ids(3);
    w.run_together([&](int t) noexcept {
      ids[static_cast<std::size_t>(t)] = std::this_thread::get_id();
      started.fetch_add(1);
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
      while (t != 0 && started.load() < 3)
        if (std::chrono::steady_clock::now() > deadline) return late.store(true);
    });
    BOOST_TEST_REQUIRE(!late.load());
    BOOST_TEST((ids[0] == std::this_thread::get_id()));
    BOOST_TEST((ids[0] != ids[1] && ids[1] != ids[2] && ids[0] != ids[2]));
  }
}

// What a task throws on any thread reaches run()'s caller once every thread
// is done (the lowest thread's when several throw), and the team runs the
// next task as before.
BOOST_AUTO_TEST_CASE(a_task_that_throws_throws_from_run) {
  Workers w(3);
  BOOST_CHECK_THROW(w.run([](int t) {
    if (t == 2) throw std::bad_alloc();
  }), std::bad_alloc);
  std::vector<int> done(3, 0);
  try {
    w.for_ranges(10000, 1, [&](int t, std::size_t, std::size_t) {
      done[static_cast<std::size_t>(t)] = 1;
      if (t >= 1) throw std::runtime_error(std::to_string(t));
    });
    BOOST_FAIL("for_ranges did not throw");
  } catch (const std::runtime_error& e) {
    BOOST_TEST(std::string(e.what()) == "1");
  }
  BOOST_TEST(done == std::vector<int>(3, 1), boost::test_tools::per_element());
  std::vector<int> runs(3, 0);
  for (int r = 0; r < 100; ++r) w.run([&](int t) { ++runs[static_cast<std::size_t>(t)]; });
  BOOST_TEST(runs == std::vector<int>(3, 100), boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(a_bad_number_of_threads_is_refused) {
  BOOST_CHECK_THROW(Workers(0), std::invalid_argument);
  BOOST_CHECK_THROW(Workers(max_threads + 1), std::invalid_argument);
  WorldDef def = default_world_def();
  def.threads = 0;
  BOOST_CHECK_THROW(create_world(def), Error);
  def.threads = 2;
  const WorldId w = create_world(def);
  BOOST_TEST(world_def(w).threads == 2);
  destroy_world(w);
}

// Every body's position and velocity, then the world destroyed.
std::vector<double> final_state(WorldId w) {
  std::vector<double> state;
  for (const BodyId id : bodies(w))
    for (const Vec2 v : {position(id), velocity(id)}) state.push_back(v.x), state.push_back(v.y);
  destroy_world(w);
  return state;
}

// A stable world on `threads` under gravity down y, with a fixed floor
// `width` px wide at y = 600.
WorldId world_on_floor(int threads, double width) {
  WorldDef def = default_world_def();
  def.gravity = {0.0, 0.001};
  def.solver = SolverKind::stable;
  def.threads = threads;
  const WorldId w = create_world(def);
  BodyDef floor = default_body_def();
  floor.mass = fixed_mass;
  floor.position = {0, 600}, floor.size = {width, 40};
  create_body(w, floor);
  return w;
}

// A walled box: a settled pile of rows (contacts far beyond
// min_parallel_items) and squares raining onto it (impacts, bounces, apart
// pairs), under `solver`, with friction on every other body (or none:
// then each sweep's rows run at once on two threads, its 12 000-odd x rows
// cut in two: ContactSolver::iterate and order_by_axis).
// `then_threads` (when not 0): the world's team changes to that size after half the steps.
// `cut` (when given): how the first step's order cut the frictionless x rows.
// `layers`: the pile's rows of squares; `pipelined` (when given): how many
// relaxations ran their y rows' last sweeps on two threads.
std::vector<double> run_rain(int threads, SolverKind solver, int steps, bool friction = true, int then_threads = 0,
                             Vec2 gravity = {0.0, 0.001},
                             ContactSolver::XRowCut* cut = nullptr, int layers = 42,
                             std::int64_t* pipelined = nullptr) {
  WorldDef def = default_world_def();
  def.gravity = gravity;
  def.solver = solver;
  def.substeps = 2;
  def.threads = threads;
  const WorldId w = create_world(def);
  // (Counted pipelines: the helpers taken as prompt, whatever the machine's load: Workers::prompt.)
  if (pipelined) api::world(w).world->workers.assume(Workers::Helpers::prompt);
  BodyDef wall = default_body_def();
  wall.mass = fixed_mass;
  wall.restitution = 0.5;
  for (const auto& [pos, size] : {std::pair<Vec2, Vec2>{{0, 600}, {1000, 40}}, {{-40, 0}, {40, 640}}, {{1000, 0}, {40, 640}}}) {
    wall.position = pos, wall.size = size;
    create_body(w, wall);
  }
  BodyDef b = default_body_def();
  b.size = {10, 10};
  b.restitution = 0.5;
  int n = 0;
  // 4 200 squares at rest, wall to wall (about 12 600 pairs), and 300 falling: more bodies than
  // min_parallel_items, so that the loops over the bodies split too (Forces, Move, the broad phase's).
  for (int row = 0; row < layers; ++row)
    for (int col = 0; col < 100; ++col, ++n) {
      b.position = {col * 10.0, 590.0 - row * 10.0};
      b.friction = friction && n % 2 ? 0.5 : 0.0;
      create_body(w, b);
    }
  for (int row = 0; row < 6; ++row)  // 300 falling, spaced apart
    for (int col = 0; col < 50; ++col, ++n) {
      b.position = {col * 20.0 + (row % 2) * 5.0, 100.0 - row * 20.0};
      b.velocity = {0.01 * ((col % 5) - 2), 0.2};
      b.friction = friction && n % 2 ? 0.5 : 0.0;
      create_body(w, b);
    }
  for (int s = 0; s < steps; ++s) {
    if (then_threads != 0 && s == steps / 2) api::world(w).world->workers = Workers(then_threads);
    step(w);
    if (cut && s == 0) *cut = api::world(w).world->contact_solver.x_row_cut();
  }
  if (pipelined) *pipelined = api::world(w).world->contact_solver.stats.pipelined;
  return final_state(w);
}

// Bit for bit (a NaN or a -0 differs too: the bits are compared).
std::vector<std::uint64_t> bits(const std::vector<double>& v) {
  std::vector<std::uint64_t> out;
  for (const double x : v) out.push_back(std::bit_cast<std::uint64_t>(x));
  return out;
}

// The stable solver's rain with friction on one thread, run once for the tests that compare with it.
const std::vector<std::uint64_t>& one_thread_rain() {
  static const std::vector<std::uint64_t> one = bits(run_rain(1, SolverKind::stable, 60));
  return one;
}

BOOST_AUTO_TEST_CASE(the_stable_solver_gives_the_same_bits_on_any_number_of_threads) {
  const auto& one = one_thread_rain();
  BOOST_TEST(one == bits(run_rain(2, SolverKind::stable, 60)));
  BOOST_TEST(one == bits(run_rain(3, SolverKind::stable, 60)));
  // Something happened: the rain has fallen onto the pile.
  const auto start = bits(run_rain(1, SolverKind::stable, 0));
  BOOST_TEST(one != start);
}

BOOST_AUTO_TEST_CASE(without_friction_the_x_and_y_sweeps_side_by_side_give_the_same_bits) {
  const auto one = bits(run_rain(1, SolverKind::stable, 60, false));
  BOOST_TEST(one == bits(run_rain(2, SolverKind::stable, 60, false)));
  BOOST_TEST(one == bits(run_rain(3, SolverKind::stable, 60, false)));
  BOOST_TEST(one != one_thread_rain());  // (friction changes the run)
}

// Without friction, a large world's x rows are cut in two stretches that
// two threads sweep at once, then the rows across the cut
// (ContactSolver::order_by_axis). Gravity along x too loads every x row of
// the pile, those across the cut among them, so their order shows.
BOOST_AUTO_TEST_CASE(the_x_rows_cut_in_two_give_the_same_bits_on_any_number_of_threads) {
  const Vec2 sideways{0.0005, 0.001};
  ContactSolver::XRowCut cut{};
  const auto one = bits(run_rain(1, SolverKind::stable, 40, false, 0, sideways, &cut));
  BOOST_TEST(cut.below > 0u);  // (the pile's x rows were cut, and some are across)
  BOOST_TEST(cut.above > 0u);
  BOOST_TEST(cut.across > 0u);
  BOOST_TEST(one == bits(run_rain(2, SolverKind::stable, 40, false, 0, sideways)));
  BOOST_TEST(one == bits(run_rain(3, SolverKind::stable, 40, false, 0, sideways)));
  BOOST_TEST(one != bits(run_rain(1, SolverKind::stable, 40, false)));  // (the sideways pull changes the run)
}

// Without friction, once a pile's x rows stop, its y rows' sweeps left run
// on two threads, one sweep a few blocks behind the other
// (ContactSolver::pipelined_sweeps): a pile of 4 800 squares has enough y
// rows for it. The same bits on any number of threads.
BOOST_AUTO_TEST_CASE(the_y_rows_sweeps_on_two_threads_give_the_same_bits) {
  const Vec2 down{0.0, 0.001};
  std::int64_t pipelined = 0;
  const auto one = bits(run_rain(1, SolverKind::stable, 30, false, 0, down, nullptr, 48, &pipelined));
  BOOST_TEST(pipelined == 0);
  BOOST_TEST(one == bits(run_rain(2, SolverKind::stable, 30, false, 0, down, nullptr, 48, &pipelined)));
  BOOST_TEST(pipelined > 0);
  BOOST_TEST(one == bits(run_rain(3, SolverKind::stable, 30, false, 0, down, nullptr, 48)));
  BOOST_TEST(one == bits(run_rain(2, SolverKind::stable, 30, false, 1, down, nullptr, 48)));
}

// SweepPipeline::defer_one_ended on a pile's contacts in pair order: the
// floor's (body 0, fixed) first, with the bottom row's bodies, whose other
// contacts come last. Each one-ended contact goes just before its body's
// next two-ended one (or to the end); every moving body keeps its
// contacts' order; and the plan's first block no longer reaches the last.
BOOST_AUTO_TEST_CASE(one_ended_items_go_just_before_their_bodys_next_item) {
  using Ends = SweepPipeline::Ends;
  // Bodies 1-3 a column on the floor (3 at the bottom), 4 on 1 (a fixed end: 0's with 3, 5's with 2).
  const std::vector<Ends> items = {{0, 3, 2}, {1, 2, 3}, {5, 2, 2}, {2, 3, 3}, {1, 4, 3}, {4, 6, 1}, {0, 0, 0}};
  std::vector<std::uint32_t> order(items.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  SweepPipeline p;
  p.defer_one_ended(order, 7, [&](std::uint32_t i) { return items[i]; });
  // {0, 3} before 3's next two-ended ({2, 3}); {5, 2} after {1, 2} (2's contact before it), before {2, 3};
  // {4, 6} (4 moves) to the end, after 4's last; {0, 0} (nothing moves) keeps its place.
  const std::vector<std::uint32_t> want = {1, 0, 2, 3, 4, 6, 5};
  BOOST_TEST(order == want, boost::test_tools::per_element());
  BOOST_TEST_REQUIRE(p.ends().size() == order.size());  // (the ends as the items now come)
  for (std::size_t i = 0; i < order.size(); ++i)
    BOOST_TEST((p.ends()[i].c == items[order[i]].c && p.ends()[i].b == items[order[i]].b &&
                p.ends()[i].moving == items[order[i]].moving));
  for (std::uint32_t body = 1; body <= 4; ++body) {  // each moving body's items in their given order
    std::vector<std::uint32_t> seen;
    for (const std::uint32_t i : order)
      if ((items[i].c == body && items[i].moving & 1) || (items[i].b == body && items[i].moving & 2)) seen.push_back(i);
    BOOST_TEST(std::is_sorted(seen.begin(), seen.end()));
  }
  // A pile's plan: 40 columns of 30 bodies on a floor, ids from the top down, contacts by pair.
  std::vector<Ends> pile;
  const auto id = [](int row, int col) { return static_cast<std::uint32_t>(1 + row * 40 + col); };  // row 0 the top
  for (int col = 0; col < 40; ++col) pile.push_back({0, id(29, col), 2});
  for (int row = 0; row < 30; ++row)
    for (int col = 0; col < 40; ++col) {
      if (col < 39) pile.push_back({id(row, col), id(row, col + 1), 3});
      if (row < 29) pile.push_back({id(row, col), id(row + 1, col), 3});
    }
  const auto reach_of_first = [&](const std::vector<std::uint32_t>& o) {
    SweepPipeline plan;
    plan.plan(o.size(), 1 + 30 * 40, 64, [&](std::size_t i, auto&& body) {
      const Ends e = pile[o[i]];
      if (e.moving & 1) body(e.c);
      if (e.moving & 2) body(e.b);
    }, [](std::size_t) { return false; });
    return plan.reach(0);
  };
  std::vector<std::uint32_t> by_pair(pile.size());
  for (std::uint32_t i = 0; i < by_pair.size(); ++i) by_pair[i] = i;
  const std::uint32_t blocks = static_cast<std::uint32_t>((pile.size() + 63) / 64);
  BOOST_TEST(reach_of_first(by_pair) == blocks - 1);  // (the floor's contacts tie block 0 to the last)
  p.defer_one_ended(by_pair, 1 + 30 * 40, [&](std::uint32_t i) { return pile[i]; });
  BOOST_TEST(reach_of_first(by_pair) <= 2u);
}

// A pile built from the top down, as a rain lands (its bottom row's ids
// last), heavy rows on light ones, without friction, its rows a px wider
// than their box, so that they overlap beyond the slop at every step with
// the same contacts: the projection's sweeps run on two threads over its
// 9 000-odd contacts (pipelined_projection), and so do the relaxation's y
// rows (pipelined_sweeps), each with the floor's and walls' contacts moved
// among their bodies' (SweepPipeline::defer_one_ended). (A new order is
// made beside one thread's sweeps, ContactSolver::beside: the steps whose contacts
// changed are not pipelined.)
// `waves` (when not 0): the fewest y rows the relaxation sweeps in waves on
// one thread (ContactSolver::sweep_in_waves_from).
std::vector<double> run_top_down_pile(int threads, SolverStats* stats,
                                      Workers::Helpers helpers = Workers::Helpers::prompt, std::size_t waves = 0) {
  const WorldId w = world_on_floor(threads, 800);
  api::world(w).world->workers.assume(helpers);  // (whatever the machine's load)
  if (waves != 0) api::world(w).world->contact_solver.sweep_in_waves_from(waves);
  BodyDef wall = default_body_def();
  wall.mass = fixed_mass;
  for (const double x : {-40.0, 599.0}) {  // (a px short of the row's 600)
    wall.position = {x, 0}, wall.size = {40, 600};
    create_body(w, wall);
  }
  BodyDef b = default_body_def();
  b.size = {10, 10};
  for (int row = 79; row >= 0; --row)  // 4 800 squares, the top row's first
    for (int col = 0; col < 60; ++col) {
      b.position = {col * 589.0 / 59.0, 590.0 - row * 10.0};
      b.mass = row % 2 ? 20.0 : 1.0;
      create_body(w, b);
    }
  for (int s = 0; s < 40; ++s) step(w);
  *stats = api::world(w).world->contact_solver.stats;
  return final_state(w);
}

BOOST_AUTO_TEST_CASE(the_projection_and_the_y_rows_on_two_threads_give_the_same_bits) {
  SolverStats stats;
  const auto one = bits(run_top_down_pile(1, &stats));
  BOOST_TEST(stats.projections_pipelined == 0);
  BOOST_TEST(one == bits(run_top_down_pile(2, &stats)));
  BOOST_TEST(stats.projections_pipelined > 5);
  BOOST_TEST(stats.pipelined > 5);
  BOOST_TEST(stats.pipelines_left == 0);
  BOOST_TEST(one == bits(run_top_down_pile(3, &stats)));
}

// When the helpers come late to the team's tasks (Workers::prompt: a busy
// machine keeps them off their core), the sweeps that would be pipelined
// run on one thread, with the same bits.
BOOST_AUTO_TEST_CASE(with_late_helpers_the_pipelines_run_on_one_thread_with_the_same_bits) {
  SolverStats stats;
  const auto one = bits(run_top_down_pile(1, &stats));
  BOOST_TEST(one == bits(run_top_down_pile(2, &stats, Workers::Helpers::late)));
  BOOST_TEST(stats.projections_pipelined == 0);
  BOOST_TEST(stats.pipelined == 0);
  BOOST_TEST(stats.pipelines_left > 10);
}

// The y rows' sweeps in waves on one thread (a pile of 100 000 takes them
// so; this one's 4 800 when told to), and, with late helpers, on one of
// two: the same bits as whole sweeps one after the other.
BOOST_AUTO_TEST_CASE(the_y_rows_sweeps_in_waves_on_one_thread_give_the_same_bits) {
  SolverStats stats;
  const auto one = bits(run_top_down_pile(1, &stats));
  BOOST_TEST(stats.in_waves == 0);
  BOOST_TEST(one == bits(run_top_down_pile(1, &stats, Workers::Helpers::prompt, 1024)));
  BOOST_TEST(stats.in_waves > 5);
  BOOST_TEST(one == bits(run_top_down_pile(2, &stats, Workers::Helpers::late, 1024)));
  BOOST_TEST(stats.in_waves > 5);
  BOOST_TEST(stats.pipelined == 0);
}

// SweepPipeline::run_in_waves against whole sweeps one after the other, on
// items whose results depend on their order (each changes both its bodies
// from both): a chain of neighbours with some items reaching far ahead (a
// block that waits for a whole sweep before it). Then a stop: the fourth
// sweep finds none of the bits going on, and the sweeps after it change
// nothing (as the solver's do).
BOOST_AUTO_TEST_CASE(sweeps_in_waves_give_the_bits_of_whole_sweeps) {
  constexpr std::size_t bodies = 400;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> items;
  for (std::uint32_t i = 0; i + 3 < bodies; ++i) {
    items.push_back({i, i + 1});
    items.push_back({i + 3, i});
    if (i % 97 == 50) items.push_back({i, static_cast<std::uint32_t>(bodies - 1 - i / 2)});
  }
  const auto apply = [&](std::vector<double>& v, std::size_t i) {
    const auto [c, b] = items[i];
    v[c] = v[c] * 0.5 + v[b] + 1.0;
    v[b] = v[b] * 0.75 - v[c] * 0.125;
  };
  const auto start = [&] {
    std::vector<double> v(bodies);
    for (std::size_t i = 0; i < bodies; ++i) v[i] = 0.001 * static_cast<double>(i * i % 17);
    return v;
  };
  SweepPipeline plan;
  plan.plan(items.size(), bodies, 16, [&](std::size_t i, auto&& body) { body(items[i].first), body(items[i].second); },
            [](std::size_t i) { return i % 5 == 0; });
  for (const int stop_at : {-1, 3}) {  // (-1: no stop; every sweep finds bit 1)
    const int sweeps = 8, counted = stop_at < 0 ? sweeps : stop_at;
    std::vector<double> want = start();
    for (int s = 0; s < counted; ++s)
      for (std::size_t i = 0; i < items.size(); ++i) apply(want, i);
    std::vector<double> got = start();
    std::vector<int> times(items.size(), 0);  // by item: the sweeps that reached it (its sweep now)
    bool too_many = false;
    const std::uint8_t found = plan.run_in_waves(sweeps, 1, [&](std::size_t from, std::size_t count) {
      std::uint8_t bits = 0;
      for (std::size_t i = from; i < from + count; ++i) {
        const int sweep = times[i]++;
        too_many = too_many || sweep >= sweeps;
        if (stop_at < 0 || sweep < stop_at) apply(got, i);
        bits |= stop_at >= 0 && sweep >= stop_at ? 2 : 1;
      }
      return bits;
    });
    BOOST_TEST(!too_many);
    BOOST_TEST(found == (stop_at < 0 ? 1 : 2));
    BOOST_TEST(plan.sweeps_counted() == (stop_at < 0 ? sweeps : stop_at + 1));  // (the stop's sweep counts)
    BOOST_TEST(bits(want) == bits(got), boost::test_tools::per_element());
    BOOST_TEST(*std::min_element(times.begin(), times.end()) >= counted);
  }
}

// A rain's first landings: a few hundred contacts at a time, too few for
// the team's sweeps, so a new bottom-up order (velocity and position stages)
// is made on the helper while this thread sweeps (ContactSolver::beside). The same
// bits as one thread's, which makes them after its sweeps.
std::vector<double> run_landing(int threads, std::int64_t* beside) {
  const WorldId w = world_on_floor(threads, 1000);
  BodyDef b = default_body_def();
  b.size = {10, 10};
  b.restitution = 0.3;
  for (int row = 0; row < 12; ++row)  // 600 squares, rows 5 px apart, a little sideways
    for (int col = 0; col < 50; ++col) {
      b.position = {col * 20.0 + (row % 2) * 4.0, 585.0 - row * 15.0};
      b.velocity = {0.005 * ((col % 3) - 1), 0.5};
      b.mass = 1.0 + (row % 3) * 4.0;  // (heavy on light: overlaps beyond the slop for the position stage)
      create_body(w, b);
    }
  for (int s = 0; s < 80; ++s) step(w);
  *beside = api::world(w).world->contact_solver.stats.orders_beside;
  return final_state(w);
}

BOOST_AUTO_TEST_CASE(the_bottom_up_order_made_beside_the_sweeps_gives_the_same_bits) {
  std::int64_t beside = 0;
  const auto one = bits(run_landing(1, &beside));
  BOOST_TEST(beside == 0);
  BOOST_TEST(one == bits(run_landing(2, &beside)));
  BOOST_TEST(beside > 10);  // (rows landed at many substeps: new orders, made beside)
  BOOST_TEST(one == bits(run_landing(3, &beside)));
}

// A pile of 2 400 squares (some 9 000 pairs) landing under 15 600 falling far apart
// (in no pair): fewer pairs than bodies, enough for the team, so the
// bodies of the pairs are looked at in ranges of ids, one a thread
// (ContactSolver::changed_since_classified). The same bits on any team.
std::vector<double> run_sparse(int threads) {
  const WorldId w = world_on_floor(threads, 4000);
  BodyDef b = default_body_def();
  b.size = {10, 10};
  b.restitution = 0.2;
  for (int i = 0; i < 18000; ++i) {  // the pile's and the falling ones' ids mixed
    const int col = i % 300, row = i / 300;
    const bool pile = col < 40;
    b.position = pile ? Vec2{col * 10.0, 560.0 - row * 10.0} : Vec2{500.0 + col * 30.0, -2000.0 - row * 30.0};
    b.velocity = {pile ? 0.001 * (col % 3) : 0.0, pile ? 0.2 : 0.05 * (row % 3)};  // (the pile lands)
    create_body(w, b);
  }
  for (int s = 0; s < 20; ++s) step(w);
  return final_state(w);
}

BOOST_AUTO_TEST_CASE(the_bodies_of_fewer_pairs_than_bodies_looked_at_by_ranges_give_the_same_bits) {
  const auto one = bits(run_sparse(1));
  BOOST_TEST(one == bits(run_sparse(2)));
  BOOST_TEST(one == bits(run_sparse(3)));
}

// What was planned for one team (the pipelines' blocks, the x rows' cut)
// serves a team of another size, with the same bits.
BOOST_AUTO_TEST_CASE(a_team_of_another_size_gives_the_same_bits) {
  const auto& one = one_thread_rain();
  BOOST_TEST(one == bits(run_rain(2, SolverKind::stable, 60, true, 3)));
  BOOST_TEST(one == bits(run_rain(3, SolverKind::stable, 60, true, 1)));
}

BOOST_AUTO_TEST_CASE(the_auto_mode_gives_the_same_bits_on_any_number_of_threads) {
  const auto one = bits(run_rain(1, SolverKind::automatic, 40));
  BOOST_TEST(one == bits(run_rain(2, SolverKind::automatic, 40)));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace

}  // namespace test_threads
