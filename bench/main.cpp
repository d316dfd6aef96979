// `make bench`: our engine, Box2D 2.4.1 and Chipmunk 7 (Debian's), and with
// `make bench PEERS=DIR` Box2D v3.2 and a release Chipmunk built from source,
// on the same scenes, in one run, on this machine. Prints a table and writes
// bench/RESULTS.md.
//
// The same program is linked twice: build/bench (ours and Debian's engines)
// and build/bench-peers (the peers from source), which cannot share a binary
// (see the Makefile). build/bench runs every run as a child process, of
// itself or of build/bench-peers for the peers' engines.
//
// Each run builds the scene (not timed), then times every one of `steps`
// steps with a steady clock; the first `warmup` are discarded (allocation,
// broadphase growth, the first impacts). Quality is measured afterwards, on
// the final state read back in the scene's units, by the same code for all
// engines.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <sys/resource.h>

#include <thread>
#include <unistd.h>
#include <vector>

#include "bench.hpp"
#include "broadphase_compare.hpp"
#include "round_trip.hpp"

namespace {

using bench::Body;
using bench::Scene;

struct Options {
  std::vector<std::string> scenes{"gas", "rain", "pyramid", "pyramid_friction", "many_pyramids", "tiles"};
  std::vector<std::size_t> sizes{1000, 10000, 100000};
  // The maps' sides of the tiles scene (cells): the same 10 000 bodies on each.
  std::vector<std::size_t> map_sides{200, 1000, 2000};
  // Gas sizes run by ours alone: the peers' 100 000-body runs already take
  // most of the budget, ten times as many bodies would only be cut short.
  std::vector<std::size_t> ours_only_gas{1000000};
  // Ours and Box2D v3.2 on two threads too (ours-2t right after ours,
  // box2d3-2t after box2d3) on the stable solver's scenes of at least this
  // many bodies (0: never). Ours and ours-2t alternate `repeats` times
  // there: one pair of runs is one draw of the second core (a busy
  // neighbour took it for a whole pair: the rain at 1.03 times one thread).
  std::size_t two_threads_from = 100000;
  // Runs of ours and of Box2D v3.2 on each scene of at most repeat_below
  // bodies (the tile maps but): each process runs fast or slow as the machine
  // places it, which swung the pyramid's ratio from 2.8x to 5.7x between
  // single runs. The two engines alternate, every other engine runs once,
  // and each row is its engine's median run.
  int repeats = 3;
  std::size_t repeat_below = 25000;
  std::vector<std::string> engines{"ours", "box2d", "chipmunk"};
  bool engines_given = false;  // without --engines, --peers puts the peers' engines second and third
  std::string peers;           // build/bench-peers: the binary holding box2d3 and chipmunk-release
  std::string peer_sources;    // the tarballs they were built from, quoted in RESULTS.md
  int steps = 600, warmup = 60;
  // s per run: a run past it stops early (and says so). 30 s keeps `make bench
  // PEERS=DIR` from a clean tree within 15 minutes on this 2-core machine
  // (40 s took 15 min 4 s, the machine shared with other builds).
  double budget = 30.0;
  double phase_budget = 150.0;  // s per run of rain_phase (its 100 000-body run: 1068 steps, ~140 s)
  std::string out = "bench/RESULTS.md";
  bool compare = true;  // the broadphase comparison
  bool isolate = true;  // each run in a fresh process (see run_isolated)
  std::string child;    // internal: "ENGINE,SCENE,N": run only that and print its RESULT line
  bool list = false;    // internal: print the engines linked into this binary
  bool round_trip = false;  // --round-trip: only print the cores' round trip (round_trip.hpp)
  bool stages = false;      // --stages (with --child): the engine's stage times over the median tenth of the steps
};

struct Quality {
  std::size_t escaped = 0;   // dynamic bodies whose centre left the container (or is not finite)
  double max_overlap = 0;    // deepest overlap of two boxes (or a box into a wall), block sides
  double energy_drift = 0;   // (KE_end - KE_start) / KE_start
  double top_moved = 0;      // pyramids: the largest displacement of a pyramid's top block, m
};

struct Result {
  std::string engine, scene;
  std::size_t n = 0;
  double median_ms = 0, p95_ms = 0, build_ms = 0;
  int steps_run = 0;  // fewer than asked when the run hit the time budget
  double peak_mb = 0; // the run's process: peak resident memory
  double map_mb = 0;  // the heap its tile map took (Engine::map_mb)
  double others = NAN; // the machine's other load during the run, in cores (others_load); NaN: unknown
  double own = NAN;    // the cores the run's process kept busy over its life (two threads: up to 2); NaN: unknown
  double round_trip_ns = NAN;  // two-thread runs: the cores' round trip just before (round_trip.hpp); NaN: not measured
  Quality q;
};

double kinetic_energy(const std::vector<Body>& bodies) {
  double e = 0;
  for (const Body& b : bodies)
    if (!b.fixed) e += 0.5 * (b.vx * b.vx + b.vy * b.vy);  // every mass is 1
  return e;
}

// Overlap depth of two boxes: the shorter of the two axis overlaps (the
// distance that separates them), 0 when they do not overlap.
double depth(const Body& a, const Body& b) {
  const double ox = (a.hx + b.hx) - std::abs(a.cx - b.cx);
  const double oy = (a.hy + b.hy) - std::abs(a.cy - b.cy);
  return ox > 0 && oy > 0 ? std::min(ox, oy) : 0.0;
}

// The fixed bodies of the final state, and the scene's map as its boxes
// (map_boxes), those that meet the region the dynamic bodies span.
std::vector<Body> walls_of(const Scene& s, const std::vector<Body>& end) {
  std::vector<Body> walls;
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  for (const Body& b : end) {
    if (b.fixed) walls.push_back(b);
    else if (std::isfinite(b.cx) && std::isfinite(b.cy))
      x0 = std::min(x0, b.cx - b.hx), y0 = std::min(y0, b.cy - b.hy), x1 = std::max(x1, b.cx + b.hx), y1 = std::max(y1, b.cy + b.hy);
  }
  if (s.map.cells.empty() || x0 > x1) return walls;
  const Body span{(x0 + x1) / 2, (y0 + y1) / 2, (x1 - x0) / 2, (y1 - y0) / 2};  // the dynamic bodies' bounding box
  for (const Body& b : bench::map_boxes(s))
    if (std::abs(b.cx - span.cx) < b.hx + span.hx && std::abs(b.cy - span.cy) < b.hy + span.hy) walls.push_back(b);
  return walls;
}

Quality measure(const Scene& s, const std::vector<Body>& end) {
  Quality q;
  std::vector<std::size_t> dyn;
  for (std::size_t i = 0; i < end.size(); ++i)
    if (!end[i].fixed) dyn.push_back(i);
  const std::vector<Body> walls = walls_of(s, end);
  for (const std::size_t i : dyn) {
    const Body& b = end[i];
    const bool inside = std::isfinite(b.cx) && std::isfinite(b.cy) && b.cx >= 0 && b.cx <= s.width && b.cy >= 0 &&
                        b.cy <= s.height;
    if (!inside) ++q.escaped;
    for (const Body& w : walls) q.max_overlap = std::max(q.max_overlap, depth(b, w));
  }
  // Every pair of dynamic boxes, by a sweep on x (boxes are at most a few
  // metres wide, so each meets only its neighbours).
  std::vector<std::size_t> order = dyn;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return end[a].cx - end[a].hx < end[b].cx - end[b].hx;
  });
  for (std::size_t oi = 0; oi < order.size(); ++oi) {
    const Body& a = end[order[oi]];
    if (!std::isfinite(a.cx)) continue;
    for (std::size_t oj = oi + 1; oj < order.size(); ++oj) {
      const Body& b = end[order[oj]];
      if (b.cx - b.hx >= a.cx + a.hx) break;
      q.max_overlap = std::max(q.max_overlap, depth(a, b));
    }
  }
  return q;
}

