#include "app/input_log.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>
#include <optional>
#include <ostream>
#include <string_view>

#include "engine/limits.hpp"
#include "scene/scene_json.hpp"

namespace physics {

namespace {

using Kind = InputEvent::Kind;

constexpr std::string_view header = "tick,kind,key,x,y,button";
constexpr std::string_view scene_prefix = "# scene: ";

// The names in the file; `end` is not an event but the last line.
constexpr std::array<std::pair<Kind, std::string_view>, 6> kind_names{{{Kind::key, "key"},
                                                                       {Kind::key_up, "key_up"},
                                                                       {Kind::mouse_down, "mouse_down"},
                                                                       {Kind::mouse_up, "mouse_up"},
                                                                       {Kind::mouse_move, "mouse_move"},
                                                                       {Kind::quit, "quit"}}};

std::string_view kind_name(Kind k) {
  for (const auto& [kind, name] : kind_names)
    if (kind == k) return name;
  return "?";
}

std::optional<Kind> kind_from(std::string_view s) {
  for (const auto& [kind, name] : kind_names)
    if (name == s) return kind;
  return std::nullopt;
}

// Reads the fields of one line and says which one is wrong, with the line.
class LineReader {
 public:
  LineReader(const std::string& name, std::size_t line) : where_(name + ":" + std::to_string(line) + ": ") {}

  [[noreturn]] void fail(const std::string& problem) const { throw InputLogError(where_ + problem); }

  template <class Int>
  Int integer(std::string_view field, const char* what) const {
    Int v{};
    const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), v);
    if (field.empty() || ec != std::errc{} || end != field.data() + field.size())
      fail(std::string(what) + " must be an integer (got '" + std::string(field) + "')");
    return v;
  }

 private:
  std::string where_;
};

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> fields;
  for (std::size_t from = 0;;) {
    const std::size_t comma = line.find(',', from);
    fields.push_back(line.substr(from, comma == std::string_view::npos ? std::string_view::npos : comma - from));
    if (comma == std::string_view::npos) return fields;
    from = comma + 1;
  }
}

}  // namespace

bool LoggedEvent::operator==(const LoggedEvent& o) const {
  return tick == o.tick && event.kind == o.event.kind && event.key == o.event.key && event.x == o.event.x &&
         event.y == o.event.y && event.button == o.event.button;
}

InputLog parse_input_log(std::string_view text, const std::string& name) {
  InputLog log;
  bool seen_header = false, ended = false;
  std::size_t n = 0;
  for (std::size_t from = 0; from < text.size();) {  // the lines, as std::getline reads them
    ++n;
    const std::size_t end = std::min(text.find('\n', from), text.size());
    std::string_view line = text.substr(from, end - from);
    from = end + 1;
    if (line.ends_with('\r')) line.remove_suffix(1);  // written on Windows
    if (line.find('\0') != std::string_view::npos) LineReader(name, n).fail("a NUL byte: an input log is text");
    if (line.starts_with(scene_prefix)) log.scene = std::string(line.substr(scene_prefix.size()));
    if (line.empty() || line.starts_with('#')) continue;
    const LineReader r(name, n);
    if (ended) r.fail("a line after the end line");
    if (!seen_header) {
      if (line != header) r.fail("expected the header '" + std::string(header) + "' (got '" + std::string(line) + "')");
      seen_header = true;
      continue;
    }
    const std::vector<std::string_view> f = split(line);
    if (f.size() != 6) r.fail("expected 6 fields tick,kind,key,x,y,button (got " + std::to_string(f.size()) + ")");
    const auto tick = r.integer<std::int64_t>(f[0], "tick");
    if (tick < 0 || tick > max_log_ticks)
      r.fail("tick must be in [0, " + std::to_string(max_log_ticks) + "] (got " + std::to_string(tick) + ")");
    const std::int64_t last = log.events.empty() ? 0 : log.events.back().tick;
    if (tick < last) r.fail("tick " + std::to_string(tick) + " is before the previous line's " + std::to_string(last));
    InputEvent e{Kind::quit};
    e.key = r.integer<int>(f[2], "key");
    e.x = r.integer<int>(f[3], "x");
    e.y = r.integer<int>(f[4], "y");
    e.button = r.integer<int>(f[5], "button");
    if (f[1] == "end") {
      log.end = tick;
      ended = true;
      continue;
    }
    const std::optional<Kind> kind = kind_from(f[1]);
    if (!kind)
      r.fail("unknown kind '" + std::string(f[1]) +
             "' (expected key, key_up, mouse_down, mouse_up, mouse_move, quit or end)");
    e.kind = *kind;
    log.events.push_back({tick, e});
  }
  if (!ended)
    throw InputLogError(name + ":" + std::to_string(n + 1) + ": missing the end line (tick,end,0,0,0,0)" +
                        (seen_header ? "" : " and the header"));
  return log;
}

InputLog read_input_log(const std::string& path) {
  std::string text;
  try {
    text = read_input_file(path, "input log");  // 64 MB at most, a device or a pipe too
  } catch (const SceneError& e) {
    throw InputLogError(e.what());
  }
  return parse_input_log(text, path);
}

void write_input_log(std::ostream& out, const InputLog& log) {
  out << "# physics input log v1\n";
  // A name on one line: a newline in it would make the rest a row.
  if (!log.scene.empty() && log.scene.find_first_of("\r\n") == std::string::npos)
    out << scene_prefix << log.scene << "\n";
  out << header << "\n";
  for (const auto& [tick, e] : log.events)
    out << tick << ',' << kind_name(e.kind) << ',' << e.key << ',' << e.x << ',' << e.y << ',' << e.button << '\n';
  out << log.end << ",end,0,0,0,0\n";
}

void write_input_log(const std::string& path, const InputLog& log) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot write the input log " + path + ": " + std::strerror(errno));
  write_input_log(out, log);
  out.flush();
  if (!out) throw std::runtime_error("cannot write the input log " + path);
}

}  // namespace physics
