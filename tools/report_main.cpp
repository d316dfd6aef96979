// make report: error against run time (report/accuracy.csv, report/REPORT.md,
// report/work_precision.png). See docs/numerics.md.
//
// The errors are deterministic; the run times are not. So the run times are
// measured only on request (`--time`, `make report TIMING=1`) and kept in
// report/costs.csv with the machine and date of that run; a plain run reuses
// them, and every file it writes comes out byte for byte the same.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>

#include "numerics/friction.hpp"
#include "numerics/report.hpp"

using namespace physics;
using namespace physics::numerics;

namespace {

constexpr int timing_runs = 5;

// One list for the whole run: the rows point into it.
const std::vector<Scenario>& report_scenarios_cached() {
  static const std::vector<Scenario> scenarios = report_scenarios();
  return scenarios;
}

std::string machine_line() {
  std::string cpu = "unknown CPU";
  std::ifstream info("/proc/cpuinfo");
  for (std::string line; std::getline(info, line);)
    if (line.rfind("model name", 0) == 0) {
      cpu = line.substr(line.find(':') + 2);
      break;
    }
  char date[64];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  std::ostringstream o;
  o << cpu << ", " << std::thread::hardware_concurrency() << " hardware threads, g++ " << __VERSION__
#ifdef __OPTIMIZE__
    << " (optimised build)"
#else
    << " (UNOPTIMISED build)"
#endif
    << ", " << date;
  return o.str();
}

// Wall time of the stepping alone, ms per simulated second: median of `timing_runs` runs.
double cost(const Scenario& s, const Mode& m) {
  std::vector<double> ms;
  const auto frames = static_cast<int>(std::lround(s.t_end / m.dt));
  for (int r = 0; r < timing_runs; ++r) {
    World w = make_world(m, s.gravity);
    s.build(w);
    const auto t0 = std::chrono::steady_clock::now();
    for (int f = 0; f < frames; ++f) Game::step(w);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2] / (frames * m.dt / 1000.0);
}

struct Row {
  const Scenario* scenario;
  Setting setting;
  Errors err;
  double cost;  // ms per simulated second; NaN when the costs file has no entry for the row
};

// The costs of one timed run, keyed by scenario, family and setting.
struct Costs {
  std::string machine;  // CPU, compiler and date of the timed run
  std::map<std::string, double> ms;
};

std::string key(const Scenario& s, const Setting& st) { return s.name + "," + st.family + "," + st.label; }

constexpr const char* machine_prefix = "# machine: ";

// report/costs.csv: a "# machine: ..." line, a header, then scenario,family,setting,ms_per_simulated_s.
Costs load_costs(const std::string& path) {
  Costs c;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(machine_prefix, 0) == 0) c.machine = line.substr(std::strlen(machine_prefix));
    const auto comma = line.rfind(',');
    if (line.empty() || line[0] == '#' || comma == std::string::npos || line.rfind("scenario,", 0) == 0) continue;
    c.ms[line.substr(0, comma)] = std::strtod(line.c_str() + comma + 1, nullptr);
  }
  return c;
}


std::string num(double x, int prec = 3) {
  if (std::isnan(x)) return "n/a";
  std::ostringstream o;
  o << std::setprecision(prec) << x;
  return o.str();
}

using Families = std::map<std::string, std::vector<const Row*>>;

const Row* find_row(const Families& fam, const std::string& family, const std::string& label) {
  const auto f = fam.find(family);
  if (f == fam.end()) return nullptr;
  for (const Row* r : f->second)
    if (r->setting.label == label) return r;
  return nullptr;
}

// The exact integrator's sentence of a scenario's reading.
std::string exact_reading(const Families& fam) {
  const Row* ce60 = find_row(fam, "course+exact (dt)", "dt=1000/60");
  const Row* ce480 = find_row(fam, "course+exact (dt)", "dt=1000/480");
  const Row* se60 = find_row(fam, "stable+exact (dt)", "dt=1000/60");
  const Row* se480 = find_row(fam, "stable+exact (dt)", "dt=1000/480");
  if (!ce60 || !ce480 || !se60 || !se480) return "";
  std::ostringstream o;
  o << "Exact integrator: course pass " << num(ce60->err.pos_rms) << " px at dt = 1000/60, " << num(ce480->err.pos_rms)
    << " px at 1000/480; stable solver " << num(se60->err.pos_rms) << " px, " << num(se480->err.pos_rms) << " px. ";
  return o.str();
}