std::unique_ptr<bench::Engine> engine_or_throw(const std::string& engine, const Scene& s) {
  if (auto e = bench::make_engine(engine, s)) return e;
  throw std::invalid_argument("engine '" + engine + "' is not in this binary");
}

// gas and rain take the size asked; the pyramids are Box2D's fixed scenes.
bool sized(const std::string& scene) {
  return scene == "gas" || scene.starts_with("rain");
}

// rain_phase: the rain over the same phase at every size. The rain's steps
// 61-600 are a different phase at each size: its grid fills the container,
// whose side grows as sqrt(N), so a 100 000-body grid falls from 3.2 times as
// high, for sqrt(3.2) = 1.78 times as long, and is still landing at step 600
// where a 10 000-body pile has settled. Here steps and warm-up are scaled by
// that factor (sqrt of the side over the 10 000-body rain's side): each size
// is timed over the same share of its fall, landing and settling. (A pile at
// rest is not a comparable phase: a frictionless 100 000-body pile is still
// flowing after 1200 steps, no body slower than 0.1 m/s.)
Scene make_rain_phase(std::size_t n) {
  Scene s = bench::make_rain(n);
  s.name = "rain_phase";
  s.time_scale = std::sqrt(s.height / bench::make_rain(10000).height);
  return s;
}

// rain_falling: the rain's first second (60 steps, the first 5 left out),
// its steps scaled as rain_phase's: each size is timed over the same share of
// its fall, in which the grid falls and its lowest rows land.
Scene make_rain_falling(std::size_t n) {
  Scene s = make_rain_phase(n);
  s.name = "rain_falling";
  s.steps = 65, s.warmup = 5;
  return s;
}

Scene make_scene(const std::string& name, std::size_t n) {
  if (name.starts_with("tiles_")) return bench::make_tiles(std::stoi(name.substr(6)));
  if (name == "gas") return bench::make_gas(n);
  if (name == "rain") return bench::make_rain(n);
  if (name == "rain_phase") return make_rain_phase(n);
  if (name == "rain_falling") return make_rain_falling(n);
  if (name == "rain_settled") return bench::make_rain_settled(n);
  if (name == "pyramid") return bench::make_pyramid();
  if (name == "pyramid_friction") return bench::make_pyramid_friction();
  if (name == "many_pyramids") return bench::make_many_pyramids();
  throw std::invalid_argument("unknown scene '" + name +
                              "' (gas, rain, rain_phase, rain_falling, rain_settled, pyramid, pyramid_friction, "
                              "many_pyramids, tiles_SIDE)");
}

// The steps a run of s takes: the scene's own, or the harness's, times its time scale.
double planned_steps(const Scene& s, const Options& o) { return (s.steps > 0 ? s.steps : o.steps) * s.time_scale; }

double largest_top_move(const Scene& s, const std::vector<Body>& end) {
  double moved = 0;
  for (const std::size_t i : s.tops)
    moved = std::max(moved, std::hypot(end[i].cx - s.bodies[i].cx, end[i].cy - s.bodies[i].cy));
  return moved;
}

double percentile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  const std::size_t k = static_cast<std::size_t>(std::ceil(p * static_cast<double>(v.size()))) - 1;
  return v[std::min(k, v.size() - 1)];
}

// The CPU time the machine has spent, every process and the hypervisor's
// steal included (/proc/stat; NaN where it cannot be read), this process's
// and its waited-for children's (getrusage).
struct CpuTimes {
  double machine_s = NAN, self_s = 0, children_s = 0;
};

CpuTimes cpu_times() {
  CpuTimes t;
  std::ifstream in("/proc/stat");
  std::string cpu;
  unsigned long long user = 0, nice = 0, system = 0, idle = 0, iowait = 0, irq = 0, softirq = 0, steal = 0;
  if (in >> cpu >> user >> nice >> system >> idle >> iowait >> irq >> softirq >> steal && cpu == "cpu")
    t.machine_s = static_cast<double>(user + nice + system + irq + softirq + steal) / static_cast<double>(sysconf(_SC_CLK_TCK));
  const auto seconds = [](timeval v) { return static_cast<double>(v.tv_sec) + static_cast<double>(v.tv_usec) * 1e-6; };
  const auto used = [&](int who) {
    rusage use{};
    getrusage(who, &use);
    return seconds(use.ru_utime) + seconds(use.ru_stime);
  };
  t.self_s = used(RUSAGE_SELF), t.children_s = used(RUSAGE_CHILDREN);
  return t;
}

