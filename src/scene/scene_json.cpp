#include "scene/scene_json.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
// nlohmann's own invariant checks (assert, as the build has no NDEBUG) cost
// a tenth of the load of a large scene; this file is the only one to include
// it, so there is no other definition of its inline functions to disagree with.
#define JSON_ASSERT(x) static_cast<void>(0)
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

namespace physics {

using json = nlohmann::json;

namespace {

constexpr std::size_t max_depth = 64;                    // scene files need 5
constexpr std::uintmax_t max_file_size = 64u << 20;      // bytes

// ---------------------------------------------------------------------------
// A plain block entry ({"pos": [x, y], "size": [w, h], "mass": m, ...}) read
// from the parser's events without a document: the entries of a large scene
// are nearly all plain blocks, and a json object per entry (a std::map, a
// vector per pair, all freed again) was half of its load time. The events
// are kept, so that an entry that is anything else (a generator, an unknown
// or repeated key, a nested value, a wrong type, shape or range) is replayed
// into the document and read by read_entry, which words the error: this path
// never makes a message of its own, so every message stays the same.

class PlainBlock {
 public:
  enum class Kind : std::uint8_t { key, start_array, end_array, null, boolean, integer, natural, real, string };
  struct Event {
    Kind kind;
    std::uint8_t id = 0;  // key: its index in names; string: its index in strings()
    bool b = false;       // the value, by kind
    std::int64_t i = 0;
    std::uint64_t u = 0;
    double d = 0;
  };
  // The keys of a plain block (read_block's list).
  static constexpr std::array<std::string_view, 8> names{"pos",   "size",  "mass",  "velocity",
                                                         "force", "impulse", "color", "restitution"};

  void reset() {
    events_.clear();
    strings_.clear();
    seen_ = 0;
    in_array_ = false;
  }
  const std::vector<Event>& events() const { return events_; }
  const std::string& text(const Event& e) const { return strings_[e.id]; }
  bool in_array() const { return in_array_; }

  // Each returns false when the event does not fit a plain block: the caller
  // replays the events so far, then gives this one to the document.
  bool key(std::string_view k) {
    const auto it = std::find(names.begin(), names.end(), k);
    const auto id = static_cast<std::uint8_t>(it - names.begin());
    if (it == names.end() || (seen_ >> id & 1u)) return false;  // unknown, or a duplicate (the document's error)
    seen_ |= 1u << id;
    return push({Kind::key, id});
  }
  bool start_array() {
    if (in_array_) return false;  // [[...]]: no block key holds one
    in_array_ = true;
    return push({Kind::start_array});
  }
  bool end_array() {
    in_array_ = false;
    return push({Kind::end_array});
  }
  bool scalar(const Event& e) { return push(e); }
  bool string(std::string&& s) {
    if (strings_.size() > 8) return false;
    strings_.push_back(std::move(s));
    return push({Kind::string, static_cast<std::uint8_t>(strings_.size() - 1)});
  }

  bool to_spec(BlockSpec& out) const;

 private:
  bool push(const Event& e) {
    events_.push_back(e);
    return true;
  }
  static bool number(const Event& e, double& out);
  static bool vec(const Event* e, Vector& out);
  static bool side(const Event& e, int& out);
  bool mass(const Event& e, double& out) const;
  bool color(const Event& e, Color& out) const;

  std::vector<Event> events_;
  std::vector<std::string> strings_;
  unsigned seen_ = 0;  // the keys given so far, a bit each
  bool in_array_ = false;
};

// Reader::number's conversion: the number's value as a double, finite.
bool PlainBlock::number(const Event& e, double& out) {
  switch (e.kind) {
    case Kind::integer: out = static_cast<double>(e.i); break;
    case Kind::natural: out = static_cast<double>(e.u); break;
    case Kind::real: out = e.d; break;
    default: return false;
  }
  return std::isfinite(out);
}

// e: the start of an array of exactly two numbers. The events are in one
// vector and every array in it is closed, so reading in order, each event
// looked at exists: e[1] since e[0] opens an array, e[2] since e[1] is not
// its end, and so on.
bool PlainBlock::vec(const Event* e, Vector& out) {
  return e[0].kind == Kind::start_array && number(e[1], out.x) && number(e[2], out.y) &&
         e[3].kind == Kind::end_array;
}

// A side, an integer in [1, max_block_size]; a real one (4.0) is left to
// the document's reader, which takes it too: rare, and it has rules of its own.
bool PlainBlock::side(const Event& e, int& out) {
  if (e.kind == Kind::natural && e.u >= 1 && e.u <= static_cast<std::uint64_t>(max_block_size)) {
    out = static_cast<int>(e.u);
    return true;
  }
  return false;  // negative integers (nlohmann's "integer"): out of range
}

bool PlainBlock::mass(const Event& e, double& out) const {
  if (e.kind == Kind::string) {
    if (text(e) != "inf") return false;
    out = infinity;
    return true;
  }
  return number(e, out);  // > 0: validate() (scene.hpp), as for the document
}

bool PlainBlock::color(const Event& e, Color& out) const {
  if (e.kind != Kind::string) return false;
  const std::string& s = text(e);
  if (s.size() != 7 || s[0] != '#') return false;
  const auto digit = [](char c) {
    return c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
  };
  std::uint8_t rgb[3];
  for (int i = 0; i < 3; ++i) {
    const int hi = digit(s[1 + 2 * i]), lo = digit(s[2 + 2 * i]);
    if (hi < 0 || lo < 0) return false;
    rgb[i] = static_cast<std::uint8_t>(hi * 16 + lo);
  }
  out = {rgb[0], rgb[1], rgb[2], 255};
  return true;
}

// The block read_block would make of these events, or false if it would
// not make one (it then says why) or might make it differently.
bool PlainBlock::to_spec(BlockSpec& out) const {
  std::array<const Event*, names.size()> at{};  // each key's value (a scalar, or the start of its array)
  for (std::size_t i = 0; i + 1 < events_.size(); ++i)
    if (events_[i].kind == Kind::key) at[events_[i].id] = &events_[i + 1];
  const Event *pos = at[0], *size = at[1], *mass_ = at[2];
  if (!pos || !size || !mass_ || !vec(pos, out.pos) || !mass(*mass_, out.mass)) return false;
  const bool sides = size[0].kind == Kind::start_array && side(size[1], out.width) && side(size[2], out.height) &&
                     size[3].kind == Kind::end_array;  // in this order: see vec()
  if (!sides) return false;
  for (std::size_t k = 3; k < 6; ++k) {
    Vector& v = k == 3 ? out.velocity : k == 4 ? out.force : out.impulse;
    if (at[k] && !vec(at[k], v)) return false;
  }
  if (at[6] && !color(*at[6], out.color)) return false;
  if (at[7]) {
    double e;
    if (!number(*at[7], e)) return false;
    out.restitution = e;  // in [0, 1]: validate()
  }
  return true;
}

// ---------------------------------------------------------------------------
// Parsing: a SAX handler that builds the document like nlohmann's own DOM
// parser, but rejects duplicate keys (nlohmann keeps the last one silently)
// and nesting deeper than max_depth, and keeps the error's byte position.

class StrictDom : public nlohmann::json_sax<json> {
 public:
  json root;
  std::string error;          // set when the parse failed
  std::size_t position = 0;   // byte position of a syntax error, else 0

