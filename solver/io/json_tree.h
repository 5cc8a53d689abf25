// Private to solver/io: reading JSON text into a tree while refusing, by place, what a plain parse
// accepts silently (duplicate keys, numbers that overflow to infinity, nesting deep enough to
// exhaust the stack of a recursive consumer). Templated on the JSON type so that this header does
// not name the JSON library, a private dependency of linkage_io (the .cpp files instantiate it with
// the library's ordered_json).
#pragma once

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <string>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <vector>

namespace linkage::json_tree {

constexpr std::size_t kMaxDepth = 256;

// Cut at a UTF-8 character boundary, so that a message stays valid text.
inline std::string shortened(std::string text, std::size_t max) {
  if (text.size() <= max) return text;
  std::size_t cut = max - 3;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  return text.substr(0, cut) + "...";
}

// A JSON string literal for messages; long ones are cut, they only have to be recognisable.
template <class Json>
std::string literal(std::string_view s) {
  return Json(shortened(std::string(s), 60)).dump(-1, ' ', false, Json::error_handler_t::replace);
}

// `path.key`, or `path["odd key"]` when the key would make the path ambiguous to read.
template <class Json>
std::string member(const std::string& path, const std::string& key) {
  bool plain = !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' ||
           static_cast<unsigned char>(c) >= 0x80;
  });
  if (!plain) return path + "[" + literal<Json>(key) + "]";
  return path.empty() ? key : path + "." + key;
}

// ordered_json's operator[] searches the members linearly; where a key is known to be new,
// appending directly keeps objects with many members (a body with thousands of points) linear.
template <class Json>
Json& appendMember(Json& obj, const std::string& key, Json value) {
  auto& members = static_cast<typename Json::object_t::Container&>(
      obj.template get_ref<typename Json::object_t&>());
  members.emplace_back(key, std::move(value));
  return members.back().second;
}

// The SAX handler: builds the tree like the library's own DOM parser, with the checks above.
template <class Json>
class Builder {
 public:
  Json root;
  std::string error;

  bool null() { return value(nullptr); }
  bool boolean(bool v) { return value(v); }
  bool number_integer(typename Json::number_integer_t v) { return value(v); }
  bool number_unsigned(typename Json::number_unsigned_t v) { return value(v); }
  bool number_float(typename Json::number_float_t v, const std::string&) { return value(v); }
  bool string(std::string& v) { return value(std::move(v)); }
  bool binary(typename Json::binary_t&) { return value(nullptr); }  // not in JSON text
  bool start_object(std::size_t) { return open(Json::object()); }
  bool start_array(std::size_t) { return open(Json::array()); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool key(std::string& k) {
    Frame& f = frames_.back();
    if (!f.keys.insert(k).second) {
      error = pathOf(frames_.size() - 1) + ": duplicate key " + literal<Json>(k);
      return false;
    }
    f.key = k;
    slot_ = &appendMember(*f.node, k, Json());
    return true;
  }

  template <class Exception>
  bool parse_error(std::size_t position, const std::string& token, const Exception& ex) {
    if (ex.id == 406) {  // number overflow: the lexer read 1e999 or a 400-digit integer
      error = pathOf(frames_.size()) + ": " + shortened(token, 40) + " is not a finite number";
      return false;
    }
    // "[json.exception.parse_error.101] parse error at line 3, column 5: syntax error ..."; the
    // "last read: '...'" at its end can quote a whole unterminated string, hence the cut.
    std::string what = ex.what();
    std::size_t at = what.find(" at line ");
    if (at != std::string::npos) {
      error = shortened(what.substr(at + 4), 300);
    } else {
      std::size_t bracket = what.find("] ");
      error = "byte " + std::to_string(position) + ": " +
              shortened(bracket == std::string::npos ? what : what.substr(bracket + 2), 300);
    }
    return false;
  }

 private:
  struct Frame {
    Json* node;
    bool isArray;
    std::size_t index = 0;  // of the element being read, in an array
    std::string key;        // of the member being read, in an object
    std::unordered_set<std::string> keys;
  };
  std::vector<Frame> frames_;
  Json* slot_ = nullptr;  // the member created by the last key()

  // Path of the value being read at nesting depth `depth` (0 = the top level).
  std::string pathOf(std::size_t depth) const {
    std::string path;
    for (std::size_t i = 0; i < depth; ++i) {
      const Frame& f = frames_[i];
      path = f.isArray ? path + "[" + std::to_string(f.index) + "]" : member<Json>(path, f.key);
    }
    return path.empty() ? "top level" : path;
  }

  Json* place(Json&& v) {
    if (frames_.empty()) {
      root = std::move(v);
      return &root;
    }
    Frame& f = frames_.back();
    if (f.isArray) {
      f.node->push_back(std::move(v));
      return &f.node->back();
    }
    *slot_ = std::move(v);
    return slot_;
  }
  void finished() {
    if (!frames_.empty() && frames_.back().isArray) ++frames_.back().index;
  }
  bool value(Json&& v) {
    place(std::move(v));
    finished();
    return true;
  }
  bool open(Json&& v) {
    if (frames_.size() >= kMaxDepth) {
      error = shortened(pathOf(frames_.size()), 80) + ": nested deeper than " +
              std::to_string(kMaxDepth) + " levels";
      return false;
    }
    bool isArray = v.is_array();
    frames_.push_back(Frame{place(std::move(v)), isArray, 0, {}, {}});
    return true;
  }
  bool close() {
    frames_.pop_back();
    finished();
    return true;
  }
};

// The tree, or nullopt-like failure with `error` set: returns false and fills `error`.
template <class Json>
bool parse(std::string_view text, Json& out, std::string& error) {
  Builder<Json> builder;
  bool ok = Json::sax_parse(text.begin(), text.end(), &builder, Json::input_format_t::json,
                            /*strict=*/true, /*ignore_comments=*/false);
  if (!ok) {
    error = builder.error.empty() ? "not valid JSON" : std::move(builder.error);
    return false;
  }
  out = std::move(builder.root);
  return true;
}

}  // namespace linkage::json_tree
