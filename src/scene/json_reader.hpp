// The typed reader of scene files, internal to src/scene: a key path built
// only for a message (Path), and a Reader whose every accessor takes a JSON
// value and its path and throws SceneError("source: path: problem") naming
// what was expected and what came; plus the few writers' helpers. Inline: a
// large scene's blocks pass thousands of these calls.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

// nlohmann's own invariant checks (assert, as the build has no NDEBUG) cost
// a tenth of the load of a large scene; only src/scene includes it, always
// through this header, so there is no other definition of its inline
// functions to disagree with.
#define JSON_ASSERT(x) static_cast<void>(0)
#include <nlohmann/json.hpp>

#include "engine/format.hpp"
#include "scene/scene.hpp"

namespace physics::scene_io {

using json = nlohmann::json;
using ojson = nlohmann::ordered_json;

inline std::size_t edit_distance(std::string_view a, std::string_view b) {
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

inline std::string quote(std::string_view s) {
  std::string out = "\"";
  for (const char c : s.substr(0, 60)) out += (c >= 32 && c < 127) ? c : '?';
  if (s.size() > 60) out += "...";
  return out + "\"";
}

inline std::string short_text(double v) { return format_g(v, 10); }

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

inline const json* find(const json& obj, const char* key) {
  const auto it = obj.find(key);
  return it == obj.end() ? nullptr : &*it;
}

// Writing: the shapes the reader takes.
inline std::string hex(Color c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
  return buf;
}
inline ojson vec(Vector v) { return ojson::array({v.x, v.y}); }
inline ojson mass_json(double m) { return std::isfinite(m) ? ojson(m) : ojson("inf"); }

}  // namespace physics::scene_io
