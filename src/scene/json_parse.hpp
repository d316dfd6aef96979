// The scene file parser, internal to src/scene: nlohmann's SAX parser with a
// handler (StrictDom) that builds the document like nlohmann's own DOM parser
// but rejects duplicate keys and deep nesting, keeps a syntax error's
// position, and hands each entry of the top-level "blocks" array over as soon
// as it is complete, as a document of its own that the typed reader
// (json_reader.hpp) reads, so that a large scene is never held whole.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/json_reader.hpp"
#include "scene/scene_json.hpp"

namespace physics::scene_io {

inline constexpr std::size_t max_depth = 64;  // scene files need 5

// ---------------------------------------------------------------------------
// Parsing: a SAX handler that builds the document like nlohmann's own DOM
// parser, but rejects duplicate keys (nlohmann keeps the last one silently)
// and nesting deeper than max_depth, and keeps the error's byte position.

class StrictDom : public nlohmann::json_sax<json> {
 public:
  json root;
  std::string error;          // set when the parse failed
  std::size_t position = 0;   // byte position of a syntax error, else 0

  bool null() override { return add(nullptr); }
  bool boolean(bool v) override { return add(v); }
  bool number_integer(number_integer_t v) override { return add(v); }
  bool number_unsigned(number_unsigned_t v) override { return add(v); }
  bool number_float(number_float_t v, const string_t&) override { return add(v); }
  bool string(string_t& v) override { return add(std::move(v)); }
  bool binary(binary_t&) override {
    error = "binary values are not JSON";
    return false;
  }
  bool start_object(std::size_t) override { return open(json::object()); }
  bool start_array(std::size_t) override {
    // Most arrays of a scene are pairs ([x, y], [w, h]): one allocation, not two.
    json a = json::array();
    a.get_ref<json::array_t&>().reserve(2);
    return open(std::move(a));
  }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }
  bool key(string_t& k) override {
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

// Parses `text` whole into dom (comments // and /* */ allowed: the files are
// written by hand), or throws SceneError "source:line:column: invalid JSON:
// ..." (or "source: ..." for an error without a position). A NUL byte is
// refused first: the parser stops at one as at the end of the text, so what
// follows it would be accepted unread. The one way a scene or map file's
// text becomes a document (scene_json.cpp, map.cpp).
inline void parse_strict(std::string_view text, const std::string& source, StrictDom& dom) {
  if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos) {
    const TextPos p = line_column(text, nul + 1);
    throw SceneError(source + ":" + std::to_string(p.line) + ":" + std::to_string(p.column) +
                     ": a NUL byte: a scene file is text");
  }
  const bool ok = json::sax_parse(text, &dom, json::input_format_t::json, true, true);
  if (ok && dom.error.empty()) return;
  if (dom.position > 0) {
    const TextPos p = line_column(text, dom.position);
    throw SceneError(source + ":" + std::to_string(p.line) + ":" + std::to_string(p.column) + ": invalid JSON: " +
                     dom.error);
  }
  throw SceneError(source + ": " + (dom.error.empty() ? std::string("invalid JSON") : dom.error));
}

}  // namespace physics::scene_io