// How many cores the rest of the machine kept busy between a and b, over
// wall_s seconds: what a two-thread run did not have of the second core (on
// a shared machine a neighbour may hold it). NaN when unknown, or when the
// window was too short for the kernel's ticks (10 ms) to tell.
double others_load(const CpuTimes& a, const CpuTimes& b, double wall_s) {
  if (!(wall_s >= 0.25) || std::isnan(a.machine_s) || std::isnan(b.machine_s)) return NAN;
  const double ours = (b.self_s - a.self_s) + (b.children_s - a.children_s);
  return std::max(0.0, ((b.machine_s - a.machine_s) - ours) / wall_s);
}

// --stages: the engine's own time a stage over the median tenth of the timed
// steps (ranked by their time; `first`: the first timed step's index), to
// stderr: what a median step is made of, where the means over a run mix
// its phases (a landing step and a settled one).
void print_stages(const bench::Engine& e, const std::vector<double>& times, std::size_t first) {
  const bench::Engine::StageSteps* st = e.stages();
  if (!st || st->steps.size() < first + times.size() || times.empty()) {
    std::fprintf(stderr, "stages: none kept (ours and ours-2t keep them)\n");
    return;
  }
  std::vector<std::size_t> rank(times.size());
  for (std::size_t i = 0; i < rank.size(); ++i) rank[i] = i;
  std::sort(rank.begin(), rank.end(), [&](std::size_t a, std::size_t b) { return times[a] < times[b]; });
  const std::size_t from = times.size() * 45 / 100, to = std::max(from + 1, times.size() * 55 / 100);
  std::vector<double> mean(st->names.size(), 0.0);
  double step_ms = 0.0;
  for (std::size_t k = from; k < to; ++k) {
    step_ms += times[rank[k]] / static_cast<double>(to - from);
    for (std::size_t j = 0; j < mean.size(); ++j) mean[j] += st->steps[first + rank[k]][j] / static_cast<double>(to - from);
  }
  std::fprintf(stderr, "stages over the median tenth of the timed steps (%zu of %zu, %.4f ms a step):\n", to - from,
               times.size(), step_ms);
  double sum = 0.0;
  for (std::size_t j = 0; j < mean.size(); ++j) {
    sum += mean[j];
    if (mean[j] > 0.0) std::fprintf(stderr, "  %-12s %.4f ms\n", st->names[j].c_str(), mean[j]);
  }
  std::fprintf(stderr, "  (the stages' sum %.4f ms)\n", sum);
}

Result run(const std::string& engine, const Scene& s, const Options& o) {
  using clock = std::chrono::steady_clock;
  Result r;
  r.engine = engine, r.scene = s.name, r.n = s.dynamic_count();
  const auto t0 = clock::now();
  auto e = engine_or_throw(engine, s);
  r.build_ms = std::chrono::duration<double, std::milli>(clock::now() - t0).count();
  r.map_mb = e->map_mb;
  // Every step's time; the first `warmup` are left out of the statistics
  // unless the budget stopped the run before it got past them.
  const int steps = static_cast<int>(std::lround(planned_steps(s, o)));
  const int warmup = static_cast<int>(std::lround((s.steps > 0 ? s.warmup : o.warmup) * s.time_scale));
  const double budget = s.name == "rain_phase" ? o.phase_budget : o.budget;
  std::vector<double> times;
  times.reserve(static_cast<std::size_t>(steps));
  const auto start = clock::now();
  for (int i = 0; i < steps; ++i) {
    const auto a = clock::now();
    e->step();
    const auto b = clock::now();
    times.push_back(std::chrono::duration<double, std::milli>(b - a).count());
    if (o.stages) e->keep_stage_times();
    r.steps_run = i + 1;
    if (std::chrono::duration<double>(b - start).count() > budget) break;
  }
  const bool past_warmup = static_cast<int>(times.size()) > warmup;
  if (past_warmup) times.erase(times.begin(), times.begin() + warmup);
  if (o.stages) print_stages(*e, times, past_warmup ? static_cast<std::size_t>(warmup) : 0);
  r.median_ms = percentile(times, 0.5);
  r.p95_ms = percentile(times, 0.95);
  std::vector<Body> end;
  e->read(end);
  r.q = measure(s, end);
  const double e0 = kinetic_energy(s.bodies);
  if (s.name == "gas" && e0 > 0) r.q.energy_drift = (kinetic_energy(end) - e0) / e0;
  r.q.top_moved = largest_top_move(s, end);
  return r;
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

// One run in a fresh process (this program again, with --child): every
// engine starts from a clean heap, whatever ran before it. In one process the
// runs were not independent: our 100 000-body gas measured 4.5 ms/step alone
// and 5-5.7 ms after the other engines' runs, the allocator's state being
// what the earlier runs left.
// The peers' engines run in build/bench-peers, the others in this binary.
Result run_isolated(const std::string& self, const std::string& engine, const Scene& s, const Options& o) {
  const auto& here = bench::engine_names();
  const bool local = std::find(here.begin(), here.end(), engine) != here.end();
  std::ostringstream cmd;
  cmd << "'" << (local ? self : o.peers) << "' --child " << engine << "," << s.name << "," << s.dynamic_count() << " --steps " << o.steps
      << " --warmup " << o.warmup << " --budget " << o.budget << " --phase-budget " << o.phase_budget;
  // A two-thread run's cores: how far apart they are now (round_trip.hpp).
  double round_trip = NAN;
  if (engine.ends_with("-2t")) try {
      round_trip = bench::core_round_trip_ns();
    } catch (const std::exception&) {
    }
  // The machine's other load over the child's whole life (its scene's
  // making too: one thread then, but the rest of the machine is what counts).
  const auto start = std::chrono::steady_clock::now();
  const CpuTimes before = cpu_times();
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.str().c_str(), "r"), pclose);
  if (!pipe) throw std::runtime_error("cannot start " + cmd.str());
  Result r;
  r.engine = engine, r.scene = s.name, r.n = s.dynamic_count(), r.round_trip_ns = round_trip;
  bool got = false;
  char line[512];
  while (std::fgets(line, sizeof line, pipe.get()))
    got = got || std::sscanf(line, "RESULT %lf %lf %lf %d %zu %lf %lf %lf %lf %lf", &r.median_ms, &r.p95_ms,
                             &r.build_ms, &r.steps_run, &r.q.escaped, &r.q.max_overlap, &r.q.energy_drift,
                             &r.q.top_moved, &r.peak_mb, &r.map_mb) == 10;
  if (pclose(pipe.release()) != 0 || !got) throw std::runtime_error("the run failed: " + cmd.str());
  const CpuTimes after = cpu_times();
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.others = others_load(before, after, wall_s);
  if (!std::isnan(r.others)) r.own = (after.children_s - before.children_s) / wall_s;
  return r;
}

