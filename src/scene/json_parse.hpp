// The scene file parser, internal to src/scene: nlohmann's SAX parser with a
// handler (StrictDom) that builds the document like nlohmann's own DOM parser
// but rejects duplicate keys and deep nesting, keeps a syntax error's
// position, and hands each entry of the top-level "blocks" array over as soon
// as it is complete: a plain block read without a document (PlainBlock, the
// fast path of a large scene), anything else as a document that the typed
// reader (json_reader.hpp) words the errors of.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/json_reader.hpp"

namespace physics::scene_io {

inline constexpr std::size_t max_depth = 64;  // scene files need 5

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

}  // namespace physics::scene_io