// The auto mode's sentence: its error and cost at the sheet's dt, beside the course's.
std::string auto_reading(const Families& fam) {
  const Row* a60 = find_row(fam, "auto (dt)", "dt=1000/60");
  const Row* c60 = find_row(fam, "course (dt)", "dt=1000/60");
  if (!a60 || !c60) return "";
  std::ostringstream o;
  o << "Auto at dt = 1000/60: " << num(a60->err.pos_rms) << " px for " << num(a60->cost / c60->cost, 2)
    << "x the course's cost. ";
  return o.str();
}

// One paragraph per scenario, from the numbers.
std::string reading(const std::vector<const Row*>& rows) {
  Families fam;
  for (const Row* r : rows) fam[r->setting.family].push_back(r);
  std::ostringstream o;
  const auto& course = fam["course (dt)"];
  if (course.size() >= 2) {
    const double e0 = course.front()->err.pos_rms, e1 = course.back()->err.pos_rms;
    const double ratio = course.front()->setting.mode.dt / course.back()->setting.mode.dt;
    o << "Course mode: position error " << num(e0) << " px at dt = 1000/60, " << num(e1) << " px at "
      << course.back()->setting.label.substr(3) << " (observed order "
      << num(e1 > 0 && e0 > 0 ? std::log(e0 / e1) / std::log(ratio) : NAN, 2) << ") for "
      << num(course.back()->cost / course.front()->cost, 2) << "x the cost. ";
  }
  const auto find = [&](const std::string& f, const std::string& label) { return find_row(fam, f, label); };
  const Row* k8 = find("substeps", "K=8");
  const Row* dt480 = find("course (dt)", "dt=1000/480");
  if (k8 && dt480)
    o << "Substeps K = 8: " << num(k8->err.pos_rms) << " px for " << num(k8->cost) << " ms/s, against "
      << num(dt480->err.pos_rms) << " px for " << num(dt480->cost)
      << " ms/s at dt = 1000/480 (the same arithmetic per substep; only the frame at which impacts are seen differs). ";
  const Row* ccd1 = find("ccd (substeps)", "K=1");
  const Row* st8 = find("stable (iterations)", "it=8");
  const Row* sc1 = find("stable+ccd (substeps)", "K=1");
  if (ccd1 && st8 && sc1)
    o << "At dt = 1000/60: ccd " << num(ccd1->err.pos_rms) << " px (" << num(ccd1->cost) << " ms/s), stable (8 it.) "
      << num(st8->err.pos_rms) << " px (" << num(st8->cost) << " ms/s), stable+ccd " << num(sc1->err.pos_rms) << " px ("
      << num(sc1->cost) << " ms/s). ";
  o << exact_reading(fam) << auto_reading(fam);
  const Row* best = nullptr;
  for (const Row* r : rows)
    if (!best || r->err.pos_rms < best->err.pos_rms ||
        (r->err.pos_rms == best->err.pos_rms && r->cost < best->cost))
      best = r;
  o << "Smallest position error: " << best->setting.family << " " << best->setting.label << ", " << num(best->err.pos_rms)
    << " px for " << num(best->cost) << " ms per simulated second. ";
  int tunnel_course = 0, tunnel_ccd = 0;
  for (const Row* r : rows) (r->setting.mode.ccd ? tunnel_ccd : tunnel_course) += r->err.tunnelled;
  if (tunnel_course + tunnel_ccd > 0)
    o << "Tunnelled bodies (or order inversions), summed over the settings: " << tunnel_course << " without CCD, "
      << tunnel_ccd << " with CCD. ";
  double pen_course = 0, pen_stable = 0, pen_ccd = 0;
  for (const Row* r : rows) {
    double& p = r->setting.mode.solver == Solver::stable ? pen_stable : r->setting.mode.ccd ? pen_ccd : pen_course;
    p = std::max(p, r->err.max_penetration);
  }
  o << "Worst penetration: " << num(pen_course) << " px (course/substeps), " << num(pen_ccd) << " px (ccd), "
    << num(pen_stable) << " px (stable). ";
  std::int64_t capped = 0;
  for (const Row* r : rows) capped += r->err.capped;
  if (capped) o << "CCD ran out of its impact budget in " << capped << " substeps (it then stops the scene for the rest of the substep). ";
  return o.str();
}