int child_run(const Options& o) {
  const auto parts = split(o.child);
  if (parts.size() != 3) throw std::invalid_argument("--child wants ENGINE,SCENE,N");
  const Scene s = make_scene(parts[1], std::stoul(parts[2]));
  const Result r = run(parts[0], s, o);
  rusage use{};
  getrusage(RUSAGE_SELF, &use);
  const double peak_mb = static_cast<double>(use.ru_maxrss) / 1024.0;  // Linux: kB
  std::printf("RESULT %.17g %.17g %.17g %d %zu %.17g %.17g %.17g %.17g %.17g\n", r.median_ms, r.p95_ms, r.build_ms,
              r.steps_run, r.q.escaped, r.q.max_overlap, r.q.energy_drift, r.q.top_moved, peak_mb, r.map_mb);
  return 0;
}

std::string machine_line() {
  std::ifstream in("/proc/cpuinfo");
  std::string line, model = "unknown CPU";
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  std::ostringstream s;
  s << model << ", " << std::thread::hardware_concurrency() << " cores (one used), g++ " << __VERSION__;
  return s.str();
}


const char* usage =
    "usage: bench [--scenes gas,rain,pyramid,pyramid_friction,many_pyramids,tiles] [--sizes 1000,10000,100000]\n"
    "             [--map-sides 200,1000,2000 (the tiles scene's maps, cells a side)]\n"
    "             [--ours-only-gas 1000000 (gas sizes for ours alone; 0: none)] [--engines ours,box2d,chipmunk]\n"
    "             [--two-threads-from 100000 (ours-2t, ours on 2 threads, after ours on the stable solver's\n"
    "             scenes of this many bodies and more, the two --repeats times in turns, and box2d3-2t\n"
    "             after box2d3; 0: never)]\n"
    "             [--peers build/bench-peers (adds box2d3,chipmunk-release)] [--peer-sources TEXT]\n"
    "             [--steps 600] [--warmup 60] [--out bench/RESULTS.md]\n"
    "             [--compare 0|1] [--budget 30 (s per run)] [--phase-budget 150 (s)] [--isolate 0|1]\n"
    "             [--round-trip (only print how long a cache line takes from core 0 to core 1 and back)]\n"
    "             [--child ENGINE,SCENE,N (run that alone, print its RESULT line) [--stages (and, to stderr,\n"
    "             ours' stage times over the median tenth of its steps)]]\n"
    "             [--repeats 3 (runs of ours and box2d3, alternated, on scenes of at most --repeat-below\n"
    "             25000 bodies but the tile maps; each row is the median run)]\n"
    "             (engines also: ours-course, our course solver on every scene; ours-2t, ours on two\n"
    "             threads; box2d3-2t, Box2D v3.2 on two (--peers); scenes also, each run\n"
    "             after the rain at its sizes from 10 000 up: rain_phase, the rain over the same share of\n"
    "             its fall at every size, by ours alone; rain_falling, its first second at every size's\n"
    "             pace; rain_settled, its squares at rest where it lands, loaded by every engine)\n";

std::vector<std::size_t> sizes_of(const std::string& v) {
  std::vector<std::size_t> out;
  for (const auto& x : split(v))
    if (const std::size_t n = std::stoul(x)) out.push_back(n);
  return out;
}

// One option and its value; false if `a` is not one of them.
bool set_option(Options& o, const std::string& a, const std::string& v) {
  if (a == "--scenes") o.scenes = split(v);
  else if (a == "--engines") o.engines = split(v), o.engines_given = true;
  else if (a == "--sizes") o.sizes = sizes_of(v);
  else if (a == "--map-sides") o.map_sides = sizes_of(v);
  else if (a == "--ours-only-gas") o.ours_only_gas = sizes_of(v);
  else if (a == "--two-threads-from") o.two_threads_from = static_cast<std::size_t>(std::stoul(v));
  else if (a == "--repeats") o.repeats = std::stoi(v);
  else if (a == "--repeat-below") o.repeat_below = static_cast<std::size_t>(std::stoul(v));
  else if (a == "--peers") o.peers = v;
  else if (a == "--peer-sources") o.peer_sources = v;
  else if (a == "--steps") o.steps = std::stoi(v);
  else if (a == "--warmup") o.warmup = std::stoi(v);
  else if (a == "--out") o.out = v;
  else if (a == "--compare") o.compare = v != "0";
  else if (a == "--budget") o.budget = std::stod(v);
  else if (a == "--phase-budget") o.phase_budget = std::stod(v);
  else if (a == "--isolate") o.isolate = v != "0";
  else if (a == "--child") o.child = v;
  else return false;
  return true;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::cout << usage;
      std::exit(0);
    }
    if (a == "--list-engines") {
      o.list = true;
      continue;
    }
    if (a == "--round-trip") {
      o.round_trip = true;
      continue;
    }
    if (a == "--stages") {
      o.stages = true;
      continue;
    }
    if (i + 1 >= argc) throw std::invalid_argument("missing value after " + a);
    if (!set_option(o, a, argv[++i])) throw std::invalid_argument("unknown option " + a);
  }
  if (o.steps <= o.warmup || o.warmup < 0) throw std::invalid_argument("--steps must exceed --warmup >= 0");
  if (o.repeats < 1) throw std::invalid_argument("--repeats must be at least 1");
  if (o.stages && o.child.empty()) throw std::invalid_argument("--stages goes with --child ENGINE,SCENE,N");
  // The strongest peers first, right after ours.
  if (!o.peers.empty() && !o.engines_given) o.engines = {"ours", "box2d3", "chipmunk-release", "box2d", "chipmunk"};
  return o;
}

std::string fmt(const char* f, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

// The engines build/bench-peers holds (it prints them with --list-engines).
std::vector<std::string> peer_engines(const std::string& peers) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(("'" + peers + "' --list-engines").c_str(), "r"), pclose);
  std::vector<std::string> names;
  char line[256];
  while (pipe && std::fgets(line, sizeof line, pipe.get())) names.push_back(std::string(line, std::strcspn(line, "\n")));
  if (!pipe || pclose(pipe.release()) != 0) throw std::runtime_error("cannot run " + peers + " --list-engines");
  return names;
}

