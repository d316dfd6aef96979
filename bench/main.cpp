// `make bench`: our engine, Box2D 2.4.1 and Chipmunk 7 on the same scenes, in
// one run, on this machine. Prints a table and writes bench/RESULTS.md.
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
#include <thread>
#include <vector>

#include "bench.hpp"
#include "broadphase_compare.hpp"

namespace {

using bench::Body;
using bench::Scene;

struct Options {
  std::vector<std::string> scenes{"gas", "rain", "pyramid", "pyramid_friction"};
  std::vector<std::size_t> sizes{1000, 10000, 100000};
  std::vector<std::string> engines{"ours", "box2d", "chipmunk"};
  int steps = 600, warmup = 60;
  double budget = 40.0;  // s per run: a run past it stops early (and says so)
  std::string out = "bench/RESULTS.md";
  bool compare = true;  // the broadphase comparison
  bool isolate = true;  // each run in a fresh process (see run_isolated)
  std::string child;    // internal: "ENGINE,SCENE,N": run only that and print its RESULT line
};

struct Quality {
  std::size_t escaped = 0;   // dynamic bodies whose centre left the container (or is not finite)
  double max_overlap = 0;    // deepest overlap of two boxes (or a box into a wall), block sides
  double energy_drift = 0;   // (KE_end - KE_start) / KE_start
  double top_moved = 0;      // pyramid: the top block's displacement, m
};

struct Result {
  std::string engine, scene;
  std::size_t n = 0;
  double median_ms = 0, p95_ms = 0, build_ms = 0;
  int steps_run = 0;  // fewer than asked when the run hit the time budget
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

Quality measure(const Scene& s, const std::vector<Body>& end) {
  Quality q;
  std::vector<std::size_t> dyn, fixed;
  for (std::size_t i = 0; i < end.size(); ++i) (end[i].fixed ? fixed : dyn).push_back(i);
  for (const std::size_t i : dyn) {
    const Body& b = end[i];
    const bool inside = std::isfinite(b.cx) && std::isfinite(b.cy) && b.cx >= 0 && b.cx <= s.width && b.cy >= 0 &&
                        b.cy <= s.height;
    if (!inside) ++q.escaped;
    for (const std::size_t f : fixed) q.max_overlap = std::max(q.max_overlap, depth(b, end[f]));
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

std::unique_ptr<bench::Engine> make_engine(const std::string& engine, const Scene& s) {
  if (engine == "ours") return bench::make_ours(s);
  if (engine == "ours-course") return bench::make_ours(s, true);
  if (engine == "box2d") return bench::make_box2d(s);
  if (engine == "chipmunk") return bench::make_chipmunk(s);
  throw std::invalid_argument("unknown engine '" + engine + "' (ours, ours-course, box2d, chipmunk)");
}

Scene make_scene(const std::string& name, std::size_t n) {
  if (name == "gas") return bench::make_gas(n);
  if (name == "rain") return bench::make_rain(n);
  if (name == "pyramid") return bench::make_pyramid();
  if (name == "pyramid_friction") return bench::make_pyramid_friction();
  throw std::invalid_argument("unknown scene '" + name + "' (gas, rain, pyramid, pyramid_friction)");
}

double percentile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  const std::size_t k = static_cast<std::size_t>(std::ceil(p * static_cast<double>(v.size()))) - 1;
  return v[std::min(k, v.size() - 1)];
}

Result run(const std::string& engine, const Scene& s, const Options& o) {
  using clock = std::chrono::steady_clock;
  Result r;
  r.engine = engine, r.scene = s.name, r.n = s.dynamic_count();
  const auto t0 = clock::now();
  auto e = make_engine(engine, s);
  r.build_ms = std::chrono::duration<double, std::milli>(clock::now() - t0).count();
  // Every step's time; the first `warmup` are left out of the statistics
  // unless the budget stopped the run before it got past them.
  std::vector<double> times;
  times.reserve(static_cast<std::size_t>(o.steps));
  const auto start = clock::now();
  for (int i = 0; i < o.steps; ++i) {
    const auto a = clock::now();
    e->step();
    const auto b = clock::now();
    times.push_back(std::chrono::duration<double, std::milli>(b - a).count());
    r.steps_run = i + 1;
    if (std::chrono::duration<double>(b - start).count() > o.budget) break;
  }
  if (static_cast<int>(times.size()) > o.warmup) times.erase(times.begin(), times.begin() + o.warmup);
  r.median_ms = percentile(times, 0.5);
  r.p95_ms = percentile(times, 0.95);
  std::vector<Body> end;
  e->read(end);
  r.q = measure(s, end);
  const double e0 = kinetic_energy(s.bodies);
  if (s.name == "gas" && e0 > 0) r.q.energy_drift = (kinetic_energy(end) - e0) / e0;
  if (s.name.starts_with("pyramid")) {
    const Body &a = s.bodies.back(), &b = end.back();
    r.q.top_moved = std::hypot(b.cx - a.cx, b.cy - a.cy);
  }
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
Result run_isolated(const std::string& self, const std::string& engine, const Scene& s, const Options& o) {
  std::ostringstream cmd;
  cmd << "'" << self << "' --child " << engine << "," << s.name << "," << s.dynamic_count() << " --steps " << o.steps
      << " --warmup " << o.warmup << " --budget " << o.budget;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.str().c_str(), "r"), pclose);
  if (!pipe) throw std::runtime_error("cannot start " + cmd.str());
  Result r;
  r.engine = engine, r.scene = s.name, r.n = s.dynamic_count();
  bool got = false;
  char line[512];
  while (std::fgets(line, sizeof line, pipe.get()))
    got = got || std::sscanf(line, "RESULT %lf %lf %lf %d %zu %lf %lf %lf", &r.median_ms, &r.p95_ms, &r.build_ms,
                             &r.steps_run, &r.q.escaped, &r.q.max_overlap, &r.q.energy_drift, &r.q.top_moved) == 8;
  if (pclose(pipe.release()) != 0 || !got) throw std::runtime_error("the run failed: " + cmd.str());
  return r;
}

int child_run(const Options& o) {
  const auto parts = split(o.child);
  if (parts.size() != 3) throw std::invalid_argument("--child wants ENGINE,SCENE,N");
  const Scene s = make_scene(parts[1], std::stoul(parts[2]));
  const Result r = run(parts[0], s, o);
  std::printf("RESULT %.17g %.17g %.17g %d %zu %.17g %.17g %.17g\n", r.median_ms, r.p95_ms, r.build_ms, r.steps_run,
              r.q.escaped, r.q.max_overlap, r.q.energy_drift, r.q.top_moved);
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
    "usage: bench [--scenes gas,rain,pyramid,pyramid_friction] [--sizes 1000,10000,100000] [--engines ours,box2d,chipmunk]\n"
    "             [--steps 600] [--warmup 60] [--out bench/RESULTS.md]\n"
    "             [--compare 0|1] [--budget 40 (s per run)] [--isolate 0|1]   (engines also: ours-course, our course solver on every scene)\n";

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::cout << usage;
      std::exit(0);
    }
    if (i + 1 >= argc) throw std::invalid_argument("missing value after " + a);
    const std::string v = argv[++i];
    if (a == "--scenes") o.scenes = split(v);
    else if (a == "--engines") o.engines = split(v);
    else if (a == "--sizes") {
      o.sizes.clear();
      for (const auto& x : split(v)) o.sizes.push_back(std::stoul(x));
    } else if (a == "--steps") o.steps = std::stoi(v);
    else if (a == "--warmup") o.warmup = std::stoi(v);
    else if (a == "--out") o.out = v;
    else if (a == "--compare") o.compare = v != "0";
    else if (a == "--budget") o.budget = std::stod(v);
    else if (a == "--isolate") o.isolate = v != "0";
    else if (a == "--child") o.child = v;
    else throw std::invalid_argument("unknown option " + a);
  }
  if (o.steps <= o.warmup || o.warmup < 0) throw std::invalid_argument("--steps must exceed --warmup >= 0");
  return o;
}