std::vector<Row> measure_rows(const Costs& costs, bool time) {
  std::vector<Row> rows;
  for (const Scenario& s : report_scenarios_cached())
    for (const Setting& st : report_settings()) {
      const auto known = costs.ms.find(key(s, st));
      const double c = time ? cost(s, st.mode) : known != costs.ms.end() ? known->second : NAN;
      Row r{&s, st, measure(s, st.mode), c};
      std::cout << std::left << std::setw(16) << s.name << std::setw(24) << st.family << std::setw(14) << st.label
                << " pos " << std::setw(10) << num(r.err.pos_rms) << " cost " << num(r.cost) << " ms/s" << std::endl;
      rows.push_back(r);
    }
  return rows;
}

// ---- friction: the sliding block (docs/game-physics.md) ----
// Not against the event reference (it has no friction) but against the
// closed form v0²/(2 mu g); costs in costs.csv like the other rows.

constexpr const char* slide_name = "sliding block (friction)";

struct SlideRow {
  FrictionSetting setting;
  SlideResult result;
  double cost;  // ms per simulated second, NaN when unknown
};

double slide_cost(const Mode& m) {
  std::vector<double> ms;
  SlideResult r;
  for (int i = 0; i < timing_runs; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    r = run_slide(m);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(ms.begin(), ms.end());
  return ms[ms.size() / 2] / (r.frames * m.dt / 1000.0);
}

std::string friction_key(const FrictionSetting& f) { return std::string(slide_name) + "," + f.family + "," + f.label; }

std::vector<SlideRow> measure_friction(Costs& costs, bool time) {
  std::vector<SlideRow> rows;
  for (const FrictionSetting& f : friction_settings()) {
    const auto known = costs.ms.find(friction_key(f));
    const double c = time ? slide_cost(f.mode) : known != costs.ms.end() ? known->second : NAN;
    rows.push_back({f, run_slide(f.mode), c});
    if (time) costs.ms[friction_key(f)] = c;
  }
  return rows;
}

void write_friction(std::ostream& md, const std::vector<SlideRow>& rows) {
  const Slide s;
  md << "## " << slide_name << "\n\n"
     << "A 40 px block launched at " << num(s.v0) << " px/ms along the floor, friction " << num(s.mu)
     << " (the pair's sqrt(mu_a mu_b)), gravity " << num(s.g) << " px/ms², e = 0: it stops after v0²/(2 mu g) = "
     << num(s.exact()) << " px. Not against the event reference (it has no friction) but against that closed form; "
        "the error is v0·dt/2 (first order), early for CCD, late for the course pass, which moves before friction "
        "acts (auto takes this slide with the course pass); the stable solver moves a slider on the trapezoid of "
        "its velocity over the substep (src/engine/slide.hpp), exact but for the last substep's mu·g·h²/2.\n\n"
     << "| family | setting | stop distance (px) | error | cost (ms/s) |\n|---|---|---|---|---|\n";
  for (const SlideRow& r : rows)
    md << "| " << r.setting.family << " | " << r.setting.label << " | " << num(r.result.distance, 6) << " | "
       << num(100 * r.result.error) << " % | " << num(r.cost) << " |\n";
  md << "\n";
}

void save_costs(const std::string& path, const Costs& c, const std::vector<Row>& rows,
                const std::vector<SlideRow>& friction) {
  std::ofstream out(path);
  out << machine_prefix << c.machine << "\nscenario,family,setting,ms_per_simulated_s\n" << std::setprecision(6);
  for (const Row& r : rows) out << key(*r.scenario, r.setting) << "," << r.cost << "\n";
  for (const SlideRow& r : friction) out << friction_key(r.setting) << "," << r.cost << "\n";
}

void write_csv(const std::string& path, const std::vector<Row>& rows) {
  std::ofstream csv(path);
  csv << "scenario,family,setting,dt_ms,substeps,ccd,solver,iterations,integrator,pos_rms_px,first_impact_err_ms,energy_err_rel,"
         "momentum_err_rel,max_penetration_px,tunnelled,ccd_capped_substeps,ms_per_simulated_s\n";
  csv << std::setprecision(6);
  for (const Row& r : rows) {
    const Mode& m = r.setting.mode;
    csv << r.scenario->name << "," << r.setting.family << "," << r.setting.label << "," << m.dt << "," << m.substeps
        << "," << (m.ccd ? 1 : 0) << "," << (m.solver == Solver::stable ? "stable" : "course") << "," << m.iterations
        << "," << name(m.integrator) << "," << r.err.pos_rms << "," << num(r.err.first_impact, 6) << "," << r.err.energy << "," << r.err.momentum
        << "," << r.err.max_penetration << "," << r.err.tunnelled << "," << r.err.capped << "," << num(r.cost, 6)
        << "\n";
  }
}

std::vector<std::string> families_of(const std::vector<Setting>& settings) {
  std::vector<std::string> families;
  for (const Setting& st : settings)
    if (std::find(families.begin(), families.end(), st.family) == families.end()) families.push_back(st.family);
  return families;
}

// A log scale has no 0: smaller errors are drawn here, below rounding (the
// exact integrator's free flight and CCD's two-body, 1e-13 to 1e-11 px, show).
constexpr double error_floor = 1e-14;

// Plot data: one gnuplot data block per scenario, one sub-block per family (rows without a cost left out).
void write_plot_data(const std::string& path, const std::vector<Row>& rows, const std::vector<std::string>& families) {
  std::ofstream dat(path);
  for (const Scenario& s : report_scenarios_cached())
    for (const std::string& f : families) {
      dat << "# " << s.name << " / " << f << "\n";
      for (const Row& r : rows)
        if (r.scenario == &s && r.setting.family == f && !std::isnan(r.cost))
          dat << r.cost << " " << std::max(r.err.pos_rms, error_floor) << "\n";
      dat << "\n\n";
    }
}

constexpr const char* styles[] = {"lc rgb '#1f77b4' pt 7", "lc rgb '#ff7f0e' pt 5", "lc rgb '#2ca02c' pt 9",
                                  "lc rgb '#d62728' pt 11", "lc rgb '#9467bd' pt 13", "lc rgb '#8c564b' pt 4",
                                  "lc rgb '#e377c2' pt 6", "lc rgb '#000000' pt 3"};
constexpr std::size_t style_count = std::size(styles);

void write_plot_script(const std::string& path, const std::string& dir, const std::string& work,
                       const std::vector<std::string>& families) {
  std::ofstream gp(path);
  gp << "set terminal pngcairo size 1500,1300 font 'DejaVu Sans,10'\n"
     << "set output '" << dir << "/work_precision.png'\n"
     << "set multiplot layout 3,3 title 'Work-precision: position RMS error vs run time (log-log; errors below 1e-14 px drawn at 1e-14)'\n"
     << "set logscale xy\nset grid\nset format y '10^{%L}'\nset format x '10^{%L}'\n"
     << "set xlabel 'ms of wall time per simulated second (report/costs.csv)'\nset ylabel 'position RMS error (px)'\n"
     << "set key off\n";
  const auto& scenarios = report_scenarios_cached();
  for (std::size_t si = 0; si < scenarios.size(); ++si) {
    gp << "set title '" << scenarios[si].name << "'\nplot ";
    for (std::size_t fi = 0; fi < families.size(); ++fi)
      gp << (fi ? ", " : "") << "'" << work << "/work_precision.dat' index " << si * families.size() + fi
         << " with linespoints lw 2 " << styles[fi % style_count] << " title '" << families[fi] << "'";
    gp << "\n";
  }
  // The legend in its own panel.
  gp << "unset title\nunset xlabel\nunset ylabel\nunset tics\nunset border\nunset grid\nunset logscale\n"
     << "set key center center box spacing 1.5 font ',12'\nset xrange [0:1]\nset yrange [0:1]\nplot ";
  for (std::size_t fi = 0; fi < families.size(); ++fi)
    gp << (fi ? ", " : "") << "NaN with linespoints lw 2 " << styles[fi % style_count] << " title '" << families[fi] << "'";
  gp << "\nunset multiplot\n";
}

void write_markdown(const std::string& path, const std::vector<Row>& rows, const std::vector<SlideRow>& friction,
                    const std::string& machine) {
  std::ofstream md(path);
  md << "# Numerics report: error against run time\n\n"
     << "Generated by `make report` (`tools/report_main.cpp`); do not edit by hand.\n\n"
     << "Errors are recomputed by every `make report` and are deterministic. Costs are not: they come from the last "
        "timed run, `make report TIMING=1`, kept in [costs.csv](costs.csv) (" << machine << "; median of "
     << timing_runs << " runs in the same process, wall time of `World::step` alone, ms per simulated second; the "
        "machine is shared, so they are noisy to some tens of per cent). A plain `make report` reuses them, so it "
        "rewrites this file, accuracy.csv and work_precision.png byte for byte.\n\n"
     << "Errors are against the exact event-driven reference (`src/reference/`): position RMS over the finite bodies "
        "at 1/4, 1/2, 3/4 and all of the run; first-impact time error (the engine sees an impact at the end of its "
        "frame; the tracked body, or any for the gas); energy error (kinetic + potential) relative to the energy in "
        "play; momentum error relative to Σ m|v0|; deepest overlap over all frames; tunnelled = bodies that left the "
        "walls (walled scenes) or pairs whose x order differs from the reference (open scenes); capped = CCD substeps "
        "that ran out of impact budget.\n\n"
     << "The families ending in +exact run `--integrator exact` (x += v h + a h²/2 in a substep, the reference's "
        "motion between events) with the course pass or the stable solver; the others the sheet's symplectic Euler. "
        "`free flight` is the projectile up to just before it lands: no event, so only the integrator's error "
        "is left.\n\n"
     << "![work-precision diagram](work_precision.png)\n\n";
  for (const Scenario& s : report_scenarios_cached()) {
    md << "## " << s.name << "\n\n"
       << "| family | setting | pos RMS (px) | first impact (ms) | energy | momentum | max pen. (px) | tunnelled | "
          "capped | cost (ms/s) |\n|---|---|---|---|---|---|---|---|---|---|\n";
    std::vector<const Row*> mine;
    for (const Row& r : rows) {
      if (r.scenario != &s) continue;
      mine.push_back(&r);
      md << "| " << r.setting.family << " | " << r.setting.label << " | " << num(r.err.pos_rms) << " | "
         << num(r.err.first_impact) << " | " << num(r.err.energy, 2) << " | " << num(r.err.momentum, 2) << " | "
         << num(r.err.max_penetration) << " | " << r.err.tunnelled << " | " << r.err.capped << " | " << num(r.cost)
         << " |\n";
    }
    md << "\n" << reading(mine) << "\n\n";
  }
  write_friction(md, friction);
}

}  // namespace