// Every engine asked for is in this binary or in the peers' one; checked
// before the first run rather than failing half-way.
void check_engines(const Options& o) {
  std::vector<std::string> known = bench::engine_names();
  if (!o.peers.empty())
    for (const auto& name : peer_engines(o.peers)) known.push_back(name);
  for (const std::string& e : o.engines) {
    if (std::find(known.begin(), known.end(), e) != known.end()) continue;
    const bool peer = e == "box2d3" || e == "chipmunk-release";
    throw std::invalid_argument("unknown engine '" + e + "'" +
                                (peer ? ": it is built by `make bench PEERS=DIR` (README, Performance)" : ""));
  }
  if (!o.isolate && !o.peers.empty())
    throw std::invalid_argument("--isolate 0 runs this binary's engines only: leave out --peers");
}

// The tarball among --peer-sources whose name holds `word`, as " from NAME".
std::string source_of(const Options& o, const std::string& word) {
  std::istringstream in(o.peer_sources);
  for (std::string name; in >> name;)
    if (name.find(word) != std::string::npos) return " from " + name;
  return "";
}

// What each engine column is, for RESULTS.md.
std::string engine_note(const std::string& e, const Options& o) {
  if (e == "ours") return "`ours`: this engine (course solver on gas, stable solver on the rest)";
  if (e == "ours-course") return "`ours-course`: this engine with the course solver on every scene";
  if (e == "ours-2t") return "`ours-2t`: this engine on two threads (WorldDef::threads = 2: the same bits as one)";
  if (e == "box2d3")
    return "`box2d3`: Box2D v3.2.0 built from source" + source_of(o, "box2d") +
           " (CMake Release, its defaults otherwise: SSE2, no AVX2; BOX2D_VALIDATE off), one worker thread, its "
           "default 4 substeps, `motionLocks.angularZ`, restitution threshold 0 for e = 1 (its default 1 m/s "
           "otherwise), bench/peers/engine_box2d3.cpp";
  if (e == "box2d3-2t")
    return "`box2d3-2t`: `box2d3` with `workerCount` 2 (v3's own scheduler and threads)";
  if (e == "chipmunk-release")
    return "`chipmunk-release`: Chipmunk 7.0.3 built from source" + source_of(o, "Chipmunk") +
           " with gcc -O2 -DNDEBUG, without cpHastySpace.c (the threaded space), through the same adapter as "
           "`chipmunk` (bench/engine_chipmunk.cpp compiled against it)";
  if (e == "box2d") return "`box2d`: Debian's Box2D 2.4.1 (libbox2d-dev), Step(dt, 8, 3), bench/engine_box2d.cpp";
  if (e == "chipmunk")
    return "`chipmunk`: Debian's Chipmunk 7.0.3 (libchipmunk-dev, built with its debug checks on), "
           "bench/engine_chipmunk.cpp";
  return "`" + e + "`";
}

// The run of median time among an engine's runs (the lower middle of an even count).
Result median_run(std::vector<Result> runs) {
  std::sort(runs.begin(), runs.end(), [](const Result& a, const Result& b) { return a.median_ms < b.median_ms; });
  return runs[(runs.size() - 1) / 2];
}

