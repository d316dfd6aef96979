#include "app/headless.hpp"

#include <cstdio>
#include <ostream>

#include "engine/format.hpp"

namespace physics::Headless {

void start_measures(Summary& s, const World& w) {
  s.ke_start = w.kinetic_energy();
  s.p_start = w.momentum();
}

void end_measures(Summary& s, World& w, std::int64_t frames) {
  s.frames = frames;
  s.bodies = w.components.size() - w.tiles.proxy_count();  // a tile strip's proxy is no body
  s.mobile = w.finite_bodies();
  if (w.health.finite()) w.health.count_escapes(w.components, w.frame);  // the frames since the last count
  s.ke_end = w.kinetic_energy();
  s.p_end = w.momentum();
}

Summary run(World& w, std::int64_t frames) {
  return run(w, frames, [](const World&) {});
}

namespace {
// Whether the options of this world run stage s at all.
bool runs(const World& w, Stage s) {
  switch (s) {
    case Stage::forces: case Stage::move: case Stage::collision: case Stage::health: return true;
    case Stage::ccd: return w.params.ccd || w.params.solver == Solver::automatic;
    case Stage::pairs: return w.params.ccd || w.params.solver != Solver::course || !w.tiles.empty();  // tiles: their strips
    default: return w.params.solver != Solver::course;
  }
}
}  // namespace

std::string stage_times(const World& w) {
  std::string out;
  bool first = true;
  for (std::size_t i = 0; i < stage_count; ++i) {
    const Stage s = static_cast<Stage>(i);
    if (!runs(w, s)) continue;
    // The stable solver replaces the course's Collision pass.
    if (s == Stage::collision && w.params.solver == Solver::stable) continue;
    out += first ? "" : ", ";
    out += name(s);
    out += ' ';
    first = false;
    // A system the scene left out has no time at all, not a time of zero.
    const bool off = (s == Stage::forces && !w.declares(SystemId::forces)) ||
                     (s == Stage::move && !w.declares(SystemId::move)) ||
                     (s == Stage::collision && !w.declares(SystemId::collision));
    out += off ? "off" : format_g(w.times.ms_per_step(s), 4);
  }
  return out;
}

std::string summary(const World& w, const Summary& s, const std::string& why, const std::string& scene) {
  using std::to_string;
  const auto vec = [](Vector v) { return "(" + format_g(v.x) + ", " + format_g(v.y) + ")"; };
  std::string o = "ran headless: " + why + "\n";
  if (!scene.empty()) {
    SystemSet physics_systems = w.declared();
    physics_systems.draw = false;
    const std::string names = physics_systems.to_string();
    o += "scene:           " + printable(scene) + " (systems: " + (names.empty() ? "none" : names) + ")\n";
  }
  o += "frames:          " + to_string(s.frames) + " (dt = " + format_g(w.params.dt) + " ms, " +
       to_string(w.params.substeps) + " substep(s)" +
       (w.params.integrator == Integrator::exact ? ", exact integrator" : "") + ")\n" +
       "bodies:          " + to_string(s.bodies) + " (" + to_string(s.mobile) + " mobile)\n";
  if (s.frames == 0) {
    // No frame ran: the state is the initial one (forces still pending).
    o += "kinetic energy:  " + format_g(s.ke_end, 9) + " (no frame ran)\n" +
         "momentum:        " + vec(s.p_end) + " (no frame ran)\n";
  } else {
    o += "kinetic energy:  " + format_g(s.ke_start, 9) + " after frame 1, " + format_g(s.ke_end, 9) + " at the end\n" +
         "momentum:        " + vec(s.p_start) + " after frame 1, " + vec(s.p_end) + " at the end\n";
  }
  o += "escaped:         " + escape_line(w) + "\n" + "physics ms/step: " + format_g(w.times.total_ms_per_step(), 4) +
       " total, " + stage_times(w) + "\n";
  if (w.params.solver == Solver::automatic) o += "auto:            " + auto_line(w) + "\n";
  if (const auto n = w.ccd.stats.capped_substeps; n > 0)  // Ccd::resolve: the bodies still to meet something stopped
    o += "ccd:             " + to_string(n) + " substeps over budget (bodies stopped where they met for the rest of the substep; docs/numerics.md)\n";
  if (const std::string a = advice(w); !a.empty()) o += "note:            " + a + "\n";
  return o;
}

void print_summary(std::ostream& out, const World& w, const Summary& s, const std::string& why,
                   const std::string& scene) {
  out << summary(w, s, why, scene);
}

// What the auto mode used: "course pass 590 substeps, stable solver 10
// substeps (310 contacts iterated), CCD swept 12 bodies" (counts summed over
// substeps).
std::string auto_line(const World& w) {
  const AutoStats& a = w.automatic.stats;
  return "course pass " + std::to_string(a.course_substeps) + " substeps, stable solver " +
         std::to_string(a.solver_substeps) + " substeps (" + std::to_string(a.contacts) +
         " contacts iterated), CCD swept " + std::to_string(a.swept) + " bodies";
}

std::string non_finite_line(const World& w) {
  if (w.health.finite()) return "";
  const NonFinite& b = *w.health.non_finite;
  return "body " + std::to_string(b.id) + " has a non-finite " + (b.velocity ? "velocity" : "position") + " (" +
         format_g(b.value.x) + ", " + format_g(b.value.y) + ") after frame " + std::to_string(b.frame);
}

std::string escape_line(const World& w) {
  const Health& h = w.health;
  if (!h.first_escape) return std::to_string(h.escaped);
  return std::to_string(h.escaped) + " (the first: body " + std::to_string(h.first_escape->id) + ", by frame " +
         std::to_string(h.first_escape->frame) + ")";
}

// The note names what happened in general terms (a pile and a crowd show the
// same two symptoms) and the option that stops each, unless it is on already.
std::string advice(const World& w) {
  const Health& h = w.health;
  const bool course = w.params.solver == Solver::course;
  std::string a;
  if (h.deep && course)
    a = "overlaps deeper than 1 px persist (bodies " + std::to_string(h.deep->c) + " and " + std::to_string(h.deep->b) +
        " after frame " + std::to_string(h.deep->frame) +
        "): the course solver's one pass per step leaves bodies pressed together overlapping (a stack sinks, a crowd "
        "pushes bodies into walls); --solver stable separates them";
  std::string how;
  if (h.escaped > 0 && !w.params.ccd) how = "fast ones tunnel through walls in one step (--ccd on stops that)";
  if (h.escaped > 0 && course)
    how += std::string(how.empty() ? "" : ", ") +
           "pressed ones are pushed into or through walls by the course solver (--solver stable stops that)";
  if (!how.empty()) a += std::string(a.empty() ? "" : "; ") + "bodies left the world: " + how;
  return a.empty() ? a : a + "; see docs/numerics.md";
}

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  const auto hex = [&](unsigned char c) {
    static constexpr char digits[] = "0123456789abcdef";
    out += {'\\', 'x', digits[c >> 4], digits[c & 15]};
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    const auto next = i + 1 < text.size() ? static_cast<unsigned char>(text[i + 1]) : 0;
    if (c < 0x20 || c == 0x7f) {
      hex(c);
    } else if (c == 0xc2 && next >= 0x80 && next <= 0x9f) {  // U+0080-U+009F, the C1 controls (CSI is U+009B)
      hex(c);
      hex(next);
      ++i;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

std::string hud_line(const World& w, double fps) {
  const Vector p = w.momentum();
  char buf[240];
  std::snprintf(buf, sizeof buf, "%.0f fps  physics %.3f ms/step  %zu bodies  KE %.5g  p (%.4g, %.4g)  escaped %lld",
                fps, w.times.total_ms_per_step(), w.components.size(), w.kinetic_energy(), p.x, p.y,
                static_cast<long long>(w.health.escaped));
  return buf;
}

}  // namespace physics::Headless
