// Reads the keys of one JSON object of a preset document, rejecting unknown keys and wrong
// types. The first error wins; its message names the key's dotted path in the document.
#pragma once

#include <set>
#include <string>
#include <utility>

#include "json_format.hpp"

namespace ocean::preset::detail {

class ObjectReader {
 public:
  ObjectReader(const Json& object, std::string path) : object_(object), path_(std::move(path)) {
    if (!object_.is_object()) error_ = invalid_argument(where() + ": expected an object");
  }
  // Numbers; null leaves `out` unset (NaN) when allow_null.
  void number(const char* key, double& out, bool allow_null = false) {
    const Json* v = find(key);
    if (v == nullptr) return;
    if (v->is_null() && allow_null) {
      out = kUnset;
    } else if (v->is_number()) {
      out = v->get<double>();
    } else {
      fail(key, "expected a number");
    }
  }
  void integer(const char* key, long long& out) {
    const Json* v = find(key);
    if (v == nullptr) return;
    if (v->is_number_integer() || v->is_number_unsigned()) {
      out = v->get<long long>();
    } else {
      fail(key, "expected an integer");
    }
  }
  void boolean(const char* key, bool& out) {
    const Json* v = find(key);
    if (v == nullptr) return;
    if (v->is_boolean())
      out = v->get<bool>();
    else
      fail(key, "expected true or false");
  }
  void string(const char* key, std::string& out) {
    const Json* v = find(key);
    if (v == nullptr) return;
    if (v->is_string())
      out = v->get<std::string>();
    else
      fail(key, "expected a string");
  }
  const Json* child(const char* key) { return find(key); }
  [[nodiscard]] std::string path_of(const char* key) const { return join(key); }
  void fail(const char* key, const std::string& what) {
    if (error_.ok()) error_ = invalid_argument(join(key) + ": " + what + ", got " + type_of(key));
  }
  void adopt(const Status& s) {
    if (error_.ok() && !s.ok()) error_ = s;
  }
  Status finish() {
    if (!error_.ok() || !object_.is_object()) return error_;
    for (const auto& [key, value] : object_.items()) {
      if (!seen_.contains(key))
        return invalid_argument(join(excerpt(key).c_str()) + ": unknown key");
    }
    return error_;
  }

 private:
  const Json* find(const char* key) {
    seen_.insert(key);
    if (!object_.is_object()) return nullptr;
    const auto it = object_.find(key);
    return it == object_.end() ? nullptr : &*it;
  }
  std::string join(const char* key) const { return path_.empty() ? key : path_ + "." + key; }
  std::string where() const { return path_.empty() ? "the document" : path_; }
  std::string type_of(const char* key) const {
    const auto it = object_.find(key);
    return it == object_.end() ? "nothing" : std::string("a ") + it->type_name();
  }
  const Json& object_;
  std::string path_;
  std::set<std::string> seen_;
  Status error_;
};

}  // namespace ocean::preset::detail
