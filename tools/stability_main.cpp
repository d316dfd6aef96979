// make stability: the matrix of stiff and extreme cases and the generated
// family (report/STABILITY.md): build/stability [OUT.md [--quick]].
// build/stability --family NAME|all [--seed S] [--mode M]: a family's draws
// replayed and printed; --family-expected: the test subset's failing draws,
// as failing_today() (tools/numerics/family.cpp) lists them.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "numerics/family.hpp"
#include "numerics/stability.hpp"

using namespace physics::numerics;

namespace {

struct Cell {
  Outcome outcome;
  double seconds = 0;  // the run's wall time: the fastest of a few runs when a run is short
};

// One run of a case in a mode, with its wall time.
Cell timed(const StabilityCase& c, const Mode& m) {
  const auto t0 = std::chrono::steady_clock::now();
  Cell cell{c.run(m)};
  cell.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return cell;
}

// A short case is run again until 0.2 s have passed (at most 25 runs) and
// its fastest run kept: single runs of a few microseconds are mostly noise.
Cell run_cell(const StabilityCase& c, const Mode& m) {
  Cell cell = timed(c, m);
  double total = cell.seconds;
  for (int run = 1; run < 25 && total < 0.2; ++run) {
    const double s = timed(c, m).seconds;
    cell.seconds = std::min(cell.seconds, s);
    total += s;
  }
  return cell;
}

std::string ms(double seconds) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g ms", seconds * 1e3);
  return buf;
}

// The auto cell's cost beside its figure, against the mode the cost rule
// names: the course where it passes, else the cheapest other mode that
// passes. The two are timed again in turn (auto, the other, auto, ...: up
// to 15 pairs or 0.5 s) and the fastest run of each kept, so that a slow
// stretch of this shared machine falls on both alike.
std::string auto_cost(const StabilityCase& c, const std::vector<Mode>& modes, const std::vector<Cell>& row) {
  const std::size_t none = modes.size();
  std::size_t self = none, ref = none;
  for (std::size_t i = 0; i < modes.size(); ++i) {
    if (modes[i].name == "auto") self = i;
    else if (modes[i].name == "course" && row[i].outcome.pass) ref = i;
  }
  for (std::size_t i = 0; i < modes.size() && (ref == none || modes[ref].name != "course"); ++i)
    if (i != self && row[i].outcome.pass && (ref == none || row[i].seconds < row[ref].seconds)) ref = i;
  if (ref == none) return "; cost " + ms(row[self].seconds) + " (no other mode passes)";
  double mine = row[self].seconds, theirs = row[ref].seconds, total = 0;
  for (int pair = 0; pair < 15 && total < 0.5; ++pair) {
    const double a = timed(c, modes[self]).seconds, b = timed(c, modes[ref]).seconds;
    mine = std::min(mine, a), theirs = std::min(theirs, b), total += a + b;
  }
  char buf[96];
  std::snprintf(buf, sizeof buf, " = %.2fx %s", mine / theirs, modes[ref].name.c_str());
  return "; cost " + ms(mine) + buf;
}

// ---- the generated family (numerics/family.hpp) ----

struct DrawResult {
  std::uint64_t seed = 0;
  std::string params;
  std::vector<Outcome> outcomes;  // by mode
};

// Seeds first..last of a family in every mode.
std::vector<DrawResult> run_family(const Family& f, const std::vector<Mode>& modes, std::uint64_t first,
                                   std::uint64_t last) {
  std::vector<DrawResult> out;
  for (std::uint64_t seed = first; seed <= last; ++seed) {
    const Draw d = f.draw(seed);
    DrawResult r{seed, d.params, {}};
    for (const Mode& m : modes) r.outcomes.push_back(d.run(m));
    out.push_back(std::move(r));
  }
  return out;
}

std::string replay_command(const Family& f, std::uint64_t seed) {
  return "`build/stability --family " + f.name + " --seed " + std::to_string(seed) + "`";
}

std::string percent(int pass, int total) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%d/%d (%.0f %%)", pass, total, total ? 100.0 * pass / total : 0.0);
  return buf;
}

