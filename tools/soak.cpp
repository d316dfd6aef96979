// make soak: the gas scene and the stack scene (course and stable solvers) for 10^6 steps each, headless, checked
// every 10^4 steps (see src/soak.hpp). Prints one summary line per scene and
// exits non-zero if a check fails.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "scene/builtin_scenes.hpp"
#include "app/soak.hpp"

using namespace physics;

int main(int argc, char** argv) {
  const std::int64_t steps = argc > 1 ? std::atoll(argv[1]) : 1'000'000;
  if (steps <= 0) {
    std::fprintf(stderr, "soak: steps must be > 0\n");
    return 2;
  }
  int failures = 0;
  struct Run {
    const char* name;
    Solver solver;
  };
  for (const Run run : {Run{"gas", Solver::course}, Run{"stack", Solver::course}, Run{"stack", Solver::stable}}) {
    const char* name = run.name;
    SceneSpec spec = *find_builtin(name);
    spec.params.solver = run.solver;
    World w = make_world(spec, false, name);
    const SoakLimits limits = soak_limits(spec, w);
    const auto t0 = std::chrono::steady_clock::now();
    const SoakResult r = soak(w, steps, 10'000, limits);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("soak %-5s %-6s %s: %lld steps, %lld checks, %zu bodies, energy start %.9g reference %.9g min %.9g max %.9g "
                "(bound %s%.3g), max wall overlap %.3g px, %.1f s%s%s\n",
                name, run.solver == Solver::stable ? "stable" : "course", r.ok ? "ok" : "FAILED", static_cast<long long>(r.steps), static_cast<long long>(r.checks),
                w.components.size(), r.energy_start, r.energy_reference, r.energy_min, r.energy_max,
                limits.energy_conserved ? "±" : "+", limits.energy_slack, r.max_wall_depth, s, r.ok ? "" : ": ",
                r.failure.c_str());
    failures += r.ok ? 0 : 1;
  }
  return failures == 0 ? 0 : 1;
}