  // Each event goes to the plain block being read, if there is one and it
  // takes it; else (the block replayed into the document first) to the document.
  bool null() override { return fast({Kind::null}) || add(nullptr); }
  bool boolean(bool v) override { return fast({.kind = Kind::boolean, .b = v}) || add(v); }
  bool number_integer(number_integer_t v) override { return fast({.kind = Kind::integer, .i = v}) || add(v); }
  bool number_unsigned(number_unsigned_t v) override { return fast({.kind = Kind::natural, .u = v}) || add(v); }
  bool number_float(number_float_t v, const string_t&) override {
    return fast({.kind = Kind::real, .d = v}) || add(v);
  }
  bool string(string_t& v) override {
    if (fast_ && plain_.string(std::move(v))) return true;
    if (fast_) fall_back();
    return add(v);
  }
  bool binary(binary_t&) override {
    error = "binary values are not JSON";
    return false;
  }
  bool start_object(std::size_t) override {
    if (fast_) fall_back();  // a nested object: not a plain block
    if (!stack_.empty() && stack_.back().blocks && on_plain_block) {
      // An entry of "blocks": read as a plain block until it shows it is not one.
      plain_.reset();
      fast_ = true;
      return true;
    }
    return open(json::object());
  }
  bool start_array(std::size_t) override {
    if (fast_ && plain_.start_array()) return true;
    if (fast_) fall_back();
    // Most arrays of a scene are pairs ([x, y], [w, h]): one allocation, not two.
    json a = json::array();
    a.get_ref<json::array_t&>().reserve(2);
    return open(std::move(a));
  }
  bool end_object() override {
    if (fast_) {
      BlockSpec spec;
      if (plain_.to_spec(spec)) {
        fast_ = false;
        on_plain_block(std::move(spec), stack_.back().children++);
        return true;
      }
      fall_back();  // read_entry says what is wrong with it
    }
    return close();
  }
  bool end_array() override {
    if (fast_) return plain_.end_array();  // the plain block only opens arrays one deep
    return close();
  }
  bool key(string_t& k) override {
    if (fast_ && plain_.key(k)) return true;
    if (fast_) fall_back();
    // One lookup: the member is made here (null until its value comes), so
    // a second one with the same name is a duplicate.
    auto [it, inserted] = stack_.back().value->emplace(k, nullptr);
    if (!inserted) {
      error = path() + (path().empty() ? "" : ": ") + "duplicate key \"" + k + "\"";
      return false;
    }
    slot_ = &it.value();
    last_key_ = k;
    return true;
  }
  bool parse_error(std::size_t pos, const std::string&, const nlohmann::detail::exception& ex) override {
    position = std::max<std::size_t>(pos, 1);
    // nlohmann says "[json.exception.parse_error.101] parse error at line 2,
    // column 5: syntax error while ..."; keep what follows the position.
    // Other errors (number overflow) have no position text: drop the "[...] " tag.
    std::string what = ex.what();
    if (const auto col = what.find("column "); col != std::string::npos) {
      if (const auto colon = what.find(": ", col); colon != std::string::npos) what = what.substr(colon + 2);
    } else if (const auto tag = what.find("] "); !what.empty() && what[0] == '[' && tag != std::string::npos) {
      what = what.substr(tag + 2) + " (numbers must be finite)";
    }
    error = what;
    return false;
  }

 // Called with each element of the top-level "blocks" array as soon as it is
  // complete (its index in the array); the element is dropped after, so a
  // large scene is never held whole as a document. Unset: nothing streamed.
  std::function<void(const json&, std::size_t)> on_block;
  // Called instead with an element of it that is a plain block (PlainBlock),
  // read without a document. Unset: every element goes to on_block.
  std::function<void(BlockSpec&&, std::size_t)> on_plain_block;

 private:
  // An open array or object; where it sits in its parent (a key or an
  // index) is kept to build the path of an error, and only then.
  struct Open {
    json* value;
    std::string key;          // in an object
    std::size_t index = 0;    // in an array
    bool in_array = false;
    std::size_t children = 0; // values placed in it so far (an array's next index)
    bool blocks = false;      // the root's "blocks" array, streamed to on_block
  };
  std::vector<Open> stack_;
  json* slot_ = nullptr;  // the member key() made, waiting for its value
  std::string last_key_;  // its name
  using Kind = PlainBlock::Kind;
  PlainBlock plain_;      // the entry of "blocks" being read as a plain block,
  bool fast_ = false;     // if this is set

  bool fast(const PlainBlock::Event& e) {
    if (!fast_) return false;
    if (plain_.scalar(e)) return true;
    fall_back();
    return false;
  }
  // The entry is not a plain block: it becomes the document's, as if it had
  // been given to it from its start (opened at the index it would have had).
  // Replaying cannot fail: the events were those of a valid, shallow object
  // with no repeated key.
  void fall_back() {
    fast_ = false;
    open(json::object());
    for (const PlainBlock::Event& e : plain_.events()) {
      switch (e.kind) {
        case Kind::key: {
          string_t k(PlainBlock::names[e.id]);
          key(k);
          break;
        }
        case Kind::start_array: start_array(0); break;
        case Kind::end_array: end_array(); break;
        case Kind::null: null(); break;
        case Kind::boolean: boolean(e.b); break;
        case Kind::integer: number_integer(e.i); break;
        case Kind::natural: number_unsigned(e.u); break;
        case Kind::real: number_float(e.d, {}); break;
        case Kind::string: {
          string_t v = plain_.text(e);
          string(v);
          break;
        }
      }
    }
  }