// report DIR WORK [--time]: DIR gets the committed files, WORK gnuplot's input.
int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : "report";
  const std::string work = argc > 2 ? argv[2] : "build/report_work";
  const bool time = argc > 3 && std::string(argv[3]) == "--time";
  std::system(("mkdir -p '" + dir + "' '" + work + "'").c_str());
  Costs costs = time ? Costs{machine_line(), {}} : load_costs(dir + "/costs.csv");
  std::cout << (time ? "timing on: " : "costs from " + dir + "/costs.csv, timed on: ") << costs.machine << "\n";

  const std::vector<Row> rows = measure_rows(costs, time);
  const std::vector<SlideRow> friction = measure_friction(costs, time);
  if (time) save_costs(dir + "/costs.csv", costs, rows, friction);
  // A setting added since the last timed run has no cost to plot: time them all again rather than mix runs.
  const auto missing = std::count_if(rows.begin(), rows.end(), [](const Row& r) { return std::isnan(r.cost); }) +
                       std::count_if(friction.begin(), friction.end(), [](const SlideRow& r) { return std::isnan(r.cost); });
  if (missing) {
    std::cerr << "report: " << missing << " of " << rows.size() << " settings have no cost in " << dir
              << "/costs.csv; time them with `make report TIMING=1`\n";
    return 1;
  }

  write_csv(dir + "/accuracy.csv", rows);
  const auto families = families_of(report_settings());
  write_plot_data(work + "/work_precision.dat", rows, families);
  write_plot_script(work + "/work_precision.gp", dir, work, families);
  if (std::system(("gnuplot '" + work + "/work_precision.gp'").c_str()) != 0) {
    std::cerr << "report: gnuplot failed\n";
    return 1;
  }
  write_markdown(dir + "/REPORT.md", rows, friction, costs.machine);
  std::cout << "wrote " << dir << "/accuracy.csv, " << dir << "/REPORT.md, " << dir << "/work_precision.png"
            << (time ? ", " + dir + "/costs.csv" : "") << "\n";
  return 0;
}