// The section of report/STABILITY.md: pass rates per family and mode, then every failing draw.
void family_section(std::ostream& md, const std::vector<Mode>& modes) {
  std::vector<int> all_pass(modes.size(), 0);
  int draws = 0;
  std::string table, failures;
  for (const Family& f : families()) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto results = run_family(f, modes, 1, family_draws);
    std::vector<int> pass(modes.size(), 0);
    std::string listed;
    int failing = 0;
    for (const DrawResult& r : results) {
      std::string failed;
      for (std::size_t i = 0; i < modes.size(); ++i) {
        if (r.outcomes[i].pass) ++pass[i];
        else failed += (failed.empty() ? "" : "; ") + modes[i].name + ": " + r.outcomes[i].figure;
      }
      if (failed.empty()) continue;
      ++failing;
      listed += "- seed " + std::to_string(r.seed) + " (" + r.params + "): " + failed + ". Replay: " +
                replay_command(f, r.seed) + "\n";
    }
    failures += "\n#### " + f.name + ": " + std::to_string(failing) + " of " + std::to_string(family_draws) +
                " draws fail in some mode\n\n" + listed;
    table += "| " + f.name + " | " + f.ranges + " | " + f.invariant + " |";
    for (std::size_t i = 0; i < modes.size(); ++i) {
      table += " " + percent(pass[i], family_draws) + " |";
      all_pass[i] += pass[i];
    }
    table += "\n";
    draws += family_draws;
    std::cout << "family " << f.name << ": "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s" << std::endl;
  }
  md << "\n## The generated family\n\nScenes drawn from parameter ranges (`tools/numerics/family.cpp`), not a fixed "
        "list: " << families().size() << " families, seeds 1-" << family_draws << " each (" << draws
     << " draws, each run in every mode), each checked against an invariant from physics. A draw is reproducible "
        "from (family, seed): `build/stability --family NAME --seed S` replays it in every mode (`--mode M`: one). "
        "A CCD run fails, as in the matrix, when more than 1 % of its substeps ran out of impact budget (time lost); "
        "it stops there, its verdict decided, and its figures are those of the frames run until then. "
        "`tests/test_family.cpp` runs seeds 1-" << test_draws << " of every family in `make test`, against the "
        "list of the draws that fail today (`family_expected_to_fail`).\n\n| family | drawn | invariant |";
  for (const Mode& m : modes) md << " " << m.name << " |";
  md << "\n|---|---|---|";
  for (std::size_t i = 0; i < modes.size(); ++i) md << "---|";
  md << "\n" << table << "| **all** | | |";
  for (std::size_t i = 0; i < modes.size(); ++i) md << " **" << percent(all_pass[i], draws) << "** |";
  md << "\n\n### Failing draws\n\nEach with the parameters drawn and the figure of every mode it fails in.\n" << failures;
}

// --family NAME [--seed S] [--mode M]: the draws replayed (every seed of make stability without --seed;
// NAME "all": every family), printed. --family-expected: the test subset's failing draws, as
// family_expected_to_fail lists them.
int family_replay(const std::vector<std::string_view>& args, std::vector<Mode> modes) {
  std::string name, mode;
  std::uint64_t first = 1, last = family_draws;
  bool expected = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const auto value = [&]() -> std::string {
      if (i + 1 >= args.size()) throw std::invalid_argument(std::string(args[i]) + " needs a value");
      return std::string(args[++i]);
    };
    if (args[i] == "--family") name = value();
    else if (args[i] == "--mode") mode = value();
    else if (args[i] == "--family-expected") expected = true, last = test_draws;
    else if (args[i] == "--seed") {
      const std::string v = value();
      if (v.empty() || v.size() > 19 || v.find_first_not_of("0123456789") != std::string::npos)
        throw std::invalid_argument("--seed: not a seed (0 to 10^19 - 1): '" + v + "'");
      first = last = std::stoull(v);
    } else throw std::invalid_argument("unknown argument '" + std::string(args[i]) + "'");
  }
  if (!mode.empty()) std::erase_if(modes, [&](const Mode& m) { return m.name != mode; });
  if (modes.empty()) throw std::invalid_argument("--mode: no mode '" + mode + "'");
  std::vector<const Family*> chosen;
  for (const Family& f : families())
    if (expected || name == "all" || f.name == name) chosen.push_back(&f);
  if (chosen.empty()) throw std::invalid_argument("--family: no family '" + name + "'");
  for (const Family* f : chosen)
    for (const DrawResult& r : run_family(*f, modes, first, last)) {
      std::string failed;
      if (!expected) std::cout << f->name << " seed " << r.seed << ": " << r.params << "\n";
      for (std::size_t i = 0; i < modes.size(); ++i) {
        if (!expected)
          std::cout << "  " << (r.outcomes[i].pass ? "pass " : "FAIL ") << modes[i].name << ": " << r.outcomes[i].figure
                    << "\n";
        if (!r.outcomes[i].pass) failed += (failed.empty() ? "" : " ") + modes[i].name;
      }
      if (expected && !failed.empty())
        std::cout << "      {\"" << f->name << "/" << r.seed << "\", \"" << failed << "\"},\n";
    }
  return 0;
}