  std::string path() const {
    std::string p;
    for (std::size_t i = 1; i < stack_.size(); ++i)
      p += stack_[i].in_array ? "[" + std::to_string(stack_[i].index) + "]" : "." + stack_[i].key;
    if (!p.empty() && p[0] == '.') p.erase(0, 1);
    return p;
  }
  // Places v in the open container (or as the root); returns where it went.
  json* place(json&& v) {
    if (stack_.empty()) {
      root = std::move(v);
      return &root;
    }
    Open& top = stack_.back();
    ++top.children;
    if (top.value->is_array()) {
      top.value->push_back(std::move(v));
      return &top.value->back();
    }
    *slot_ = std::move(v);
    return slot_;
  }
  bool add(json&& v) {
    if (!stack_.empty() && stack_.back().blocks) {
      on_block(v, stack_.back().children++);  // a block that is not an object: on_block says so
      return true;
    }
    place(std::move(v));
    return true;
  }
  bool open(json&& v) {
    if (stack_.size() >= max_depth) {
      error = "nesting deeper than " + std::to_string(max_depth) + " levels";
      return false;
    }
    Open o{nullptr, {}, 0, false, 0, false};
    if (!stack_.empty()) {
      const Open& top = stack_.back();
      o.in_array = top.value->is_array();
      if (o.in_array) o.index = top.children;
      else o.key = last_key_;
      o.blocks = on_block && stack_.size() == 1 && !o.in_array && o.key == "blocks" && v.is_array();
    }
    o.value = place(std::move(v));
    stack_.push_back(std::move(o));
    return true;
  }
  bool close() {
    stack_.pop_back();
    if (!stack_.empty() && stack_.back().blocks) {
      json& blocks = *stack_.back().value;
      on_block(blocks.back(), stack_.back().children - 1);
      blocks.get_ref<json::array_t&>().pop_back();
    }
    return true;
  }
};

// ---------------------------------------------------------------------------
// Reading: every accessor takes the value and its key path, and throws
// SceneError("source: path: problem").

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string quote(std::string_view s) {
  std::string out = "\"";
  for (const char c : s.substr(0, 60)) out += (c >= 32 && c < 127) ? c : '?';
  if (s.size() > 60) out += "...";
  return out + "\"";
}

std::string short_text(double v) {
  std::ostringstream o;
  o.precision(10);
  o << v;
  return o.str();
}

// A key path ("blocks[3].size[0]"), built only for a message: a scene's
// thousands of blocks pass their checks without a string being made. A Path
// points to its parent, so it lives no longer than it: name only Paths made
// from named ones.
class Path {
 public:
  Path(const char* text) : text_(text) {}  // NOLINT: a literal path
  Path(const Path& parent, const char* suffix) : parent_(&parent), text_(suffix) {}
  Path(const Path& parent, std::size_t index) : parent_(&parent), index_(index), indexed_(true) {}
  std::string str() const {
    std::string p = parent_ ? parent_->str() : std::string();
    return indexed_ ? p + "[" + std::to_string(index_) + "]" : p + text_;
  }
  friend Path operator+(const Path& parent, const char* suffix) { return Path(parent, suffix); }

 private:
  const Path* parent_ = nullptr;
  const char* text_ = "";
  std::size_t index_ = 0;
  bool indexed_ = false;
};

class Reader {
 public:
  explicit Reader(const std::string& source) : source_(source) {}

  [[noreturn]] void fail(const Path& at, const std::string& problem) const {
    const std::string path = at.str();
    throw SceneError(source_ + ": " + (path.empty() ? "" : path + ": ") + problem);
  }

  std::string got(const json& v) const {
    if (v.is_number()) return short_text(v.get<double>());
    if (v.is_string()) return "the string " + quote(v.get_ref<const std::string&>());
    if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
    return std::string(v.is_null() ? "null" : v.is_array() ? "an array" : "an object");
  }

  void object(const json& v, const Path& path) const {
    if (!v.is_object()) fail(path, "must be an object {...} (got " + got(v) + ")");
  }

  // Unknown keys are errors, with the nearest known key as a hint.
  void keys(const json& v, const Path& path, std::initializer_list<std::string_view> allowed) const {
    keys(v, path, std::span<const std::string_view>(allowed.begin(), allowed.size()));
  }
  void keys(const json& v, const Path& path, std::span<const std::string_view> allowed) const {
    object(v, path);
    for (const auto& item : v.items()) {
      const std::string& k = item.key();
      if (std::find(allowed.begin(), allowed.end(), k) != allowed.end()) continue;
      std::string hint, list;
      std::size_t best = 3;
      for (const std::string_view a : allowed) {
        list += (list.empty() ? "" : ", ") + std::string(a);
        if (const std::size_t d = edit_distance(k, a); d < best) best = d, hint = std::string(a);
      }
      const std::string p = path.str();
      fail((p.empty() ? quote(k) : p + "." + k).c_str(),
           "unknown key" + (hint.empty() ? "" : " (did you mean \"" + hint + "\"?)") + "; expected one of: " + list);
    }
  }

  double number(const json& v, const Path& path) const {
    if (!v.is_number()) fail(path, "must be a number (got " + got(v) + ")");
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(path, "must be a finite number (got " + short_text(d) + ")");
    return d;
  }

  std::int64_t integer(const json& v, const Path& path, std::int64_t lo, std::int64_t hi) const {
    if (!v.is_number()) fail(path, "must be an integer (got " + got(v) + ")");
    std::int64_t i;
    if (v.is_number_unsigned()) {
      const auto u = v.get<std::uint64_t>();
      if (u > static_cast<std::uint64_t>(hi)) range_fail(path, lo, hi, std::to_string(u));
      i = static_cast<std::int64_t>(u);
    } else if (v.is_number_integer()) {
      i = v.get<std::int64_t>();
    } else {
      const double d = v.get<double>();
      if (!std::isfinite(d) || std::floor(d) != d) fail(path, "must be an integer (got " + short_text(d) + ")");
      if (d < static_cast<double>(lo) || d > static_cast<double>(hi)) range_fail(path, lo, hi, short_text(d));
      i = static_cast<std::int64_t>(d);
    }
    if (i < lo || i > hi) range_fail(path, lo, hi, std::to_string(i));
    return i;
  }

  std::uint64_t seed(const json& v, const Path& path) const {
    if (v.is_number_unsigned()) return v.get<std::uint64_t>();
    return static_cast<std::uint64_t>(integer(v, path, 0, std::int64_t{1} << 53));
  }

