// What the file readers share (model_file.cpp, forces_read.cpp): the JSON value type, refusals
// that name the place, and readers of fields that refuse anything else with what was found.
#pragma once

#include <span>

#include <climits>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "io/json_tree.h"
#include "linkage/model.h"

namespace linkage::json_read {

using Json = nlohmann::ordered_json;

inline std::string literal(std::string_view s) {
  return json_tree::literal<Json>(s);
}
inline std::string member(const std::string& path, const std::string& key) {
  return json_tree::member<Json>(path, key);
}

// Written the way the messages spell the expected shape: [x, y], [[x0, y0], [x1, y1]].
inline std::string inlineArray(const Json& v, int depth) {
  std::string text = "[";
  for (size_t i = 0; i < v.size() && text.size() <= 60; ++i) {
    const Json& e = v[i];
    text += i > 0 ? ", " : "";
    if (e.is_array())
      text += depth < 2 ? inlineArray(e, depth + 1) : "[...]";
    else if (e.is_object())
      text += "{...}";
    else
      text += e.dump(-1, ' ', false, Json::error_handler_t::replace);
  }
  return text + "]";
}

// What was found instead: scalars as written, containers by kind.
inline std::string describe(const Json& v) {
  switch (v.type()) {
    case Json::value_t::string:
      return literal(v.get_ref<const std::string&>());
    case Json::value_t::object:
      return v.empty() ? "an empty object" : "an object";
    case Json::value_t::array: {
      if (v.empty()) return "an empty array";
      std::string text = inlineArray(v, 0);
      return text.size() <= 60 ? text : "an array of " + std::to_string(v.size()) + " elements";
    }
    default:
      return v.dump();
  }
}

struct Refusal {
  std::string message;
};

[[noreturn]] inline void refuse(const std::string& path, const std::string& what) {
  throw Refusal{(path.empty() ? std::string("top level") : path) + ": " + what};
}

inline std::string element(const std::string& path, size_t i) {
  return path + "[" + std::to_string(i) + "]";
}

inline const Json* find(const Json& obj, const char* key) {
  auto it = obj.find(key);
  return it == obj.end() ? nullptr : &*it;
}

inline const Json& require(const Json& obj, const char* key, const std::string& path) {
  const Json* v = find(obj, key);
  if (!v) refuse(path, std::string("missing required field ") + literal(key));
  return *v;
}

inline void requireObject(const Json& v, const std::string& path) {
  if (!v.is_object()) refuse(path, "expected an object {...}, got " + describe(v));
}

inline const std::string& getString(const Json& v, const std::string& path) {
  if (!v.is_string()) refuse(path, "expected a string, got " + describe(v));
  return v.get_ref<const std::string&>();
}

inline double getNumber(const Json& v, const std::string& path, const char* expected = "a number") {
  // The reader refused non-finite values already; this guards hand-made trees.
  if (!v.is_number() || !std::isfinite(v.get<double>()))
    refuse(path, std::string("expected ") + expected + ", got " + describe(v));
  return v.get<double>();
}

// Integers must be written as such: 2.0 or 2e0 is refused rather than silently truncated.
inline long long getInteger(const Json& v, const std::string& path, const char* expected) {
  if (v.is_number_integer() && !v.is_number_unsigned()) return v.get<long long>();
  if (v.is_number_unsigned()) {
    auto u = v.get<unsigned long long>();
    return u > static_cast<unsigned long long>(LLONG_MAX) ? LLONG_MAX : static_cast<long long>(u);
  }
  refuse(path, std::string("expected ") + expected + ", got " + describe(v));
}

inline std::optional<Vec2> asPair(const Json& v) {
  if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number()) return {};
  Vec2 p(v[0].get<double>(), v[1].get<double>());
  if (!p.allFinite()) return {};
  return p;
}

// [x, y] or [x, y, third] with finite numbers; the third, when given, to `third`.
inline std::optional<Vec2> asPoint(const Json& v, std::optional<double>& third) {
  third.reset();
  if (v.is_array() && v.size() == 3) {
    if (!v[2].is_number() || !std::isfinite(v[2].get<double>())) return {};
    const Json xy = Json::array({v[0], v[1]});
    std::optional<Vec2> p = asPair(xy);
    if (p) third = v[2].get<double>();
    return p;
  }
  return asPair(v);
}

// Keys outside `known` in their original order, as compact JSON object text; "" when none.
inline Extras unknownFields(const Json& obj, std::span<const char* const> known) {
  Json extras = Json::object();
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    bool isKnown = false;
    for (const char* k : known) isKnown = isKnown || it.key() == k;
    if (!isKnown) json_tree::appendMember(extras, it.key(), it.value());
  }
  return extras.empty() ? Extras() : extras.dump();
}
inline Extras unknownFields(const Json& obj, std::initializer_list<const char*> known) {
  return unknownFields(obj, std::span<const char* const>(known.begin(), known.size()));
}

// References are "body.point" and names are checked to have no '.', so the first dot splits.
inline void checkName(const std::string& name, const std::string& path, const char* kind) {
  if (name.empty()) refuse(path, std::string("a ") + kind + " name may not be empty");
  if (name.find('.') != std::string::npos)
    refuse(path, std::string(kind) + " names may not contain '.' (references are \"body." +
                     (std::strcmp(kind, "slot") == 0 ? "slot" : "point") + "\"): " + literal(name));
}

}  // namespace linkage::json_read