// The table, printed and in Markdown, the two-thread runs and the growth of our cost.
class Report {
 public:
  explicit Report(const Options& o) : o_(o) {
    table_ << "| engine | scene | N | median ms/step | p95 ms/step | ns/body/step | time ÷ ours | escaped | max overlap "
              "(block) | KE drift (gas) | top block moved (pyramids, m) | peak MB | other load (cores) |\n"
              "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    std::printf("%-22s %-16s %7s %9s %9s %9s %7s %7s %9s %10s %9s %7s %6s\n", "engine", "scene", "N", "median", "p95",
                "ns/body", "÷ours", "escaped", "overlap", "KE drift", "top moved", "peak MB", "others");
  }

  // ours_ms: ours' median on the same scene (0 if ours did not run it).
  void add(const Result& r, double ours_ms, const std::string& label) {
    const double ns_body = r.median_ms * 1e6 / static_cast<double>(r.n);
    const std::string ratio = ours_ms > 0 ? fmt("%.2f", r.median_ms / ours_ms) : "-";
    const std::string drift = r.scene == "gas" ? fmt("%+.2e", r.q.energy_drift) : "-";
    const std::string top = r.scene.find("pyramid") != std::string::npos ? fmt("%.4f", r.q.top_moved) : "-";
    std::printf("%-22s %-16s %7zu %9.3f %9.3f %9.1f %7s %7zu %9.4f %10s %9s %7.0f %6s\n", label.c_str(),
                r.scene.c_str(), r.n, r.median_ms, r.p95_ms, ns_body, ratio.c_str(), r.q.escaped, r.q.max_overlap,
                drift.c_str(), top.c_str(), r.peak_mb, load(r).c_str());
    std::fflush(stdout);
    table_ << "| " << label << " | " << r.scene << " | " << r.n << " | " << fmt("%.3f", r.median_ms) << " | "
           << fmt("%.3f", r.p95_ms) << " | " << fmt("%.1f", ns_body) << " | " << ratio << " | " << r.q.escaped
           << " | " << fmt("%.4f", r.q.max_overlap) << " | " << drift << " | " << top << " | "
           << fmt("%.0f", r.peak_mb) << " | " << load(r) << " |\n";
    results_.push_back(r);
  }

  std::string table() const { return table_.str(); }

  // One engine's runs on one thread and on two of one scene (in turns).
  void add_threads(const std::vector<Result>& one, const std::vector<Result>& two) {
    if (one.empty() || two.empty()) return;
    const auto runs = [](const std::vector<Result>& rs) {
      std::string out;
      for (const Result& r : rs)
        out += (out.empty() ? "" : ", ") + fmt("%.3f", r.median_ms) + " (" + load(r) +
               (std::isnan(r.own) ? "" : " / " + fmt("%.2f", r.own)) +
               (std::isnan(r.round_trip_ns) ? "" : " / " + fmt("%.0f", r.round_trip_ns) + " ns") + ")";
      return out;
    };
    const double base = median_run(one).median_ms, gain = base / median_run(two).median_ms;
    const auto gain_over = [&](auto&& kept) {
      std::vector<Result> runs_kept;
      for (const Result& r : two)
        if (kept(r)) runs_kept.push_back(r);
      return runs_kept.empty() ? std::string("- (none)")
                               : fmt("%.2f×", base / median_run(runs_kept).median_ms) + " (" +
                                     std::to_string(runs_kept.size()) + " of " + std::to_string(two.size()) + ")";
    };
    const std::string gain_free = gain_over([](const Result& r) { return r.others < free_below; });
    const std::string gain_near = gain_over([](const Result& r) { return r.others < free_below && r.round_trip_ns < near_below; });
    threads_ << "| " << two.front().engine << " | " << one.front().scene << " | " << one.front().n << " | " << runs(one)
             << " | " << runs(two) << " | " << fmt("%.2f×", gain) << " | " << gain_free << " | " << gain_near
             << " |\n";
    std::printf("%s %s %zu: two threads %.2fx one (median runs), %s with the second core free\n",
                two.front().engine.c_str(), one.front().scene.c_str(), one.front().n, gain, gain_free.c_str());
  }

  std::string threads() const {
    if (threads_.str().empty()) return "";
    return "## Two threads\n\nEach engine's runs on one thread and on two, in turns, with the machine's other load "
           "during each and the cores the run kept busy itself (*other load / own*: the cores' time spent by other "
           "processes or taken by the hypervisor, then by the run's process, over the run's time, its scene's making "
           "included; other load near 0: the second core was free, near 1: a neighbour held it; - for runs under a "
           "quarter of a second). *gain*: the median one-thread "
           "run's time over the median two-thread run's; *gain, second core free*: the same over the two-thread runs "
           "whose other load stayed under " + fmt("%.2f", free_below) + " core; *and near*: of those, the runs whose "
           "cores handed a cache line back and forth in under " + fmt("%.0f", near_below) + " ns just before (*round "
           "trip*, `build/bench --round-trip`: 90-160 ns on this machine in some hours, 360-410 in others, when "
           "two-thread runs are slow: docs/performance.md, \"Threads\").\n\n"
           "| engine | scene | N | one thread: ms a step (other load / own) | two threads: ms a step (other load / own / "
           "round trip) | gain | gain, second core free | and near |\n|---|---|---:|---|---|---:|---:|---:|\n" +
           threads_.str() + "\n";
  }

  // The tiles scene: per engine and map, the map's heap and the step's cost
  // over the engine's own on the first (smallest) map.
  std::string tiles() const {
    std::ostringstream md;
    std::map<std::string, double> first;  // by engine: its median on the first map
    for (const Result& r : results_) {
      if (!r.scene.starts_with("tiles_")) continue;
      const double base = first.try_emplace(r.engine, r.median_ms).first->second;
      const int side = std::stoi(r.scene.substr(6));
      const std::size_t boxes = bench::map_boxes(bench::make_tiles(side)).size();
      md << "| " << r.engine << " | " << side << " x " << side << " | " << (r.engine.starts_with("ours") ? "tile layer" : std::to_string(boxes) + " boxes")
         << " | " << fmt("%.2f", r.map_mb) << " | " << fmt("%.3f", r.median_ms) << " | " << fmt("%.3f", r.p95_ms)
         << " | " << fmt("%.2f", r.median_ms / base) << " | " << fmt("%.0f", r.peak_mb) << " |\n";
      std::printf("%s %s: map %.2f MB, %.3f ms/step, x%.2f the first map's\n", r.engine.c_str(), r.scene.c_str(), r.map_mb,
                  r.median_ms, r.median_ms / base);
    }
    if (md.str().empty()) return "";
    return "## Tile maps\n\nThe `tiles_SIDE` scenes: the same 10 000 bodies in the same 100 rooms on maps of growing side "
           "(bench/scenes.cpp, make_tiles). *map MB* is the heap the map took when the adapter built it (glibc's "
           "mallinfo2 before and after): ours a tile layer (a byte a cell, its strips and their index), the peers "
           "the map's solid cells as static boxes (each row's runs merged down the rows, bench/scenes.cpp, "
           "map_boxes). *÷ first map* is the engine's median over its own on the first map: 1 when a step's cost "
           "does not grow with the map.\n\n"
           "| engine | map (cells) | map as | map MB | median ms/step | p95 ms/step | ÷ first map | peak MB |\n"
           "|---|---|---|---:|---:|---:|---:|---:|\n" +
           md.str() + "\n";
  }

  // Growth of our cost between consecutive sizes from 10 000 up: exponent of
  // t ~ N^k; beside it Box2D v3.2's over the same sizes where it ran both
  // (the aim's yardstick: what the memory of the machine does to the
  // strongest peer), with its steps where a budget cut its run short (its
  // median then covers another share of the scene's phases).
  std::string growth() const {
    std::ostringstream md;
    std::vector<std::string> names;
    for (const Result& r : results_)
      if (std::find(names.begin(), names.end(), r.scene) == names.end()) names.push_back(r.scene);
    for (const std::string& name : names) {
      std::vector<const Result*> ours;
      for (const Result& r : results_)
        if (r.engine == "ours" && r.scene == name && r.n >= 10000) ours.push_back(&r);
      for (std::size_t i = 0; i + 1 < ours.size(); ++i) {
        const Result &a = *ours[i], &b = *ours[i + 1];
        const double k = exponent(a, b);
        md << "| " << name << " | " << a.n << " → " << b.n << " | " << fmt("%.3f", a.median_ms) << " | "
           << fmt("%.3f", b.median_ms) << " | " << fmt("%.2f", k) << " | " << peer_growth(a, b) << " |\n";
        std::printf("ours %s: cost grows as N^%.2f from %zu to %zu bodies\n", name.c_str(), k, a.n, b.n);
      }
    }
    if (md.str().empty()) return "";
    return "## Growth of our cost with N\n\n| scene | N | ms/step at the first | ms/step at the second | exponent k "
           "(t ∝ N^k) | Box2D v3.2's k |\n|---|---|---:|---:|---:|---:|\n" +
           md.str() + "\n";
  }

 private:
  static double exponent(const Result& a, const Result& b) {
    return std::log(b.median_ms / a.median_ms) / std::log(double(b.n) / double(a.n));
  }
  // Box2D v3.2's exponent over ours' two runs' sizes, "-" where it ran one of them not.
  std::string peer_growth(const Result& ours_a, const Result& ours_b) const {
    const auto find = [&](const Result& o) -> const Result* {
      for (const Result& r : results_)
        if (r.engine == "box2d3" && r.scene == o.scene && r.n == o.n) return &r;
      return nullptr;
    };
    const Result *a = find(ours_a), *b = find(ours_b);
    if (!a || !b) return "-";
    std::string cut;
    for (const auto& [peer, ours] : {std::pair{a, &ours_a}, std::pair{b, &ours_b}})
      if (peer->steps_run < ours->steps_run)
        cut += (cut.empty() ? " (" : ", ") + std::to_string(peer->steps_run) + " of " + std::to_string(ours->steps_run) +
               " steps at " + std::to_string(peer->n);
    return fmt("%.2f", exponent(*a, *b)) + (cut.empty() ? "" : cut + ")");
  }

  static constexpr double free_below = 0.25;  // a two-thread run had the second core: others' load under this
  static constexpr double near_below = 200;   // ... and its cores were near: their round trip under this, in ns
  static std::string load(const Result& r) { return std::isnan(r.others) ? "-" : fmt("%.2f", r.others); }
  const Options& o_;
  std::ostringstream table_, threads_;
  std::vector<Result> results_;
};