std::string fmt(const char* f, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

}  // namespace

int main(int argc, char** argv) try {
  const Options o = parse(argc, argv);
  if (!o.child.empty()) return child_run(o);
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  std::string command = "build/bench";
  for (int i = 1; i < argc; ++i) command += std::string(" ") + argv[i];
  const std::string machine = machine_line();
  std::cout << "machine: " << machine << "\n";
  std::vector<Result> results;
  std::ostringstream table;
  table << "| engine | scene | N | median ms/step | p95 ms/step | ns/body/step | time ÷ ours | escaped | max overlap "
           "(block) | KE drift (gas) | top block moved (pyramid, m) |\n"
           "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  std::printf("%-18s %-16s %7s %9s %9s %9s %7s %7s %9s %10s %9s\n", "engine", "scene", "N", "median", "p95", "ns/body",
              "÷ours", "escaped", "overlap", "KE drift", "top moved");
  for (const std::string& name : o.scenes) {
    std::vector<std::size_t> sizes = o.sizes;
    if (name.starts_with("pyramid")) sizes = {5050};
    for (const std::size_t n : sizes) {
      const Scene s = make_scene(name, n);
      double ours_ms = 0;
      for (const std::string& engine : o.engines) {
        const Result r = o.isolate ? run_isolated(self, engine, s, o) : run(engine, s, o);
        if (engine == "ours") ours_ms = r.median_ms;
        const double ns_body = r.median_ms * 1e6 / static_cast<double>(r.n);
        const std::string ratio = ours_ms > 0 ? fmt("%.2f", r.median_ms / ours_ms) : "-";
        const std::string drift = name == "gas" ? fmt("%+.2e", r.q.energy_drift) : "-";
        const std::string top = name.starts_with("pyramid") ? fmt("%.4f", r.q.top_moved) : "-";
        // A run cut short by the budget says how far it got.
        const std::string label =
            r.steps_run < o.steps ? engine + " (" + std::to_string(r.steps_run) + " steps)" : engine;
        std::printf("%-18s %-16s %7zu %9.3f %9.3f %9.1f %7s %7zu %9.4f %10s %9s\n", label.c_str(), name.c_str(), r.n,
                    r.median_ms, r.p95_ms, ns_body, ratio.c_str(), r.q.escaped, r.q.max_overlap, drift.c_str(),
                    top.c_str());
        std::fflush(stdout);
        table << "| " << label << " | " << name << " | " << r.n << " | " << fmt("%.3f", r.median_ms) << " | "
              << fmt("%.3f", r.p95_ms) << " | " << fmt("%.1f", ns_body) << " | " << ratio << " | " << r.q.escaped
              << " | " << fmt("%.4f", r.q.max_overlap) << " | " << drift << " | " << top << " |\n";
        results.push_back(r);
      }
    }
  }

  // Growth of our cost from 10 000 to 100 000 bodies: exponent of t ~ N^k.
  std::ostringstream growth;
  for (const std::string& name : o.scenes) {
    auto find = [&](std::size_t n) -> const Result* {
      for (const Result& r : results)
        if (r.engine == "ours" && r.scene == name && r.n == n) return &r;
      return nullptr;
    };
    const Result *a = find(10000), *b = find(100000);
    if (a && b) {
      const double k = std::log(b->median_ms / a->median_ms) / std::log(10.0);
      growth << "| " << name << " | " << fmt("%.3f", a->median_ms) << " | " << fmt("%.3f", b->median_ms) << " | "
             << fmt("%.2f", k) << " |\n";
      std::printf("ours %s: cost grows as N^%.2f from 10 000 to 100 000 bodies\n", name.c_str(), k);
    }
  }

  // Grid against sort-and-sweep, fed the same boxes.
  const std::string broadphase = o.compare ? bench::compare_broadphases(o.sizes) : "";
  std::cout << broadphase;

  std::ofstream md(o.out);
  if (!md) throw std::runtime_error("cannot write " + o.out);
  md << "# Benchmark: our engine, Box2D 2.4.1, Chipmunk 7.0.3\n\n"
     << "Written by `make bench` (`" << command << "`); do not edit by hand.\n\n"
     << "Machine: " << machine << ". Steps: " << o.steps << ", the first " << o.warmup
     << " discarded; times are per step, single thread, each run in a fresh process. A run that passes " << o.budget
     << " s stops early: its row says after how many steps (its statistics then cover the steps past the warm-up, "
        "or all of them if it did not get that far; its quality is the state where it stopped).\n\n"
     << "Scenes (bench/scenes.cpp): unit squares of mass 1, fixed rotation, friction 0 (but in pyramid_friction), sleeping off, each "
        "engine's default iterations; 1 m = 10 px in our engine. `gas`: area fraction 0.10, random velocities up "
        "to 5 m/s per axis (seed 42), no gravity, e = 1, our course solver. `rain`: a grid at area fraction 0.25 "
        "falls under 10 m/s² into a walled box, e = 0.5, our stable solver. `pyramid`: Box2D's large_pyramid "
        "(base 100, 5050 blocks), e = 0, our stable solver; `pyramid_friction`: the same with friction 0.6 on every "
        "body and wall (Box2D's and our mixing rule, sqrt(mu_a mu_b), give the pair 0.6; Chipmunk multiplies, so "
        "it gets sqrt(0.6) per shape). Engine settings: bench/engine_*.cpp.\n\n"
     << "Columns: *time ÷ ours* is the engine's median over ours (above 1: ours is faster); *escaped* counts "
        "bodies whose centre left the box; *max overlap* is the deepest overlap of two boxes, or of a box into a "
        "wall, at the last step, in block sides; *KE drift* is (E_end − E_start)/E_start; *top block moved* is the "
        "pyramid's top block's displacement over the run.\n\n"
     << table.str() << "\n";
  if (!growth.str().empty())
    md << "## Growth from 10 000 to 100 000 bodies (ours)\n\n| scene | ms/step at 10 000 | ms/step at 100 000 | "
          "exponent k (t ∝ N^k) |\n|---|---:|---:|---:|\n"
       << growth.str() << "\n";
  md << broadphase;
  std::cout << "wrote " << o.out << "\n";
  return 0;
} catch (const std::exception& e) {
  std::cerr << "bench: " << e.what() << "\n";
  return 2;
}
