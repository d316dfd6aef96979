#include "scene/keys.hpp"

#include "api/convert.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <limits>

namespace physics::scene_io {
namespace {

using scene_check::At;
using scene_check::Checker;
using scene_check::num;

constexpr std::int64_t bits = 0xFFFFFFFF;
constexpr std::array<const char*, 5> faces{"none", "up", "down", "left", "right"};

Face face_named(const Reader& r, const json& v, const Path& path) {
  const std::string name = r.text(v, path);
  for (std::size_t i = 1; i < faces.size(); ++i)
    if (name == faces[i]) return static_cast<Face>(i);
  r.fail(path, "must be \"up\", \"down\", \"left\" or \"right\" (got " + r.got(v) + ")");
}

void in_range(const Checker& k, int v, int lo, int hi, At at) {
  if (v < lo || v > hi)
    k.fail(at, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] (got " + std::to_string(v) + ")");
}

bool tag_ok(const std::string& tag) {
  return tag.size() <= 32 && std::all_of(tag.begin(), tag.end(), [](char c) {
           return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
         });
}

void positive(const Checker& k, const std::optional<double>& v, At at) {
  if (v && !(std::isfinite(*v) && *v > 0.0)) k.fail(at, "must be a finite number > 0 (got " + num(*v) + ")");
}

// A platform's travel_from and travel_dir come with its travel.
void with_travel(const Checker& k, const BlockSpec& b, bool given, At at) {
  if (given && !b.travel) k.fail(at, "only a block with a \"travel\" has one");
}

// A platform's direction from its velocity, as the platformer always took it
// (1/|v|)·v: bit for bit the same for a velocity turned back (-v).
Vector unit(Vector v) { return (1.0 / Vector::norm(v)) * v; }

using BK = Key<BlockSpec>;
using W = const Components&;  // the world a block is saved from

// In the order of the writer (--print-scene's output) and the doc. Each key
// the physics reads goes into the public API's BodyDef through its to_def
// (populate, scene.cpp, creates the body with create_body).
const BK block_rows[] = {
    {.doc = {".pos", "[x, y]", "finite", "required", "the top-left corner, px (y grows downwards)"},
     .missing = "(the top-left corner [x, y], px)",
     .read = [](const Reader& r, const json& v, const Path& p, BlockSpec& b) { b.pos = r.vec(v, p); },
     .write = [](ojson& o, const BlockSpec& b) { o["pos"] = vec(b.pos); },
     .check = [](const Checker& k, const BlockSpec& b, const std::string& at) { k.finite(b.pos, At{at, ".pos"}); },
     .from_world = [](W k, EntityId e, const SceneSpec&, BlockSpec& b) { b.pos = k.position[e]; },
     .to_body = [](const BlockSpec& b, const SceneSpec&, Body& out) { out.pos = b.pos; },
     .to_def = [](const Body& b, double, BodyDef& d) { d.position = api::to_public(b.pos); }},
    {.doc = {".size", "[width, height]", "integers in [1, 2^20]", "required", "px"},
     .missing = "([width, height], px)",
     .read =
         [](const Reader& r, const json& v, const Path& p, BlockSpec& b) {
           r.pair(v, p, "an array of two integers [width, height]");
           b.width = r.size_value(v[0], p + "[0]");
           b.height = r.size_value(v[1], p + "[1]");
         },
     .write = [](ojson& o, const BlockSpec& b) { o["size"] = ojson::array({b.width, b.height}); },
     .check =
         [](const Checker& k, const BlockSpec& b, const std::string& at) {
           k.size(b.width, At{at, ".size"});
           k.size(b.height, At{at, ".size"});
         },
     .from_world = [](W k, EntityId e, const SceneSpec&, BlockSpec& b) { b.width = k.box[e].width, b.height = k.box[e].height; },
     .to_body = [](const BlockSpec& b, const SceneSpec&, Body& out) { out.width = b.width, out.height = b.height; },
     .to_def = [](const Body& b, double, BodyDef& d) { d.size = {double(b.width), double(b.height)}; }},
    {.doc = {".mass", "number or `\"inf\"`", "1e-300 to 1e150", "required", "`\"inf\"` for a fixed body"},
     .missing = "(a number > 0, or \"inf\" for a fixed body)",
     .read = [](const Reader& r, const json& v, const Path& p, BlockSpec& b) { b.mass = r.mass(v, p); },
     .write = [](ojson& o, const BlockSpec& b) { o["mass"] = mass_json(b.mass); },
     .check = [](const Checker& k, const BlockSpec& b, const std::string& at) { k.mass(b.mass, At{at, ".mass"}); },
     .from_world = [](W k, EntityId e, const SceneSpec&, BlockSpec& b) { b.mass = k.mass[e]; },
     .to_body = [](const BlockSpec& b, const SceneSpec&, Body& out) { out.mass = b.mass; },
     .to_def = [](const Body& b, double, BodyDef& d) { d.mass = b.mass; }},
    {.doc = {".velocity", "[x, y]", "±10^6 per axis", "[0, 0]", "px/ms at start"},
     .read = [](const Reader& r, const json& v, const Path& p, BlockSpec& b) { b.velocity = r.vec(v, p); },
     .write =
         [](ojson& o, const BlockSpec& b) {
           if (!Vector::is_zero(b.velocity)) o["velocity"] = vec(b.velocity);
         },
     .check = [](const Checker& k, const BlockSpec& b, const std::string& at) { k.motion(b.velocity, At{at, ".velocity"}); },
     .from_world = [](W k, EntityId e, const SceneSpec&, BlockSpec& b) { b.velocity = k.velocity[e]; },
     .to_body = [](const BlockSpec& b, const SceneSpec&, Body& out) { out.velocity = b.velocity; },
     .to_def = [](const Body& b, double, BodyDef& d) { d.velocity = api::to_public(b.velocity); }},
    {.doc = {".force", "[x, y]", "±10^6 per axis", "[0, 0]",
             "initial Σf (Q5), turned into a velocity change by Forces on frame 1"},
     .read = [](const Reader& r, const json& v, const Path& p, BlockSpec& b) { b.force = r.vec(v, p); },
     .write =
         [](ojson& o, const BlockSpec& b) {
           if (!Vector::is_zero(b.force)) o["force"] = vec(b.force);
         },
     .check = [](const Checker& k, const BlockSpec& b, const std::string& at) { k.motion(b.force, At{at, ".force"}); },
     // The pending force: an impulse not yet applied is in it.
     .from_world = [](W k, EntityId e, const SceneSpec&, BlockSpec& b) { b.force = k.sum_forces[e]; },
     .to_body = [](const BlockSpec& b, const SceneSpec&, Body& out) { out.force = b.force; },
     // An impulse J changes the velocity by J/m. Forces applies Σf·dt/m on the
     // first frame, so the initial force J/dt is exactly that impulse.
     .to_def =
         [](const Body& b, double dt, BodyDef& d) {
           d.force = api::to_public(b.force + Vector::mult(1.0 / dt, b.impulse));
         }},
    {.doc = {".impulse", "[x, y]", "±10^6 per axis", "[0, 0]",
             "velocity change × mass on frame 1 (given to Forces as the force impulse/dt)"},
     .read = [](const Reader& r, const json& v, const Path& p, BlockSpec& b) { b.impulse = r.vec(v, p); },
     .write =
         [](ojson& o, const BlockSpec& b) {
           if (!Vector::is_zero(b.impulse)) o["impulse"] = vec(b.impulse);
         },
     .check = [](const Checker& k, const BlockSpec& b, const std::string& at) { k.motion(b.impulse, At{at, ".impulse"}); },
     .from_world = [](W, EntityId, const SceneSpec&, BlockSpec&) {},  // in the force (above), as to_def
     .to_body = [](const BlockSpec& b, const SceneSpec&, Body& out) { out.impulse = b.impulse; }},
    {.doc = {".color", "`\"#rrggbb\"`", "", "`\"#808080\"`", "its colour"},
     .read = [](const Reader& r, const json& v, const Path& p, BlockSpec& b) { b.color = r.color(v, p); },
     .write =
         [](ojson& o, const BlockSpec& b) {
           if (!(b.color == default_block_color)) o["color"] = hex(b.color);
         },
     .from_world = [](W k, EntityId e, const SceneSpec&, BlockSpec& b) { b.color = k.color[e]; },
     .to_body = [](const BlockSpec& b, const SceneSpec&, Body& out) { out.color = b.color; },
     .to_def = [](const Body& b, double, BodyDef& d) { d.color = b.color; }},
    {.doc = {".restitution", "number", "[0, 1]", "the world's", "a pair uses the smaller of its two"},
     .read = [](const Reader& r, const json& v, const Path& p, BlockSpec& b) { b.restitution = r.restitution(v, p); },
     .write =
         [](ojson& o, const BlockSpec& b) {
           if (b.restitution) o["restitution"] = *b.restitution;
         },
     .check =
         [](const Checker& k, const BlockSpec& b, const std::string& at) {
           if (b.restitution) k.restitution(*b.restitution, At{at, ".restitution"});
         },
     // Only where it differs from the world's (which the walls and unset blocks take).
     .from_world =
         [](W k, EntityId e, const SceneSpec& from, BlockSpec& b) {
           if (k.restitution[e] != from.restitution) b.restitution = k.restitution[e];
         },
     .to_body = [](const BlockSpec& b, const SceneSpec& s, Body& out) { out.restitution = b.restitution.value_or(s.restitution); },
     .to_def = [](const Body& b, double, BodyDef& d) { d.restitution = b.restitution; }},
    {.doc = {".friction", "number", "[0, 1000]", "the world's",
             "Coulomb's coefficient; a pair uses sqrt(mu_a mu_b) ([game-physics.md](game-physics.md))"},
     .read = [](const Reader& r, const json& v, const Path& p, BlockSpec& b) { b.contact.friction = r.number(v, p); },
     .write =
         [](ojson& o, const BlockSpec& b) {
           if (b.contact.friction) o["friction"] = *b.contact.friction;
         },
     .check =
         [](const Checker& k, const BlockSpec& b, const std::string& at) {
           if (b.contact.friction) k.friction(*b.contact.friction, At{at, ".friction"});
         },
     .contact = true,
     .from_world =
         [](W k, EntityId e, const SceneSpec& from, BlockSpec& b) {
           if (k.friction[e] != from.friction) b.contact.friction = k.friction[e];
         },
     .to_body = [](const BlockSpec& b, const SceneSpec& s, Body& out) { out.friction = b.contact.friction.value_or(s.friction); },
     .to_def = [](const Body& b, double, BodyDef& d) { d.friction = b.friction; }},
    {.doc = {".category", "integer", "[0, 2^32 - 1]", "1",
             "bits: a pair interacts only if each one's category meets the other's mask"},
     .read =
         [](const Reader& r, const json& v, const Path& p, BlockSpec& b) {
           b.contact.rules.category = static_cast<std::uint32_t>(r.integer(v, p, 0, bits));
         },
     .write =
         [](ojson& o, const BlockSpec& b) {
           if (b.contact.rules.category != ContactRules{}.category) o["category"] = b.contact.rules.category;
         },
     .contact = true,
     .from_world = [](W k, EntityId e, const SceneSpec&, BlockSpec& b) { b.contact.rules.category = k.rules(e).category; },
     .to_body = [](const BlockSpec& b, const SceneSpec&, Body& out) { out.rules.category = b.contact.rules.category; },
     // The four keys of the contact rules at once (the world keeps them only for a body that has some).
     .to_def =
         [](const Body& b, double, BodyDef& d) {
           d.filter = {b.rules.category, b.rules.mask};
           d.sensor = b.rules.sensor;
           d.one_way = api::to_public(b.rules.one_way);
         }},
    {.doc = {".mask", "integer", "[0, 2^32 - 1]", "4294967295", "bits: the categories it meets"},
     .read =
         [](const Reader& r, const json& v, const Path& p, BlockSpec& b) {
           b.contact.rules.mask = static_cast<std::uint32_t>(r.integer(v, p, 0, bits));
         },
     .write =
         [](ojson& o, const BlockSpec& b) {
           if (b.contact.rules.mask != ContactRules{}.mask) o["mask"] = b.contact.rules.mask;
         },
     .contact = true,
     .from_world = [](W k, EntityId e, const SceneSpec&, BlockSpec& b) { b.contact.rules.mask = k.rules(e).mask; },
     .to_body = [](const BlockSpec& b, const SceneSpec&, Body& out) { out.rules.mask = b.contact.rules.mask; }},
    {.doc = {".sensor", "boolean", "", "false", "overlaps give contact events, never a correction or an impulse"},
     .read = [](const Reader& r, const json& v, const Path& p, BlockSpec& b) { b.contact.rules.sensor = r.boolean(v, p); },
     .write =
         [](ojson& o, const BlockSpec& b) {
           if (b.contact.rules.sensor) o["sensor"] = true;
         },
     .contact = true,
     .from_world = [](W k, EntityId e, const SceneSpec&, BlockSpec& b) { b.contact.rules.sensor = k.rules(e).sensor; },
     .to_body = [](const BlockSpec& b, const SceneSpec&, Body& out) { out.rules.sensor = b.contact.rules.sensor; }},
    {.doc = {".one_way", "string", "`\"up\"`, `\"down\"`, `\"left\"`, `\"right\"`", "–", "stops bodies on that face only"},
     .read = [](const Reader& r, const json& v, const Path& p, BlockSpec& b) { b.contact.rules.one_way = face_named(r, v, p); },
     .write =
         [](ojson& o, const BlockSpec& b) {
           if (b.contact.rules.one_way != Face::none) o["one_way"] = faces[static_cast<int>(b.contact.rules.one_way)];
         },
     .contact = true,
     .from_world = [](W k, EntityId e, const SceneSpec&, BlockSpec& b) { b.contact.rules.one_way = k.rules(e).one_way; },
     .to_body = [](const BlockSpec& b, const SceneSpec&, Body& out) { out.rules.one_way = b.contact.rules.one_way; }},
    {.doc = {".tag", "string", "a-z, 0-9, `_`, `-`; at most 32", "\"\"",
             "what the block is in a game (`player`, `coin`, `goal`, `platform`, `sling`, `target`, `crate`, ...); "
             "the physics ignores it, the sprite style draws by it"},
     .read = [](const Reader& r, const json& v, const Path& p, BlockSpec& b) { b.tag = r.text(v, p); },
     .write =
         [](ojson& o, const BlockSpec& b) {
           if (!b.tag.empty()) o["tag"] = b.tag;
         },
     .check =
         [](const Checker& k, const BlockSpec& b, const std::string& at) {
           if (!tag_ok(b.tag))
             k.fail(At{at, ".tag"}, "must be at most 32 characters of a-z, 0-9, '_' and '-' (got \"" + b.tag + "\")");
         },
     .to_role = [](const BlockSpec& b, const Body&, BlockRole& role) { role.tag = b.tag; },
     .from_role = [](const BlockRole& role, BlockSpec& b) { b.tag = role.tag; }},
    {.doc = {".strength", "number", "> 0, finite", "–",
             "the normal impulse in one step that breaks a target ([games.md](games.md))"},
     .read = [](const Reader& r, const json& v, const Path& p, BlockSpec& b) { b.strength = r.number(v, p); },
     .write =
         [](ojson& o, const BlockSpec& b) {
           if (b.strength) o["strength"] = *b.strength;
         },
     .check = [](const Checker& k, const BlockSpec& b, const std::string& at) { positive(k, b.strength, At{at, ".strength"}); },
     .to_role = [](const BlockSpec& b, const Body&, BlockRole& role) { role.strength = b.strength.value_or(infinity); },
     .from_role =
         [](const BlockRole& role, BlockSpec& b) {
           if (std::isfinite(role.strength)) b.strength = role.strength;
         }},
    {.doc = {".travel", "number", "> 0, finite", "–",
             "px: how far a block tagged `platform` goes along its velocity before turning back (only on such a "
             "block; a platform needs both)"},
     .read = [](const Reader& r, const json& v, const Path& p, BlockSpec& b) { b.travel = r.number(v, p); },
     .write =
         [](ojson& o, const BlockSpec& b) {
           if (b.travel) o["travel"] = *b.travel;
         },
     .check =
         [](const Checker& k, const BlockSpec& b, const std::string& at) {
           positive(k, b.travel, At{at, ".travel"});
           if (b.travel && b.tag != "platform")
             k.fail(At{at, ".travel"}, "only a block with \"tag\": \"platform\" travels (got the tag \"" + b.tag + "\")");
         },
     .to_role = [](const BlockSpec& b, const Body&, BlockRole& role) { role.travel = b.travel.value_or(infinity); },
     .from_role =
         [](const BlockRole& role, BlockSpec& b) {
           if (std::isfinite(role.travel)) b.travel = role.travel;
         }},
    {.doc = {".travel_from", "[x, y]", "finite", "`pos`",
             "where the platform's travel starts (`--save` writes it for a platform on its way)"},
     .read = [](const Reader& r, const json& v, const Path& p, BlockSpec& b) { b.travel_from = r.vec(v, p); },
     .write =
         [](ojson& o, const BlockSpec& b) {
           if (b.travel_from) o["travel_from"] = vec(*b.travel_from);
         },
     .check =
         [](const Checker& k, const BlockSpec& b, const std::string& at) {
           if (b.travel_from) k.finite(*b.travel_from, At{at, ".travel_from"});
           with_travel(k, b, b.travel_from.has_value(), At{at, ".travel_from"});
         },
     .to_role =
         [](const BlockSpec& b, const Body& body, BlockRole& role) {
           if (b.travel) role.travel_from = b.travel_from.value_or(body.pos);
         },
     // Written only where the default would not give it back: a platform on its way.
     .from_role =
         [](const BlockRole& role, BlockSpec& b) {
           if (std::isfinite(role.travel) && !(role.travel_from == b.pos)) b.travel_from = role.travel_from;
         }},
    {.doc = {".travel_dir", "[x, y]", "a unit vector", "the velocity's direction",
             "the direction of the travel (`--save` writes it for a platform on its way back)"},
     .read = [](const Reader& r, const json& v, const Path& p, BlockSpec& b) { b.travel_dir = r.vec(v, p); },
     .write =
         [](ojson& o, const BlockSpec& b) {
           if (b.travel_dir) o["travel_dir"] = vec(*b.travel_dir);
         },
     .check =
         [](const Checker& k, const BlockSpec& b, const std::string& at) {
           if (b.travel_dir && !(std::abs(Vector::norm(*b.travel_dir) - 1.0) <= 1e-9))
             k.fail(At{at, ".travel_dir"},
                    "must be a unit vector (got [" + num(b.travel_dir->x) + ", " + num(b.travel_dir->y) + "])");
           with_travel(k, b, b.travel_dir.has_value(), At{at, ".travel_dir"});
         },
     .to_role =
         [](const BlockSpec& b, const Body& body, BlockRole& role) {
           if (b.travel) role.travel_dir = b.travel_dir.value_or(unit(body.velocity));
         },
     // Written only where the default would not give it back: a platform on its way back.
     .from_role =
         [](const BlockRole& role, BlockSpec& b) {
           if (std::isfinite(role.travel) && !(role.travel_dir == unit(b.velocity))) b.travel_dir = role.travel_dir;
         }},
};

using WK = Key<SceneSpec>;

// In the writer's order.
const WK world_rows[] = {
    {{".width", "integer", "[1, 2^20]", "800", "px"},
     "",
     [](const Reader& r, const json& v, const Path& p, SceneSpec& s) {
       s.width = static_cast<int>(r.integer(v, p, 1, max_world_size));
     },
     [](ojson& o, const SceneSpec& s) { o["width"] = s.width; },
     [](const Checker& k, const SceneSpec& s, const std::string& at) { in_range(k, s.width, 1, max_world_size, At{at, ".width"}); }},
    {{".height", "integer", "[1, 2^20]", "600", "px"},
     "",
     [](const Reader& r, const json& v, const Path& p, SceneSpec& s) {
       s.height = static_cast<int>(r.integer(v, p, 1, max_world_size));
     },
     [](ojson& o, const SceneSpec& s) { o["height"] = s.height; },
     [](const Checker& k, const SceneSpec& s, const std::string& at) { in_range(k, s.height, 1, max_world_size, At{at, ".height"}); }},
    {{".dt", "number", "[10^-6, 10^6]", "16.666666666666668", "ms, the time of a frame", "the sheet's: 1000/60"},
     "",
     [](const Reader& r, const json& v, const Path& p, SceneSpec& s) { s.params.dt = r.number(v, p); },
     [](ojson& o, const SceneSpec& s) { o["dt"] = s.params.dt; },
     [](const Checker& k, const SceneSpec& s, const std::string& at) {
       const double dt = s.params.dt;
       const At a{at, ".dt"};
       if (!std::isfinite(dt)) k.fail(a, "must be a finite number (got " + num(dt) + ")");
       if (dt <= 0.0) k.fail(a, "must be > 0 (got " + num(dt) + ")");
       if (dt < min_dt) k.fail(a, "must be >= " + num(min_dt) + " ms (got " + num(dt) + ")");
       if (dt > max_dt) k.fail(a, "must be <= " + num(max_dt) + " ms (got " + num(dt) + ")");
     }},
    {{".substeps", "integer", "[1, 1000]", "1", "Forces, Move and Collision run that many times a frame with dt/substeps",
      ""},
     "",
     [](const Reader& r, const json& v, const Path& p, SceneSpec& s) {
       s.params.substeps = static_cast<int>(r.integer(v, p, 1, max_substeps));
     },
     [](ojson& o, const SceneSpec& s) { o["substeps"] = s.params.substeps; },
     [](const Checker& k, const SceneSpec& s, const std::string& at) {
       in_range(k, s.params.substeps, 1, max_substeps, At{at, ".substeps"});
     }},
    {{".gravity", "[x, y]", "±10^6 per axis", "[0, 0]", "px/ms², applied by Forces to finite masses",
      "y grows downwards, e.g. 0,0.001"},
     "",
     [](const Reader& r, const json& v, const Path& p, SceneSpec& s) { s.params.gravity = r.vec(v, p); },
     [](ojson& o, const SceneSpec& s) { o["gravity"] = vec(s.params.gravity); },
     [](const Checker& k, const SceneSpec& s, const std::string& at) { k.motion(s.params.gravity, At{at, ".gravity"}); }},
    {{".restitution", "number", "[0, 1]", "1.0", "the walls', and the blocks' that give none (a pair uses the smaller)",
      "given here, it also replaces every block's own"},
     "",
     [](const Reader& r, const json& v, const Path& p, SceneSpec& s) { s.restitution = r.restitution(v, p); },
     [](ojson& o, const SceneSpec& s) { o["restitution"] = s.restitution; },
     [](const Checker& k, const SceneSpec& s, const std::string& at) { k.restitution(s.restitution, At{at, ".restitution"}); }},
    {{".walls", "boolean", "", "true", "the four walls of Q1 around width × height (the world must then exceed 80×80)"},
     "",
     [](const Reader& r, const json& v, const Path& p, SceneSpec& s) { s.walls = r.boolean(v, p); },
     [](ojson& o, const SceneSpec& s) { o["walls"] = s.walls; },
     [](const Checker& k, const SceneSpec& s, const std::string& at) {
       if (s.walls && (s.width <= 2 * wall_thickness || s.height <= 2 * wall_thickness))
         k.fail(At{at, ".walls"}, "the world must be larger than " + std::to_string(2 * wall_thickness) + "x" +
                                      std::to_string(2 * wall_thickness) + " px to hold its walls");
     }},
    {{".systems", "array of strings", "`\"draw\"`, `\"move\"`, `\"forces\"`, `\"collision\"`", "all four",
      "the systems created and updated each frame, only those"},
     "",
     [](const Reader& r, const json& v, const Path& p, SceneSpec& s) {
       if (!v.is_array()) r.fail(p, "must be an array of system names (got " + r.got(v) + ")");
       SystemSet set{false, false, false, false};
       for (std::size_t i = 0; i < v.size(); ++i) {
         const Path at(p, i);
         const std::string name = r.text(v[i], at);
         const auto id = system_from_name(name);
         if (!id) r.fail(at, "unknown system " + quote(name) + "; expected draw, move, forces or collision");
         if (set.has(*id)) r.fail(at, "system " + quote(name) + " listed twice");
         set.set(*id, true);
       }
       s.systems = set;
     },
     [](ojson& o, const SceneSpec& s) {
       ojson systems = ojson::array();
       for (const SystemId id : all_systems)
         if (s.systems.has(id)) systems.push_back(std::string(name(id)));
       o["systems"] = systems;
     }},
    {{".ccd", "boolean", "", "false", "swept collision ([numerics.md](numerics.md))", ""},
     "",
     [](const Reader& r, const json& v, const Path& p, SceneSpec& s) { s.params.ccd = r.boolean(v, p); },
     [](ojson& o, const SceneSpec& s) { o["ccd"] = s.params.ccd; }},
    {{".solver", "string", "`\"course\"`, `\"stable\"`, `\"auto\"`", "`\"course\"`",
      "the sheet's one pass, the iterated contact solver, or per substep what the scene needs (auto decides CCD "
      "itself and does not read `ccd`)",
      ""},
     "",
     [](const Reader& r, const json& v, const Path& p, SceneSpec& s) {
       const auto solver = solver_from_name(r.text(v, p));
       if (!solver) r.fail(p, "must be \"course\", \"stable\" or \"auto\" (got " + r.got(v) + ")");
       s.params.solver = *solver;
     },
     [](ojson& o, const SceneSpec& s) { o["solver"] = std::string(name(s.params.solver)); }},
    {{".iterations", "integer", "[1, 1000]", "8", "iterations of the stable solver", ""},
     "",
     [](const Reader& r, const json& v, const Path& p, SceneSpec& s) {
       s.params.iterations = static_cast<int>(r.integer(v, p, 1, max_iterations));
     },
     [](ojson& o, const SceneSpec& s) { o["iterations"] = s.params.iterations; },
     [](const Checker& k, const SceneSpec& s, const std::string& at) {
       in_range(k, s.params.iterations, 1, max_iterations, At{at, ".iterations"});
     }},
    {{".friction", "number", "[0, 1000]", "0",
      "the walls', and the blocks' that give none (a pair uses sqrt(mu_a mu_b)); written only when used",
      "given here, it also replaces every block's own"},
     "",
     [](const Reader& r, const json& v, const Path& p, SceneSpec& s) { s.friction = r.number(v, p); },
     [](ojson& o, const SceneSpec& s) {
       if (s.friction != 0.0) o["friction"] = s.friction;  // beyond the sheet: only when used
     },
     [](const Checker& k, const SceneSpec& s, const std::string& at) { k.friction(s.friction, At{at, ".friction"}); }},
    {{".integrator", "string", "`\"course\"`, `\"exact\"`", "`\"course\"`",
      "the sheet's symplectic Euler, or x += v h + a h²/2 in a substep (free flight exact, "
      "[numerics.md](numerics.md)); written only when `\"exact\"`",
      ""},
     "",
     [](const Reader& r, const json& v, const Path& p, SceneSpec& s) {
       const auto i = integrator_from_name(r.text(v, p));
       if (!i) r.fail(p, "must be \"course\" or \"exact\" (got " + r.got(v) + ")");
       s.params.integrator = *i;
     },
     [](ojson& o, const SceneSpec& s) {
       if (s.params.integrator != Integrator::course) o["integrator"] = std::string(name(s.params.integrator));
     }},
};

const KeyDoc scene_docs[] = {
    {".name", "string", "", "the file's name", "shown in the HUD and the summary"},
    {".description", "string", "", "\"\"", "one line, for listings"},
    {".world", "object", "", "", "the world's size and parameters (below)"},
    {".blocks", "array", "", "[]", "the blocks: each a block, a `grid` or a `random` entry (below)"},
    {".tiles", "array", "", "[]", "tile layers, made after the blocks: each an object (below, `tiles[]`)"},
    {".game", "object", "", "–", "the scene is a game's level ([games.md](games.md))"},
    {".style", "string", "`\"plain\"`, `\"speed\"`, `\"sprite\"`", "`\"plain\"`",
     "how the blocks are drawn (below, \"Drawing styles\"); written when it is not `\"plain\"`"},
    {".state", "object", "", "–", "written by `--save`: what the next step reads beyond the bodies"},
};
const KeyDoc grid_docs[] = {
    {".count", "[columns, rows]", "integers in [1, 10^6]", "required",
     "the body in column c, row r is at `pos + (c·step.x, r·step.y)`, row by row"},
    {".step", "[x, y]", "finite", "the size", "touching blocks by default; may be negative"},
};
const KeyDoc random_docs[] = {
    {".count", "integer", "[1, 10^6]", "required", "the number of blocks"},
    {".side", "integer or range", "[1, 2^20]", "–", "square blocks, one draw (or `size`)"},
    {".size", "[w, h] of integers or ranges", "[1, 2^20]", "–", "(or `side`)"},
    {".mass", "number, range or `\"inf\"`", "1e-300 to 1e150", "required", ""},
    {".velocity", "[x, y] of numbers or ranges", "±10^6 per axis", "[0, 0]", ""},
    {".force", "[x, y] of numbers or ranges", "±10^6 per axis", "[0, 0]", ""},
    {".impulse", "[x, y] of numbers or ranges", "±10^6 per axis", "[0, 0]", ""},
    {".restitution", "number or range", "[0, 1]", "the world's", ""},
    {".color", "`\"#rrggbb\"` or `\"random\"`", "", "`\"random\"`", "random: each channel in [40, 220]"},
    {".cells", "`{pos, columns, step, jitter}`", "", "–",
     "body i in cell (i mod columns, i div columns) of a grid at `pos` with cells of `step`, plus a draw in [0, "
     "jitter) per axis"},
    {".area", "`{pos, size}`", "", "the inside of the walls", "anywhere the body fits (or `cells`)"},
};
const KeyDoc entry_docs[] = {
    {".grid", "object", "", "–", "a grid of equal blocks: a block's keys and `count`, `step`"},
    {".random", "object", "", "–", "seeded random blocks: the keys below and the contact keys"},
    {".seed", "integer", "[0, 2^64 - 1]", "42", "beside `random`: its generator's seed (SplitMix64)"},
};
using GK = Key<GameSpec>;

const GK game_rows[] = {
    {{".kind", "string", "`\"platformer\"`, `\"targets\"`", "required", "which game"},
     "(\"platformer\" or \"targets\")",
     [](const Reader& r, const json& v, const Path& p, GameSpec& g) { g.kind = r.text(v, p); },
     [](ojson& o, const GameSpec& g) { o["kind"] = g.kind; },
     [](const Checker& k, const GameSpec& g, const std::string& at) {
       if (g.kind != "platformer" && g.kind != "targets")
         k.fail(At{at, ".kind"}, "must be \"platformer\" or \"targets\" (got \"" + g.kind + "\")");
     }},
    {{".shots", "integer", "[1, 99]", "5", "targets: launches allowed"},
     "",
     [](const Reader& r, const json& v, const Path& p, GameSpec& g) {
       g.shots = static_cast<int>(r.integer(v, p, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
     },
     [](ojson& o, const GameSpec& g) {
       if (g.kind == "targets") o["shots"] = g.shots;
     },
     [](const Checker& k, const GameSpec& g, const std::string& at) {
       if (g.shots < 1 || g.shots > 99) k.fail(At{at, ".shots"}, "must be in [1, 99] (got " + std::to_string(g.shots) + ")");
     }},
    {{".next", "string", "", "\"\"",
      "the next level's scene file, relative to this file's folder (`--save` rewrites it from the saved file's)"},
     "",
     [](const Reader& r, const json& v, const Path& p, GameSpec& g) { g.next = r.text(v, p); },
     [](ojson& o, const GameSpec& g) {
       if (!g.next.empty()) o["next"] = g.next;
     }},
};
using TK = Key<TileSpec>;

// The rows' problems: the first unknown character, or a row of another
// length than the first; "" if none. `bad` gets the row's index.
std::string row_problem(const TileSpec& t, std::size_t& bad) {
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    bad = i;
    const std::string& row = t.rows[i];
    if (row.empty()) return "is empty (a row has at least one cell)";
    if (row.size() != t.rows[0].size())
      return "has " + std::to_string(row.size()) + " cells, rows[0] " + std::to_string(t.rows[0].size()) +
             " (every row the same length)";
    for (std::size_t c = 0; c < row.size(); ++c)
      if (!tile_of_char(row[c]))
        return "unknown tile '" + std::string(1, row[c]) + "' at column " + std::to_string(c) +
               " ('#' solid, '=' one-way up, '.' empty)";
  }
  return "";
}

const TK tile_rows[] = {
    {{".pos", "[x, y]", "finite", "required", "the grid's top-left corner, px"},
     "([x, y], px)",
     [](const Reader& r, const json& v, const Path& p, TileSpec& t) { t.pos = r.vec(v, p); },
     [](ojson& o, const TileSpec& t) { o["pos"] = ojson::array({t.pos.x, t.pos.y}); }},
    {{".cell", "integer", "[1, 2^20]", "16", "a cell's side, px"},
     "",
     [](const Reader& r, const json& v, const Path& p, TileSpec& t) {
       t.cell = static_cast<int>(r.integer(v, p, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
     },
     [](ojson& o, const TileSpec& t) { o["cell"] = t.cell; },
     [](const Checker& k, const TileSpec& t, const std::string& at) { k.size(t.cell, At{at, ".cell"}); }},
    {{".rows", "array of strings", "`#` solid, `=` one-way up, `.` empty", "required",
      "the cells, top row first, one character each; every row the same length"},
     "(the cells as strings, e.g. [\"#..=##\"])",
     [](const Reader& r, const json& v, const Path& p, TileSpec& t) {
       if (!v.is_array() || v.empty()) r.fail(p, "must be a non-empty array of strings (got " + r.got(v) + ")");
       t.rows.clear();
       for (std::size_t i = 0; i < v.size(); ++i) t.rows.push_back(r.text(v[i], Path(p, i)));
     },
     [](ojson& o, const TileSpec& t) {
       ojson rows = ojson::array();
       for (const std::string& row : t.rows) rows.push_back(row);
       o["rows"] = rows;
     },
     [](const Checker& k, const TileSpec& t, const std::string& at) {
       if (t.rows.empty()) k.fail(at + ".rows", "must be a non-empty array of strings");
       std::size_t bad = 0;
       if (const std::string problem = row_problem(t, bad); !problem.empty())
         k.fail(at + ".rows[" + std::to_string(bad) + "]", problem);
       if (std::int64_t{t.cell} * static_cast<std::int64_t>(t.rows[0].size()) > max_world_size ||
           std::int64_t{t.cell} * static_cast<std::int64_t>(t.rows.size()) > max_world_size)
         k.fail(at + ".rows", "the layer is " + std::to_string(t.rows[0].size()) + " x " +
                                  std::to_string(t.rows.size()) + " cells of " + std::to_string(t.cell) +
                                  " px: at most 1048576 px a side");
     }},
    {{".restitution", "number", "[0, 1]", "the world's", "the layer's; a pair uses the smaller"},
     "",
     [](const Reader& r, const json& v, const Path& p, TileSpec& t) { t.restitution = r.restitution(v, p); },
     [](ojson& o, const TileSpec& t) {
       if (t.restitution) o["restitution"] = *t.restitution;
     },
     [](const Checker& k, const TileSpec& t, const std::string& at) {
       if (t.restitution) k.restitution(*t.restitution, At{at, ".restitution"});
     }},
    {{".friction", "number", "[0, 1000]", "the world's", "the layer's; a pair uses sqrt(mu_a mu_b)"},
     "",
     [](const Reader& r, const json& v, const Path& p, TileSpec& t) { t.friction = r.number(v, p); },
     [](ojson& o, const TileSpec& t) {
       if (t.friction) o["friction"] = *t.friction;
     },
     [](const Checker& k, const TileSpec& t, const std::string& at) {
       if (t.friction) k.friction(*t.friction, At{at, ".friction"});
     }},
    {{".color", "`\"#rrggbb\"`", "", "`\"#808080\"`", "for drawing"},
     "",
     [](const Reader& r, const json& v, const Path& p, TileSpec& t) { t.color = r.color(v, p); },
     [](ojson& o, const TileSpec& t) {
       if (!(t.color == TileSpec{}.color)) o["color"] = hex(t.color);
     }},
};

const KeyDoc state_docs[] = {
    {".frame", "integer", ">= 0", "0", "the frame it was saved after"},
    {".warm_start", "array of [c, b, axis, jn, jt]", "", "[]", "the stable solver's warm-start impulses, by body id"},
    {".auto", "`{hold, jam, pressed: [[c, b, substeps], ...], pushed: [[body, by, side, ago], ...]}`", "", "–", "with solver `\"auto\"`: its choice's state"},
};


}  // namespace

std::span<const Key<BlockSpec>> block_keys() { return block_rows; }
std::span<const Key<SceneSpec>> world_keys() { return world_rows; }
std::span<const KeyDoc> scene_keys() { return scene_docs; }
std::span<const KeyDoc> grid_keys() { return grid_docs; }
std::span<const KeyDoc> random_keys() { return random_docs; }
std::span<const KeyDoc> entry_keys() { return entry_docs; }
std::span<const Key<GameSpec>> game_keys() { return game_rows; }
std::span<const Key<TileSpec>> tile_keys() { return tile_rows; }
std::span<const KeyDoc> state_keys() { return state_docs; }

std::vector<std::string_view> names(std::span<const KeyDoc> docs) {
  std::vector<std::string_view> out;
  for (const KeyDoc& d : docs) out.emplace_back(d.name());
  return out;
}

const std::vector<std::string_view>& block_names() {
  static const std::vector<std::string_view> out = names(block_keys());
  return out;
}
const std::vector<std::string_view>& grid_names() {
  static const std::vector<std::string_view> out = [] {
    std::vector<std::string_view> v = block_names();
    for (const std::string_view n : names(grid_keys())) v.push_back(n);
    return v;
  }();
  return out;
}
const std::vector<std::string_view>& random_names() {
  static const std::vector<std::string_view> out = [] {
    std::vector<std::string_view> v = names(random_keys());
    for (const auto& k : block_keys())
      if (k.contact) v.emplace_back(k.doc.name());
    return v;
  }();
  return out;
}
const std::vector<std::string_view>& world_names() {
  static const std::vector<std::string_view> out = names(world_keys());
  return out;
}

void read_block_keys(const Reader& r, const json& b, const Path& p, BlockSpec& out) {
  for (const auto& k : block_keys())
    if (!k.missing.empty() && !find(b, k.doc.name()))
      r.fail(p, "missing key \"" + std::string(k.doc.name()) + "\" " + std::string(k.missing));
  for (const auto& k : block_keys())
    if (const json* v = find(b, k.doc.name())) k.read(r, *v, Path(p, k.doc.key), out);
}

// A random entry's contact keys are a block's: read, written and checked by
// the same rows on a block that has nothing else.
void read_contact_keys(const Reader& r, const json& b, const Path& p, ContactSpec& out) {
  BlockSpec block;
  block.contact = out;
  for (const auto& k : block_keys())
    if (const json* v = find(b, k.doc.name()); v && k.contact) k.read(r, *v, Path(p, k.doc.key), block);
  out = block.contact;
}

void write_block_keys(ojson& o, const BlockSpec& b) {
  for (const auto& k : block_keys()) k.write(o, b);
}

void write_contact_keys(ojson& o, const ContactSpec& c) {
  BlockSpec block;
  block.contact = c;
  for (const auto& k : block_keys())
    if (k.contact) k.write(o, block);
}

}  // namespace physics::scene_io

namespace physics {

void check_block_keys(const scene_check::Checker& k, const BlockSpec& b, const std::string& path) {
  for (const auto& key : scene_io::block_keys())
    if (key.check) key.check(k, b, path);
}

BlockRole role_of(const BlockSpec& b, const Body& body) {
  BlockRole role;
  for (const auto& key : scene_io::block_keys())
    if (key.to_role) key.to_role(b, body, role);
  return role;
}

BlockSpec block_from_world(const Components& k, EntityId e, const SceneSpec& from, const BlockRole& role) {
  BlockSpec b;
  for (const auto& key : scene_io::block_keys())
    if (key.from_world) key.from_world(k, e, from, b);
  for (const auto& key : scene_io::block_keys())  // after: a platform's compare with its position and velocity
    if (key.from_role) key.from_role(role, b);
  return b;
}

Body body_of(const BlockSpec& b, const SceneSpec& s, std::size_t entry, std::int64_t index) {
  Body out;
  out.entry = entry;
  out.index = index;
  for (const auto& key : scene_io::block_keys())
    if (key.to_body) key.to_body(b, s, out);
  return out;
}

BodyDef body_def(const Body& b, double dt) {
  BodyDef d;
  for (const auto& key : scene_io::block_keys())
    if (key.to_def) key.to_def(b, dt, d);
  return d;
}

void check_contact_keys(const scene_check::Checker& k, const ContactSpec& c, const std::string& path) {
  BlockSpec block;
  block.contact = c;
  for (const auto& key : scene_io::block_keys())
    if (key.check && key.contact) key.check(k, block, path);
}

}  // namespace physics

namespace physics {
namespace {

using scene_io::KeyDoc;

void table(std::string& out, std::string_view title, std::string_view prefix, std::span<const KeyDoc> docs) {
  out += std::string(title) + "\n\n| Key | Type | Range | Default | Meaning |\n|---|---|---|---|---|\n";
  for (const KeyDoc& d : docs) {
    out += "| `" + std::string(prefix) + d.name() + "` | " + std::string(d.type) + " | " + std::string(d.range) + " | " +
           std::string(d.fallback) + " | " + std::string(std::string_view(d.doc)) + " |\n";
  }
  out += "\n";
}

std::vector<KeyDoc> docs_of(auto rows) {
  std::vector<KeyDoc> out;
  for (const auto& k : rows) out.push_back(k.doc);
  return out;
}

}  // namespace

std::string key_tables_markdown() {
  std::string out;
  table(out, "**The top level**", "", scene_io::scene_keys());
  table(out, "**`world`**", "world.", docs_of(scene_io::world_keys()));
  table(out, "**A block** (an entry of `blocks`; `friction` to `one_way` are the contact keys)", "blocks[].",
        docs_of(scene_io::block_keys()));
  table(out, "**Generators**: an entry of `blocks` that makes many blocks", "blocks[].", scene_io::entry_keys());
  table(out, "**`grid`**: a block's keys, and", "grid.", scene_io::grid_keys());
  table(out, "**`random`**: the contact keys (the same for all its bodies, never drawn), and", "random.",
        scene_io::random_keys());
  table(out, "**`game`**", "game.", docs_of(scene_io::game_keys()));
  table(out, "**A tile layer** (an entry of `tiles`)", "tiles[].", docs_of(scene_io::tile_keys()));
  table(out, "**`state`**", "state.", scene_io::state_keys());
  out.pop_back();  // one newline at the end
  return out;
}

}  // namespace physics

// The command line's world flags: their options and values from the rows.
namespace physics {
namespace {

using scene_io::json;
using scene_io::Key;
using scene_io::KeyDoc;

// The doc's markdown as plain text: no backticks or quotes, a link as its file.
std::string plain(std::string_view md) {
  std::string out;
  for (std::size_t i = 0; i < md.size(); ++i) {
    const std::size_t mid = md[i] == '[' ? md.find("](", i) : std::string_view::npos;
    const std::size_t end = mid == std::string_view::npos ? mid : md.find(')', mid);
    if (end != std::string_view::npos) {
      out += "docs/" + std::string(md.substr(mid + 2, end - mid - 2));
      i = end;
    } else if (md[i] != '`' && md[i] != '"') {
      out += md[i];
    }
  }
  return out;
}

WorldFlag flag_of(const KeyDoc& d) {
  const bool boolean = d.type == "boolean", text = d.type == "string";
  std::string value = d.type == "integer" ? "N" : d.type == "number" ? "X" : d.type == "[x, y]" ? "X,Y" : "on|off";
  if (text) {
    value = plain(d.range);
    for (std::size_t at; (at = value.find(", ")) != std::string::npos;) value.replace(at, 2, "|");
  }
  // Without the writer's note ("; written only when used"): no file is written here.
  const std::string_view doc = d.doc;
  std::string help = plain(doc.substr(0, doc.find("; written "))) + " (" + (d.range.empty() ? "" : (text ? "one of " : "in ") + plain(d.range) + ", ") +
                     "default " + plain(d.fallback) + ")";
  if (*d.flag) help += std::string("; ") + d.flag;
  if (boolean) help += std::string("; --") + d.name() + " alone means on";
  return {d.name(), value, help, boolean};
}

// A number's text as JSON: for an integer key an integer only (the row reads
// its range), for any other the double from_chars reads (-0 stays -0).
std::optional<json> number(std::string_view s, bool integer) {
  const char* end = s.data() + s.size();
  if (integer) {
    std::int64_t i = 0;
    const auto [at, ec] = std::from_chars(s.data(), end, i);
    return ec == std::errc{} && at == end ? std::optional<json>(i) : std::nullopt;
  }
  double v = 0;
  const auto [at, ec] = std::from_chars(s.data(), end, v);
  return ec == std::errc{} && at == end ? std::optional<json>(v) : std::nullopt;
}

// The flag's text as the JSON value its row reads (value_of_text), or the
// flag's error.
json flag_value(const KeyDoc& d, const std::string& text) {
  if (std::optional<json> v = scene_io::value_of_text(d, text)) return *std::move(v);
  const std::string problem = d.type == "boolean"  ? "must be on or off"
                              : d.type == "[x, y]" ? "must be two numbers X,Y"
                              : d.type == "integer" ? "must be an integer in " + std::string(d.range)
                                                    : "must be a number";
  throw SceneError("--" + std::string(d.name()) + ": " + problem + " (got '" + text + "')");
}

// The row's message without its path ("[0]: ", ".dt: ") and its value (the
// flag's text is shown instead, as given).
std::string problem_of(const std::string& message, const std::string& flag) {
  std::string p = message.substr(std::min(message.size(), flag.size() + 2));
  if (!p.empty() && (p[0] == '.' || p[0] == '[')) p = p.substr(std::min(p.size(), p.find(": ") + 2));
  return p.substr(0, p.rfind(" (got "));
}

}  // namespace

// A key's value written as text (a flag's, a map editor's string property),
// by the row's type: on/off (true/false, 1/0, yes/no) for a boolean, "X,Y"
// for [x, y], a number, a comma-separated list for an array of strings, else
// the text itself.
std::optional<json> scene_io::value_of_text(const KeyDoc& d, std::string_view text) {
  if (d.type == "boolean") {
    for (const char* on : {"on", "true", "1", "yes"})
      if (text == on) return true;
    for (const char* off : {"off", "false", "0", "no"})
      if (text == off) return false;
    return std::nullopt;
  }
  if (d.type == "[x, y]") {
    const std::size_t comma = text.find(',');
    if (comma == std::string_view::npos) return std::nullopt;
    const auto x = number(text.substr(0, comma), false), y = number(text.substr(comma + 1), false);
    if (!x || !y) return std::nullopt;
    return json::array({*x, *y});
  }
  if (d.type == "integer" || d.type == "number") return number(text, d.type == "integer");
  if (d.type == "array of strings") {
    json out = json::array();
    for (std::size_t at = 0; at <= text.size();) {
      const std::size_t comma = std::min(text.find(',', at), text.size());
      out.push_back(std::string(text.substr(at, comma - at)));
      at = comma + 1;
    }
    return out;
  }
  return std::string(text);
}

const std::vector<WorldFlag>& world_flags() {
  static const std::vector<WorldFlag> out = [] {
    std::vector<WorldFlag> v;
    for (const auto& k : scene_io::world_keys())
      if (k.doc.flag) v.push_back(flag_of(k.doc));
    return v;
  }();
  return out;
}

void read_world_flag(SceneSpec& s, std::string_view name, const std::string& text) {
  const auto rows = scene_io::world_keys();
  const auto row = std::find_if(rows.begin(), rows.end(), [&](const auto& k) { return k.doc.flag && name == k.doc.name(); });
  const std::string flag = "--" + std::string(name);
  if (row == rows.end()) throw SceneError(flag + ": not a world key of the command line");
  const json v = flag_value(row->doc, text);
  try {
    const scene_io::Reader r(flag);
    row->read(r, v, "", s);
    if (row->check) row->check(scene_check::Checker{flag}, s, "");
  } catch (const SceneError& e) {
    throw SceneError(flag + ": " + problem_of(e.what(), flag) + " (got '" + text + "')");
  }
}

}  // namespace physics