// A row's engine, with how its run differed from the plan.
std::string label_of(const std::string& engine, const Result& r, const Scene& s, bool alone, const Options& o) {
  // A run cut short by the budget says how far it got; one run alone says why.
  std::string label = engine;
  if (r.steps_run < std::lround(planned_steps(s, o))) label += " (" + std::to_string(r.steps_run) + " steps)";
  if (s.name == "rain_phase") label += " (alone, steps x" + fmt("%.2f", s.time_scale) + ")";
  else if (s.time_scale != 1.0) label += " (steps x" + fmt("%.2f", s.time_scale) + ")";
  else if (alone) label += " (alone: peers over budget)";
  return label;
}

// One engine's run of a scene (each in a fresh process unless --isolate 0).
Result run_one(const std::string& self, const std::string& engine, const Scene& s, const Options& o) {
  return o.isolate ? run_isolated(self, engine, s, o) : run(engine, s, o);
}

// Whether ours and Box2D v3.2 run on two threads too on scene s (Options::two_threads_from).
bool two_threads(const Scene& s, const Options& o) {
  return o.two_threads_from > 0 && s.resting && s.dynamic_count() >= o.two_threads_from;
}

// How many runs an engine gets on a scene (Options::repeats).
int runs_of(const std::string& engine, const Scene& s, bool alone, const Options& o) {
  const bool repeated = !alone && !s.name.starts_with("tiles_") && s.dynamic_count() <= o.repeat_below;
  const bool paired = two_threads(s, o) && (engine == "ours" || engine == "ours-2t");
  return (repeated && (engine == "ours" || engine == "box2d3")) || paired ? o.repeats : 1;
}

// One scene at one size, every engine (ours alone if `alone`), ours and
// Box2D v3.2 in turns where they run several times (runs_of); ours and
// Box2D v3.2 on two threads too (ours-2t, box2d3-2t) on the stable solver's
// scenes from two_threads_from bodies up, each right after its one-thread run.
void run_scene(const std::string& self, const Scene& s, bool alone, const Options& o, Report& report) {
  std::vector<std::string> order;  // the rows' engines, in the table's order
  for (const std::string& engine : o.engines) {
    if (alone && engine != "ours") continue;
    order.push_back(engine);
    const bool two = two_threads(s, o);
    const std::string twin = engine + "-2t";  // ours-2t after ours, box2d3-2t after box2d3
    if ((engine == "ours" || engine == "box2d3") && two &&
        std::find(o.engines.begin(), o.engines.end(), twin) == o.engines.end())
      order.push_back(twin);
  }
  std::map<std::string, std::vector<Result>> runs;
  for (int round = 0;; ++round) {
    bool ran = false;
    for (const std::string& engine : order)
      if (round < runs_of(engine, s, alone, o)) runs[engine].push_back(run_one(self, engine, s, o)), ran = true;
    if (!ran) break;
  }
  const double ours_ms = runs.count("ours") ? median_run(runs["ours"]).median_ms : 0.0;
  for (const std::string& engine : order) {
    const Result r = median_run(runs[engine]);
    std::string label = label_of(engine, r, s, alone, o);
    if (runs[engine].size() > 1) label += " (median of " + std::to_string(runs[engine].size()) + ")";
    report.add(r, ours_ms, label);
  }
  for (const std::string engine : {"ours", "box2d3"})
    if (runs.count(engine) && runs.count(engine + "-2t")) report.add_threads(runs[engine], runs[engine + "-2t"]);
}

void run_all(const std::string& self, const Options& o, Report& report) {
  for (const std::string& name : o.scenes) {
    if (name == "tiles") {
      for (const std::size_t side : o.map_sides) run_scene(self, make_scene("tiles_" + std::to_string(side), 0), false, o, report);
      continue;
    }
    const std::vector<std::size_t> sizes = sized(name) ? o.sizes : std::vector<std::size_t>{0};
    for (const std::size_t n : sizes) run_scene(self, make_scene(name, n), false, o, report);
    if (name == "gas")
      for (const std::size_t n : o.ours_only_gas) run_scene(self, make_scene(name, n), true, o, report);
    // Ours alone: the peers' 100 000-body rain would take minutes over 1068 steps.
    // The rain's phases apart, from 10 000 bodies up: falling and settled, every engine.
    if (name == "rain")
      for (const char* phase : {"rain_phase", "rain_falling", "rain_settled"})
        for (const std::size_t n : sizes)
          if (n >= 10000) run_scene(self, make_scene(phase, n), phase == std::string("rain_phase"), o, report);
  }
}

std::string title(const Options& o) {
  std::string t = "# Benchmark: our engine";
  for (const std::string& e : o.engines)
    if (e != "ours") t += ", `" + e + "`";
  return t;
}