// The same, a bad argument reported on one line (exit 2).
int family_command(const std::vector<std::string_view>& args, const std::vector<Mode>& modes) {
  try {
    return family_replay(args, modes);
  } catch (const std::invalid_argument& e) {
    std::cerr << "stability: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace

int main(int argc, char** argv) {
  auto modes = stability_modes();
  // STABILITY_MODE=name: that column alone (while working on a mode).
  if (const char* only = std::getenv("STABILITY_MODE"))
    std::erase_if(modes, [&](const Mode& m) { return m.name != only; });
  if (argc > 1 && std::string_view(argv[1]).starts_with("--family"))
    return family_command(std::vector<std::string_view>(argv + 1, argv + argc), modes);
  // A flag where the output file goes (--help, a typo) would have been taken
  // for the file's name, and the whole matrix run into it.
  const std::vector<std::string_view> args(argv + 1, argv + argc);
  const bool quick = args.size() == 2 && args[1] == "--quick";  // skip the long cases
  if (args.size() > 2 || (args.size() == 2 && !quick) || (!args.empty() && args[0].starts_with("-"))) {
    const bool help = !args.empty() && (args[0] == "--help" || args[0] == "-h");
    (help ? std::cout : std::cerr)
        << "usage: build/stability [OUT.md [--quick]]   the matrix and the family (default report/STABILITY.md)\n"
           "       build/stability --family NAME|all [--seed S] [--mode M]   replay a family's draws\n"
           "       build/stability --family-expected   the test subset's failing draws\n";
    return help ? 0 : 2;
  }
  const std::string out_path = args.empty() ? "report/STABILITY.md" : std::string(args[0]);
  const auto cases = stability_cases();
  std::ofstream md(out_path);
  if (!md) {
    std::cerr << "stability: cannot write " << out_path << "\n";
    return 2;
  }
  md << "# Stability matrix: stiff and extreme cases\n\n"
     << "Generated by `make stability` (`tools/stability_main.cpp`, cases in `tools/numerics/stability.cpp`); do not "
        "edit by hand. Each cell: pass/fail against the case's criterion, and the measured figure. Modes: the course "
        "(dt = 1000/60), 16 substeps, ccd, the stable solver (8 iterations), stable + ccd, auto. dE is the largest growth "
        "of the step energy (kinetic + potential + h g·v/2, which the time stepping keeps exactly in free flight) "
        "relative to the energy in play; dp the momentum drift relative to Σ m|v|; sink the deepest overlap at a "
        "frame's end. A CCD cell fails when more than 1 % of its substeps ran out of impact budget (capped: the "
        "scene's time stopped for the rest of the substep). The same criteria are asserted in "
        "`tests/test_stability.cpp`. The auto column (`--solver auto`) also gives its cost: the case's wall time "
        "(the fastest of several runs) and its ratio to the mode the cost rule compares it with: the course where "
        "the course passes, else the cheapest other mode that passes; the two are timed in turn, so that a slow "
        "stretch of the machine falls on both. Costs are wall times of "
        "this machine and vary between runs by a few per cent; everything else is deterministic.\n\n";
  md << "| case | criterion |";
  for (const Mode& m : modes) md << " " << m.name << " |";
  md << "\n|---|---|";
  for (std::size_t i = 0; i < modes.size(); ++i) md << "---|";
  md << "\n";
  int fails = 0, unexpected = 0;
  const char* only_case = std::getenv("STABILITY_CASE");  // cases whose name starts so (while working on one)
  for (const StabilityCase& c : cases) {
    if (quick && c.slow) continue;
    if (only_case && c.name.rfind(only_case, 0) != 0) continue;
    md << "| " << c.name << " | " << c.criterion << " |";
    std::vector<Cell> row;
    for (const Mode& m : modes) row.push_back(run_cell(c, m));
    for (std::size_t i = 0; i < modes.size(); ++i) {
      const Cell& cell = row[i];
      const bool surprise = cell.outcome.pass == expected_to_fail(c.name, modes[i].name);
      fails += cell.outcome.pass ? 0 : 1;
      unexpected += surprise ? 1 : 0;
      const std::string cost = modes[i].name == "auto" ? auto_cost(c, modes, row) : std::string();
      md << " " << (cell.outcome.pass ? "pass" : "**FAIL**") << ": " << cell.outcome.figure << cost << " |";
      std::cout << (cell.outcome.pass ? "pass " : "FAIL ") << c.name << " [" << modes[i].name
                << "]: " << cell.outcome.figure << cost << " (" << cell.seconds << " s)"
                << (surprise ? "  <-- not as expected" : "") << std::endl;
    }
    md << "\n";
  }
  md << "\n## Why shock propagation\n\nDeepest sink (px) of a 40x40 block of mass `ratio` resting on a 20x20 block of "
        "mass 1 on the floor, over 600 frames, stable solver with and without its bottom-up pass. Gauss-Seidel alone "
        "carries the weight through the light block only at the light block's rate, so more iterations help little "
        "beyond ratio 1e2.\n\n"
     << shock_ablation();
  family_section(md, modes);
  std::cout << fails << " failing cells, " << unexpected << " not as expected; wrote " << out_path << "\n";
  return 0;
}