  bool boolean(const json& v, const Path& path) const {
    if (!v.is_boolean()) fail(path, "must be true or false (got " + got(v) + ")");
    return v.get<bool>();
  }

  std::string text(const json& v, const Path& path) const {
    if (!v.is_string()) fail(path, "must be a string (got " + got(v) + ")");
    return v.get<std::string>();
  }

  const json& pair(const json& v, const Path& path, const char* what) const {
    if (!v.is_array() || v.size() != 2) fail(path, std::string("must be ") + what + " (got " + got(v) + ")");
    return v;
  }

  Vector vec(const json& v, const Path& path) const {
    pair(v, path, "an array of two numbers [x, y]");
    return {number(v[0], path + "[0]"), number(v[1], path + "[1]")};
  }

  int size_value(const json& v, const Path& path) const {
    if (v.is_number() && v.get<double>() <= 0) fail(path, "must be > 0 (got " + got(v) + ")");
    return static_cast<int>(integer(v, path, 1, max_block_size));
  }

  double mass(const json& v, const Path& path) const {
    if (v.is_string()) {
      if (v.get_ref<const std::string&>() == "inf") return infinity;
      fail(path, "must be a number > 0 or \"inf\" (got " + got(v) + ")");
    }
    if (v.is_number() && !std::isfinite(v.get<double>()))
      fail(path, "must be a finite number > 0, or the string \"inf\" for a fixed body (got " + got(v) + ")");
    return number(v, path);  // > 0: validate() (scene.hpp)
  }

  double restitution(const json& v, const Path& path) const {
    return number(v, path);  // in [0, 1]: validate() (scene.hpp)
  }

  Color color(const json& v, const Path& path) const {
    if (v.is_string()) {
      const std::string& s = v.get_ref<const std::string&>();
      const bool hex = s.size() == 7 && s[0] == '#' &&
                       std::all_of(s.begin() + 1, s.end(), [](char c) { return std::isxdigit(static_cast<unsigned char>(c)); });
      if (hex) {
        const auto byte = [&](int i) { return static_cast<std::uint8_t>(std::stoi(s.substr(i, 2), nullptr, 16)); };
        return {byte(1), byte(3), byte(5), 255};
      }
    }
    fail(path, "must be a colour \"#rrggbb\" (got " + got(v) + ")");
  }

  // A number, or a range [min, max] a generator draws from.
  RealSpec real_spec(const json& v, const Path& path) const {
    if (v.is_array()) {
      pair(v, path, "a number or a range [min, max]");
      const double lo = number(v[0], path + "[0]"), hi = number(v[1], path + "[1]");
      if (lo > hi) fail(path, "range [" + short_text(lo) + ", " + short_text(hi) + "] is empty (min > max)");
      return RealSpec::uniform(lo, hi);
    }
    return RealSpec::fixed(number(v, path));
  }
  IntSpec size_spec(const json& v, const Path& path) const {
    if (v.is_array()) {
      pair(v, path, "an integer or a range [min, max]");
      const int lo = size_value(v[0], path + "[0]"), hi = size_value(v[1], path + "[1]");
      if (lo > hi)
        fail(path, "range [" + std::to_string(lo) + ", " + std::to_string(hi) + "] is empty (min > max)");
      return IntSpec::uniform(lo, hi);
    }
    return IntSpec::fixed(size_value(v, path));
  }
  VecSpec vec_spec(const json& v, const Path& path) const {
    pair(v, path, "an array [x, y] of numbers or ranges [min, max]");
    return {real_spec(v[0], path + "[0]"), real_spec(v[1], path + "[1]")};
  }