void write_markdown(const Options& o, const std::string& command, const std::string& machine, const Report& report,
                    const std::string& broadphase) {
  std::ofstream md(o.out);
  if (!md) throw std::runtime_error("cannot write " + o.out);
  md << title(o) << "\n\n"
     << "Written by `make bench` (`" << command << "`); do not edit by hand.\n\n"
     << "Machine: " << machine << ". Steps: " << o.steps << ", the first " << o.warmup
     << " discarded; times are per step, single thread (but ours-2t and box2d3-2t), each run in a fresh process. "
     << (o.repeats > 1 ? "On the scenes of at most " + std::to_string(o.repeat_below) + " bodies (the tile maps but), ours "
                         "and box2d3 run " + std::to_string(o.repeats) + " times, in turns, and their rows are their "
                         "median runs (a fresh process runs fast or slow as the machine places it). " : "")
     << "A run that passes " << o.budget
     << " s stops early: its row says after how many steps (its statistics then cover the steps past the warm-up, "
        "or all of them if it did not get that far; its quality is the state where it stopped).\n\n"
     << "Engines:\n\n";
  for (const std::string& e : o.engines) md << "- " << engine_note(e, o) << ".\n";
  if (o.two_threads_from > 0 && std::find(o.engines.begin(), o.engines.end(), "ours-2t") == o.engines.end())
    md << "- " << engine_note("ours-2t", o) << ", run after `ours` on the stable solver's scenes of "
       << o.two_threads_from << " bodies and more (the two " << o.repeats << " times there, in turns, each row "
       << "the median run); its ÷ours is its time over ours on one thread.\n";
  if (o.two_threads_from > 0 && std::find(o.engines.begin(), o.engines.end(), "box2d3") != o.engines.end() &&
      std::find(o.engines.begin(), o.engines.end(), "box2d3-2t") == o.engines.end())
    md << "- " << engine_note("box2d3-2t", o) << ", run after `box2d3` on the same scenes; its ÷ours is its time "
       << "over ours on one thread.\n";
  md << "\nScenes (bench/scenes.cpp): unit squares of mass 1, fixed rotation, friction 0 (but in pyramid_friction), "
        "sleeping off, each engine's default iterations; 1 m = 10 px in our engine. `gas`: area fraction 0.10, "
        "random velocities up to 5 m/s per axis (seed 42), no gravity, e = 1, our course solver. `rain`: a grid at "
        "area fraction 0.25 falls under 10 m/s² into a walled box, e = 0.5, our stable solver. `pyramid`: Box2D's "
        "large_pyramid (base 100, 5050 blocks), e = 0, our stable solver; `pyramid_friction`: the same with "
        "friction 0.6 on every body and wall (Box2D's and our mixing rule, sqrt(mu_a mu_b), give the pair 0.6; "
        "Chipmunk multiplies, so it gets sqrt(0.6) per shape). `many_pyramids`: Box2D v3's benchmark of that name "
        "(shared/benchmarks.c, CreateManyPyramids): 20 shelves 11 m apart, each 220 m long holding 20 pyramids of "
        "base 10, 22 000 blocks, e = 0, our stable solver; Box2D's shelves are segments, here fixed boxes 0.5 m "
        "thick under the same lines (the floor is the first). ";
  md << "`rain_phase`: the same rain, run by ours alone from 10 000 bodies up, its steps and warm-up scaled by "
        "the square root of its container's side over the 10 000-body one's (the time its grid takes to fall): "
        "each size is timed over the same share of its fall, landing and settling, where the rain's steps 61-600 "
        "catch a 10 000-body pile settled and a 100 000-body one landing (bench/main.cpp, make_rain_phase). ";
  md << "`rain_falling`: the rain's first 65 steps, the first 5 left out, scaled as rain_phase's: the grid falls "
        "and its lowest rows land (bench/main.cpp, make_rain_falling). `rain_settled`: the rain's squares at rest "
        "where it lands, loaded by every engine: rows wall to wall from the floor up, each square on the one below, "
        "no velocity (bench/scenes.cpp, make_rain_settled; a frictionless pile run to rest would keep flowing for "
        "thousands of steps). ";
  md << "`tiles_SIDE`: a map of SIDE x SIDE cells of 1 m, rooms of 20 x 20 cells walled by solid cells (two thick "
        "between rooms, 18 x 18 inside, a ledge of 8 cells in each), 10 000 squares in the 100 rooms of its "
        "top-left corner fall under 10 m/s², e = 0.5, our stable solver: the same bodies on every map (section "
        "\"Tile maps\"); ours gets the map as one tile layer, the peers (no tile layers) as static boxes, each row's "
        "runs of solid cells merged down the rows into one box. ";
  if (!o.ours_only_gas.empty())
    md << "`gas` at " << o.ours_only_gas.front()
       << " bodies is run by ours alone: the peers' 100 000-body runs already take a large part of the budget, "
          "so ten times as many bodies would only be cut short. ";
  md << "Engine settings: bench/engine_*.cpp, bench/peers/engine_*.cpp.\n\n"
     << "Columns: *time ÷ ours* is the engine's median over ours (above 1: ours is faster); *escaped* counts "
        "bodies whose centre left the box; *max overlap* is the deepest overlap of two boxes, or of a box into a "
        "wall, at the last step, in block sides; *KE drift* is (E_end − E_start)/E_start; *top block moved* is the "
        "largest displacement of a pyramid's top block over the run; *peak MB* is the run's process's peak "
        "resident memory (the scene's description included); *other load* is how many cores the rest of the machine "
        "kept busy during the run (/proc/stat less the run's own time, over its process's life; a two-thread run "
        "with 1 here had one core; - for runs under a quarter of a second).\n\n"
     << report.table() << "\n"
     << report.threads() << report.growth() << report.tiles() << broadphase;
}

}  // namespace

int main(int argc, char** argv) try {
  const Options o = parse(argc, argv);
  if (o.list) {
    for (const std::string& e : bench::engine_names()) std::cout << e << "\n";
    return 0;
  }
  if (o.round_trip) {
    std::cout << "cores 0 and 1: a cache line's round trip " << fmt("%.0f", bench::core_round_trip_ns()) << " ns\n";
    return 0;
  }
  if (!o.child.empty()) return child_run(o);
  check_engines(o);
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  std::string command = "build/bench";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    command += a.find(' ') == std::string::npos ? " " + a : " \"" + a + "\"";
  }
  const std::string machine = machine_line();
  std::cout << "machine: " << machine << "\n";
  Report report(o);
  run_all(self, o, report);
  // Grid against sort-and-sweep, fed the same boxes.
  const std::string broadphase = o.compare ? bench::compare_broadphases(o.sizes) : "";
  std::cout << broadphase;
  write_markdown(o, command, machine, report, broadphase);
  std::cout << "wrote " << o.out << "\n";
  return 0;
} catch (const std::exception& e) {
  std::cerr << "bench: " << e.what() << "\n";
  return 2;
}