 private:
  [[noreturn]] void range_fail(const Path& path, std::int64_t lo, std::int64_t hi, const std::string& v) const {
    fail(path, "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] (got " + v + ")");
  }
  const std::string& source_;
};

const json* find(const json& obj, const char* key) {
  const auto it = obj.find(key);
  return it == obj.end() ? nullptr : &*it;
}

void read_world(const Reader& r, const json& w, SceneSpec& s) {
  r.keys(w, "world",
         {"width", "height", "dt", "substeps", "gravity", "restitution", "friction", "walls", "systems", "ccd",
          "solver", "iterations", "integrator"});
  if (const json* v = find(w, "width")) s.width = static_cast<int>(r.integer(*v, "world.width", 1, max_world_size));
  if (const json* v = find(w, "height")) s.height = static_cast<int>(r.integer(*v, "world.height", 1, max_world_size));
  if (const json* v = find(w, "dt")) {
    s.params.dt = r.number(*v, "world.dt");  // > 0, <= max_dt: validate()
  }
  if (const json* v = find(w, "substeps"))
    s.params.substeps = static_cast<int>(r.integer(*v, "world.substeps", 1, max_substeps));
  if (const json* v = find(w, "gravity")) s.params.gravity = r.vec(*v, "world.gravity");
  if (const json* v = find(w, "restitution")) s.restitution = r.restitution(*v, "world.restitution");
  if (const json* v = find(w, "friction")) s.friction = r.number(*v, "world.friction");  // >= 0: validate()
  if (const json* v = find(w, "walls")) s.walls = r.boolean(*v, "world.walls");
  if (const json* v = find(w, "ccd")) s.params.ccd = r.boolean(*v, "world.ccd");
  if (const json* v = find(w, "solver")) {
    const std::string name = r.text(*v, "world.solver");
    const auto solver = solver_from_name(name);
    if (!solver) r.fail("world.solver", "must be \"course\", \"stable\" or \"auto\" (got " + r.got(*v) + ")");
    s.params.solver = *solver;
  }
  if (const json* v = find(w, "integrator")) {
    const auto i = integrator_from_name(r.text(*v, "world.integrator"));
    if (!i) r.fail("world.integrator", "must be \"course\" or \"exact\" (got " + r.got(*v) + ")");
    s.params.integrator = *i;
  }
  if (const json* v = find(w, "iterations"))
    s.params.iterations = static_cast<int>(r.integer(*v, "world.iterations", 1, max_iterations));
  if (const json* v = find(w, "systems")) {
    if (!v->is_array()) r.fail("world.systems", "must be an array of system names (got " + r.got(*v) + ")");
    SystemSet set{false, false, false, false};
    for (std::size_t i = 0; i < v->size(); ++i) {
      const Path systems = "world.systems", path(systems, i);
      const std::string name = r.text((*v)[i], path);
      const auto id = system_from_name(name);
      if (!id) r.fail(path, "unknown system " + quote(name) + "; expected draw, move, forces or collision");
      if (set.has(*id)) r.fail(path, "system " + quote(name) + " listed twice");
      set.set(*id, true);
    }
    s.systems = set;
  }
}

// The contact keys beyond the sheet, which blocks, grids and random
// generators share (docs/game-physics.md).
constexpr std::array<std::string_view, 5> contact_key_names{"friction", "category", "mask", "sensor", "one_way"};

Face face_named(const Reader& r, const json& v, const Path& path) {
  const std::string name = r.text(v, path);
  if (name == "up") return Face::up;
  if (name == "down") return Face::down;
  if (name == "left") return Face::left;
  if (name == "right") return Face::right;
  r.fail(path, "must be \"up\", \"down\", \"left\" or \"right\" (got " + r.got(v) + ")");
}

void read_contact_keys(const Reader& r, const json& b, const Path& p, ContactSpec& out) {
  constexpr std::int64_t bits = 0xFFFFFFFF;
  if (const json* v = find(b, "friction")) out.friction = r.number(*v, p + ".friction");  // >= 0: validate()
  if (const json* v = find(b, "category"))
    out.rules.category = static_cast<std::uint32_t>(r.integer(*v, p + ".category", 0, bits));
  if (const json* v = find(b, "mask")) out.rules.mask = static_cast<std::uint32_t>(r.integer(*v, p + ".mask", 0, bits));
  if (const json* v = find(b, "sensor")) out.rules.sensor = r.boolean(*v, p + ".sensor");
  if (const json* v = find(b, "one_way")) out.rules.one_way = face_named(r, *v, p + ".one_way");
}

// `base` and the contact keys.
std::vector<std::string_view> with_contact_keys(std::initializer_list<std::string_view> base) {
  std::vector<std::string_view> out(base);
  out.insert(out.end(), contact_key_names.begin(), contact_key_names.end());
  return out;
}

// The keys a block and a grid share: everything but the placement.
void read_block_keys(const Reader& r, const json& b, const Path& p, BlockSpec& out) {
  const json* pos = find(b, "pos");
  const json* size = find(b, "size");
  const json* mass = find(b, "mass");
  if (!pos) r.fail(p, "missing key \"pos\" (the top-left corner [x, y], px)");
  if (!size) r.fail(p, "missing key \"size\" ([width, height], px)");
  if (!mass) r.fail(p, "missing key \"mass\" (a number > 0, or \"inf\" for a fixed body)");
  out.pos = r.vec(*pos, p + ".pos");
  r.pair(*size, p + ".size", "an array of two integers [width, height]");
  out.width = r.size_value((*size)[0], p + ".size[0]");
  out.height = r.size_value((*size)[1], p + ".size[1]");
  out.mass = r.mass(*mass, p + ".mass");
  if (const json* v = find(b, "velocity")) out.velocity = r.vec(*v, p + ".velocity");
  if (const json* v = find(b, "force")) out.force = r.vec(*v, p + ".force");
  if (const json* v = find(b, "impulse")) out.impulse = r.vec(*v, p + ".impulse");
  if (const json* v = find(b, "color")) out.color = r.color(*v, p + ".color");
  if (const json* v = find(b, "restitution")) out.restitution = r.restitution(*v, p + ".restitution");
  if (const json* v = find(b, "tag")) out.tag = r.text(*v, p + ".tag");  // its characters: validate()
  if (const json* v = find(b, "strength")) out.strength = r.number(*v, p + ".strength");  // > 0: validate()
  if (const json* v = find(b, "travel")) out.travel = r.number(*v, p + ".travel");  // > 0: validate()
  if (const json* v = find(b, "travel_from")) out.travel_from = r.vec(*v, p + ".travel_from");
  if (const json* v = find(b, "travel_dir")) out.travel_dir = r.vec(*v, p + ".travel_dir");  // unit: validate()
  read_contact_keys(r, b, p, out.contact);
}

// "game": {"kind": "platformer" | "targets", "shots": N, "next": "level2.json"}
GameSpec read_game(const Reader& r, const json& g) {
  if (!g.is_object()) r.fail("game", "must be an object {\"kind\": ...} (got " + r.got(g) + ")");
  r.keys(g, "game", {"kind", "shots", "next"});
  GameSpec out;
  const json* kind = find(g, "kind");
  if (!kind) r.fail("game", "missing key \"kind\" (\"platformer\" or \"targets\")");
  out.kind = r.text(*kind, "game.kind");  // one of the games: validate()
  if (const json* v = find(g, "shots"))  // in [1, 99]: validate()
    out.shots = static_cast<int>(r.integer(*v, "game.shots", std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
  if (const json* v = find(g, "next")) out.next = r.text(*v, "game.next");
  return out;
}

BlockSpec read_block(const Reader& r, const json& b, const Path& p) {
  r.keys(b, p,
         with_contact_keys({"pos", "size", "mass", "velocity", "force", "impulse", "color", "restitution", "tag", "strength",
                            "travel", "travel_from", "travel_dir"}));
  BlockSpec out;
  read_block_keys(r, b, p, out);
  return out;
}

GridSpec read_grid(const Reader& r, const json& g, const Path& p) {
  r.keys(g, p,
         with_contact_keys({"pos", "size", "mass", "velocity", "force", "impulse", "color", "restitution", "count", "step",
                            "tag", "strength", "travel", "travel_from", "travel_dir"}));
  GridSpec out;
  read_block_keys(r, g, p, out.first);
  const json* count = find(g, "count");
  if (!count) r.fail(p, "missing key \"count\" ([columns, rows])");
  r.pair(*count, p + ".count", "an array of two integers [columns, rows]");
  out.columns = static_cast<int>(r.integer((*count)[0], p + ".count[0]", 1, max_bodies));
  out.rows = static_cast<int>(r.integer((*count)[1], p + ".count[1]", 1, max_bodies));
  // Default step: the block's size, so the blocks touch.
  out.step = {static_cast<double>(out.first.width), static_cast<double>(out.first.height)};
  if (const json* v = find(g, "step")) out.step = r.vec(*v, p + ".step");
  return out;
}

RandomSpec read_random(const Reader& r, const json& g, const Path& p) {
  r.keys(g, p,
         with_contact_keys(
             {"count", "side", "size", "mass", "velocity", "force", "impulse", "restitution", "color", "cells", "area"}));
  RandomSpec out;
  read_contact_keys(r, g, p, out.contact);
  const json* count = find(g, "count");
  if (!count) r.fail(p, "missing key \"count\" (the number of blocks)");
  out.count = r.integer(*count, p + ".count", 1, max_bodies);
  const json* side = find(g, "side");
  const json* size = find(g, "size");
  if (side && size) r.fail(p, "give \"side\" (square blocks) or \"size\", not both");
  if (!side && !size) r.fail(p, "missing key \"size\" ([width, height]) or \"side\" (square blocks)");
  if (side) {
    out.side = r.size_spec(*side, p + ".side");
  } else {
    r.pair(*size, p + ".size", "an array [width, height] of integers or ranges [min, max]");
    out.width = r.size_spec((*size)[0], p + ".size[0]");
    out.height = r.size_spec((*size)[1], p + ".size[1]");
  }
  const json* mass = find(g, "mass");
  if (!mass) r.fail(p, "missing key \"mass\" (a number > 0, a range [min, max], or \"inf\")");
  if (mass->is_array()) {
    out.mass = r.real_spec(*mass, p + ".mass");
  } else {
    out.mass = RealSpec::fixed(r.mass(*mass, p + ".mass"));
  }
  if (const json* v = find(g, "velocity")) out.velocity = r.vec_spec(*v, p + ".velocity");
  if (const json* v = find(g, "force")) out.force = r.vec_spec(*v, p + ".force");
  if (const json* v = find(g, "impulse")) out.impulse = r.vec_spec(*v, p + ".impulse");
  if (const json* v = find(g, "restitution")) {
    out.restitution = r.real_spec(*v, p + ".restitution");  // in [0, 1]: validate()
  }
  if (const json* v = find(g, "color"); v && !(v->is_string() && v->get<std::string>() == "random"))
    out.color = r.color(*v, p + ".color");
  const json* cells = find(g, "cells");
  const json* area = find(g, "area");
  if (cells && area) r.fail(p, "give \"cells\" or \"area\", not both");
  if (cells) {
    const Path c = p + ".cells";
    r.keys(*cells, c, {"pos", "columns", "step", "jitter"});
    out.use_cells = true;
    for (const char* k : {"pos", "columns", "step"})
      if (!find(*cells, k)) r.fail(c, std::string("missing key \"") + k + "\"");
    out.origin = r.vec(cells->at("pos"), c + ".pos");
    out.columns = static_cast<int>(r.integer(cells->at("columns"), c + ".columns", 1, max_bodies));
    out.step = r.vec(cells->at("step"), c + ".step");
    if (const json* v = find(*cells, "jitter")) {
      out.jitter = r.vec(*v, c + ".jitter");  // >= 0: validate()
    }
  } else {
    // Default area: the inside of the walls, or the whole world, set by
    // read_scene once the world is read (NaN here: a file's numbers are finite).
    out.use_cells = false;
    out.origin = out.extent = Vector{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    if (area) {
      const Path a = p + ".area";
      r.keys(*area, a, {"pos", "size"});
      if (const json* v = find(*area, "pos")) out.origin = r.vec(*v, a + ".pos");
      if (const json* v = find(*area, "size")) out.extent = r.vec(*v, a + ".size");
    }
  }
  return out;
}

// The rows of a saved state's list of pairs (`shape`, e.g. "[c, b, substeps]",
// `length` numbers each): f(row, its path, the pair it names), after the
// shape and the two ids are checked.
template <class F>
void read_pair_rows(const Reader& r, const json* list, const char* name, std::size_t length, const char* shape,
                    F&& f) {
  if (!list) return;
  if (!list->is_array()) r.fail(name, "must be an array (got " + r.got(*list) + ")");
  const Path path = name;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const json& e = (*list)[i];
    const Path p(path, i);
    if (!e.is_array() || e.size() != length) r.fail(p, std::string("must be ") + shape + " (got " + r.got(e) + ")");
    const auto id = [&](std::size_t k) { return static_cast<EntityId>(r.integer(e[k], p, 0, max_bodies + 4)); };
    f(e, p, Pair{id(0), id(1)});
  }
}

// The auto mode's state: {"hold": n, "pressed": [[c, b, substeps], ...]}.
AutoState read_auto_state(const Reader& r, const json& v) {
  r.keys(v, "state.auto", {"hold", "pressed"});
  AutoState out;
  if (const json* h = find(v, "hold")) out.hold = static_cast<int>(r.integer(*h, "state.auto.hold", 0, AutoMode::hold));
  read_pair_rows(r, find(v, "pressed"), "state.auto.pressed", 3, "[c, b, substeps]",
                 [&](const json& e, const Path& p, Pair pair) {
                   out.pressed.push_back({pair, static_cast<int>(r.integer(e[2], p, 1, 1 << 30))});
                 });
  return out;
}

// A saved world's "state": {"frame": n, "warm_start": [[c, b, axis, jn, jt], ...], "auto": {...}}.
SavedState read_state(const Reader& r, const json& v) {
  r.keys(v, "state", {"frame", "warm_start", "auto"});
  SavedState out;
  if (const json* a = find(v, "auto")) out.automatic = read_auto_state(r, *a);
  if (const json* f = find(v, "frame")) out.frame = r.integer(*f, "state.frame", 0, max_frames);
  read_pair_rows(r, find(v, "warm_start"), "state.warm_start", 5, "[c, b, axis, jn, jt]",
                 [&](const json& e, const Path& p, Pair pair) {
                   out.warm_start.push_back(
                       {pair, static_cast<int>(r.integer(e[2], p, 0, 3)), r.number(e[3], p), r.number(e[4], p)});
                 });
  return out;
}

BlockEntry read_entry(const Reader& r, const json& e, const Path& p) {
  r.object(e, p);
  const bool grid = e.contains("grid"), random = e.contains("random");
  if (grid && random) r.fail(p, "an entry is a \"grid\" or a \"random\" generator, not both");
  if (grid) {
    r.keys(e, p, {"grid"});
    return read_grid(r, e["grid"], p + ".grid");
  }
  if (random) {
    r.keys(e, p, {"random", "seed"});
    RandomSpec out = read_random(r, e["random"], p + ".random");
    if (const json* v = find(e, "seed")) out.seed = r.seed(*v, p + ".seed");
    return out;
  }
  return read_block(r, e, p);
}

std::string stem(const std::string& source) {
  std::string name = std::filesystem::path(source).stem().string();
  return name.empty() ? "scene" : name;
}

}  // namespace

TextPos line_column(std::string_view text, std::size_t position) {
  // position counts the characters read, the offending one included.
  const std::size_t at = std::min(position == 0 ? 0 : position - 1, text.size());
  TextPos p;
  for (std::size_t i = 0; i < at; ++i) {
    if (text[i] == '\n') {
      ++p.line;
      p.column = 1;
    } else {
      ++p.column;
    }
  }
  return p;
}

SceneSpec read_scene(std::string_view text, const std::string& source) {
  const Reader r(source);
  SceneSpec s;
  // The blocks are read as the parser completes each one. Their first error
  // is kept and raised after the checks that come before the blocks (syntax
  // anywhere in the file, top-level keys, world), as if the file were read
  // whole first.
  std::optional<SceneError> block_error;
  // Room for the blocks up front: an entry is large (a variant of the three
  // kinds), and growing the vector moves each one again. Every block and
  // grid has a "pos" key, so their count bounds the entries of a plain file;
  // capped, so a file of nothing but "pos" reserves little.
  std::size_t entries = 0;
  for (auto at = text.find("\"pos\""); at != std::string_view::npos && entries < (1u << 17); at = text.find("\"pos\"", at + 5))
    ++entries;
  s.blocks.reserve(entries);
  StrictDom dom;
  const Path blocks = "blocks";
  dom.on_plain_block = [&](BlockSpec&& b, std::size_t) {
    if (!block_error) s.blocks.push_back(std::move(b));
  };
  dom.on_block = [&](const json& e, std::size_t i) {
    if (block_error) return;
    try {
      s.blocks.push_back(read_entry(r, e, Path(blocks, i)));
    } catch (const SceneError& err) {
      block_error = err;
    }
  };
  // Comments (// and /* */) are allowed: scene files are written by hand.
  const bool ok = json::sax_parse(text, &dom, json::input_format_t::json, true, true);
  if (!ok || !dom.error.empty()) {
    if (dom.position > 0) {
      const TextPos p = line_column(text, dom.position);
      throw SceneError(source + ":" + std::to_string(p.line) + ":" + std::to_string(p.column) +
                       ": invalid JSON: " + dom.error);
    }
    throw SceneError(source + ": " + (dom.error.empty() ? std::string("invalid JSON") : dom.error));
  }
  const json& doc = dom.root;
  if (!doc.is_object()) r.fail("", "a scene file must hold one JSON object {...} (got " + r.got(doc) + ")");
  r.keys(doc, "", {"name", "description", "world", "blocks", "state", "game", "style"});
  s.name = stem(source);
  if (const json* v = find(doc, "name")) s.name = r.text(*v, "name");
  if (const json* v = find(doc, "description")) s.description = r.text(*v, "description");
  if (const json* v = find(doc, "world")) read_world(r, *v, s);
  if (const json* v = find(doc, "state")) s.state = read_state(r, *v);
  if (const json* v = find(doc, "game")) s.game = read_game(r, *v);
  if (const json* v = find(doc, "style")) {
    const auto style = style_from_name(r.text(*v, "style"));
    if (!style) r.fail("style", "must be \"plain\", \"speed\" or \"sprite\" (got " + r.got(*v) + ")");
    s.style = *style;
  }
  if (const json* v = find(doc, "blocks"); v && !v->is_array())
    r.fail("blocks", "must be an array of blocks (got " + r.got(*v) + ")");
  if (block_error) throw *block_error;
  // Random generators without an area take the inside of the walls, or the whole world.
  const double t = s.walls ? wall_thickness : 0;
  for (BlockEntry& e : s.blocks)
    if (auto* g = std::get_if<RandomSpec>(&e); g && !g->use_cells) {
      if (std::isnan(g->origin.x)) g->origin = {t, t};
      if (std::isnan(g->extent.x)) g->extent = {s.width - 2 * t, s.height - 2 * t};
    }
  return s;
}

SceneSpec parse_scene(std::string_view text, const std::string& source) {
  SceneSpec s = read_scene(text, source);
  expand(s, source);  // the validation (scene.hpp), placement included
  return s;
}

SceneSpec read_scene_file(const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status))
    throw SceneError(path + ": cannot read the scene file: no such file");
  if (std::filesystem::is_directory(status)) throw SceneError(path + ": cannot read the scene file: it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot read the scene file: " + std::strerror(errno));
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec && size > max_file_size)
    throw SceneError(path + ": cannot read the scene file: larger than " + std::to_string(max_file_size >> 20) + " MB");
  // Read at once into a string of the file's size (a stream, then a copy,
  // doubled the work on a large scene); grown by the loop if it was not known.
  std::string text(ec ? 0 : static_cast<std::size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  for (char buf[65536]; in && !in.eof();) {
    in.read(buf, sizeof buf);
    text.append(buf, static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw SceneError(path + ": cannot read the scene file: read error");
  SceneSpec s = read_scene(text, path);
  // A game's next level is named relative to this file's folder; it must be
  // there now, not only once this level is won.
  if (!s.game.next.empty()) {
    s.game.next_path = (std::filesystem::path(path).parent_path() / s.game.next).string();
    if (!std::filesystem::is_regular_file(s.game.next_path, ec))
      throw SceneError(path + ": game.next: no scene file " + s.game.next_path);
  }
  return s;
}

SceneSpec load_scene_file(const std::string& path) {
  SceneSpec s = read_scene_file(path);
  expand(s, path);  // the validation (scene.hpp), placement included
  return s;
}

// ---------------------------------------------------------------------------
// Writing.

namespace {

using ojson = nlohmann::ordered_json;

std::string hex(Color c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
  return buf;
}
ojson vec(Vector v) { return ojson::array({v.x, v.y}); }
ojson mass(double m) { return std::isfinite(m) ? ojson(m) : ojson("inf"); }
ojson real(const RealSpec& r) { return r.drawn ? ojson::array({r.lo, r.hi}) : ojson(r.lo); }
ojson integer(const IntSpec& r) { return r.drawn ? ojson::array({r.lo, r.hi}) : ojson(r.lo); }
ojson vec(const VecSpec& v) { return ojson::array({real(v.x), real(v.y)}); }
bool zero(const VecSpec& v) { return v == VecSpec{}; }

// Only the keys that differ from their defaults.
void contact_keys(ojson& o, const ContactSpec& c) {
  static constexpr const char* faces[] = {"none", "up", "down", "left", "right"};
  const ContactRules plain;
  if (c.friction) o["friction"] = *c.friction;
  if (c.rules.category != plain.category) o["category"] = c.rules.category;
  if (c.rules.mask != plain.mask) o["mask"] = c.rules.mask;
  if (c.rules.sensor) o["sensor"] = true;
  if (c.rules.one_way != Face::none) o["one_way"] = faces[static_cast<int>(c.rules.one_way)];
}

void block_keys(ojson& o, const BlockSpec& b) {
  o["pos"] = vec(b.pos);
  o["size"] = ojson::array({b.width, b.height});
  o["mass"] = mass(b.mass);
  if (!Vector::is_zero(b.velocity)) o["velocity"] = vec(b.velocity);
  if (!Vector::is_zero(b.force)) o["force"] = vec(b.force);
  if (!Vector::is_zero(b.impulse)) o["impulse"] = vec(b.impulse);
  if (!(b.color == default_block_color)) o["color"] = hex(b.color);
  if (b.restitution) o["restitution"] = *b.restitution;
  contact_keys(o, b.contact);
  if (!b.tag.empty()) o["tag"] = b.tag;
  if (b.strength) o["strength"] = *b.strength;
  if (b.travel) o["travel"] = *b.travel;
  if (b.travel_from) o["travel_from"] = vec(*b.travel_from);
  if (b.travel_dir) o["travel_dir"] = vec(*b.travel_dir);
}

ojson entry(const BlockEntry& e) {
  ojson o = ojson::object();
  if (const auto* b = std::get_if<BlockSpec>(&e)) block_keys(o, *b);
  if (const auto* g = std::get_if<GridSpec>(&e)) {
    ojson grid = ojson::object();
    block_keys(grid, g->first);
    grid["count"] = ojson::array({g->columns, g->rows});
    grid["step"] = vec(g->step);
    o["grid"] = grid;
  }
  if (const auto* r = std::get_if<RandomSpec>(&e)) {
    ojson gen = ojson::object();
    gen["count"] = r->count;
    if (r->side) gen["side"] = integer(*r->side);
    else gen["size"] = ojson::array({integer(r->width), integer(r->height)});
    gen["mass"] = r->mass.drawn ? real(r->mass) : mass(r->mass.lo);
    if (!zero(r->velocity)) gen["velocity"] = vec(r->velocity);
    if (!zero(r->force)) gen["force"] = vec(r->force);
    if (!zero(r->impulse)) gen["impulse"] = vec(r->impulse);
    if (r->restitution) gen["restitution"] = real(*r->restitution);
    contact_keys(gen, r->contact);
    gen["color"] = r->color ? ojson(hex(*r->color)) : ojson("random");
    if (r->use_cells) {
      gen["cells"] = {{"pos", vec(r->origin)}, {"columns", r->columns}, {"step", vec(r->step)},
                      {"jitter", vec(r->jitter)}};
    } else {
      gen["area"] = {{"pos", vec(r->origin)}, {"size", vec(r->extent)}};
    }
    o["random"] = gen;
    o["seed"] = r->seed;
  }
  return o;
}

// nlohmann's dump(2), except that a short array of numbers or strings (a
// position, a size, a range, the systems) stays on one line: [100, 200].
void write_pretty(const ojson& j, int indent, std::string& out) {
  constexpr std::size_t max_inline = 8;
  const std::string pad(static_cast<std::size_t>(indent) + 2, ' ');
  const bool flat = std::all_of(j.begin(), j.end(), [](const ojson& e) { return e.is_primitive(); });
  if (j.is_array() && (j.empty() || (flat && j.size() <= max_inline))) {
    out += '[';
    for (std::size_t i = 0; i < j.size(); ++i) out += (i ? ", " : "") + j[i].dump();
    out += ']';
  } else if (j.is_array()) {
    out += "[\n";
    for (std::size_t i = 0; i < j.size(); ++i) {
      out += (i ? ",\n" : "") + pad;
      write_pretty(j[i], indent + 2, out);
    }
    out += "\n" + std::string(static_cast<std::size_t>(indent), ' ') + ']';
  } else if (j.is_object() && !j.empty()) {
    out += "{\n";
    bool first = true;
    for (const auto& [key, value] : j.items()) {
      out += (first ? "" : ",\n") + pad + ojson(key).dump() + ": ";
      first = false;
      write_pretty(value, indent + 2, out);
    }
    out += "\n" + std::string(static_cast<std::size_t>(indent), ' ') + '}';
  } else {
    out += j.dump();
  }
}

}  // namespace

std::string to_json(const SceneSpec& s) {
  ojson o = ojson::object();
  o["name"] = s.name;
  if (!s.description.empty()) o["description"] = s.description;
  ojson systems = ojson::array();
  for (const SystemId id : all_systems)
    if (s.systems.has(id)) systems.push_back(std::string(name(id)));
  o["world"] = {{"width", s.width},
                {"height", s.height},
                {"dt", s.params.dt},
                {"substeps", s.params.substeps},
                {"gravity", vec(s.params.gravity)},
                {"restitution", s.restitution},
                {"walls", s.walls},
                {"systems", systems},
                {"ccd", s.params.ccd},
                {"solver", std::string(name(s.params.solver))},
                {"iterations", s.params.iterations}};
  if (s.friction != 0.0) o["world"]["friction"] = s.friction;  // beyond the sheet: only when used
  if (s.params.integrator != Integrator::course) o["world"]["integrator"] = std::string(name(s.params.integrator));
  ojson blocks = ojson::array();
  for (const BlockEntry& e : s.blocks) blocks.push_back(entry(e));
  o["blocks"] = blocks;
  if (!s.game.kind.empty()) {
    o["game"] = {{"kind", s.game.kind}};
    if (s.game.kind == "targets") o["game"]["shots"] = s.game.shots;
    if (!s.game.next.empty()) o["game"]["next"] = s.game.next;
  }
  if (s.style != Style::plain) o["style"] = std::string(name(s.style));  // plain: today's files unchanged
  if (s.state) {
    ojson warm = ojson::array();
    for (const WarmImpulse& w : s.state->warm_start) warm.push_back({w.pair.c, w.pair.b, w.axis, w.jn, w.jt});
    o["state"] = {{"frame", s.state->frame}, {"warm_start", warm}};
    if (s.state->automatic) {
      ojson pressed = ojson::array();
      for (const AutoState::Run& r : s.state->automatic->pressed) pressed.push_back({r.pair.c, r.pair.b, r.substeps});
      o["state"]["auto"] = {{"hold", s.state->automatic->hold}, {"pressed", pressed}};
    }
  }
  std::string out;
  write_pretty(o, 0, out);
  return out + "\n";
}

}  // namespace physics
