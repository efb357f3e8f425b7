// Presets assembled in layers and the built-in presets by name (see ocean/preset.hpp).
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>

#include "json_format.hpp"
#include "ocean/io.hpp"
#include "ocean/preset.hpp"

namespace ocean::preset {

namespace {

using detail::builtin_presets;
using detail::BuiltinPreset;
using detail::Json;

// "calm, moderate, storm"
std::string builtin_list() {
  std::string list;
  for (const BuiltinPreset& p : builtin_presets()) {
    if (!list.empty()) list += ", ";
    list += p.name;
  }
  return list;
}

Result<Json> read_preset(std::string_view name_or_path, std::string_view label) {
  const std::filesystem::path path(name_or_path);
  // A bare name that is not a file selects a compiled-in preset.
  std::error_code ec;
  if (!path.has_parent_path() && !path.has_extension() && !std::filesystem::exists(path, ec)) {
    const std::string_view json = builtin_json(name_or_path);
    if (!json.empty()) return Json::parse(json);
    return invalid_argument(std::string(label) + " = " + excerpt(name_or_path) +
                            " is neither a file nor a preset: must be " + builtin_list() +
                            " or a JSON file");
  }
  Result<std::string> text = io::read_bounded(
      path, {.max_bytes = kMaxPresetBytes, .what = "preset", .fifo_wait_ms = kFifoWaitMs});
  if (!text.ok()) return text.status();
  detail::Parsed parsed = detail::parse_bounded(text.value(), kMaxPresetDepth);
  const std::string name = excerpt(path.string());
  if (parsed.outcome == detail::Parse::too_deep)
    return invalid_argument("preset '" + name + "' nests deeper than " +
                            std::to_string(kMaxPresetDepth) + " levels");
  if (parsed.outcome == detail::Parse::not_json)
    return invalid_argument("preset '" + name + "' is not valid JSON");
  return std::move(parsed.value);
}

// Merges `patch` into `target` key by key: an object merges into an object, any other value
// (null included) replaces. Unlike an RFC 7386 merge patch, null does not remove the key: in a
// preset, null is a value ("unset": no fetch, deep water, no swell; ocean/preset.hpp), and a
// removed key would fall back to SimulationConfig's default instead (a 100 km fetch where the
// file said none). So a file merged over the defaults reads as preset::from_json reads its text.
void merge_values(Json& target, const Json& patch) {
  for (const auto& [key, value] : patch.items()) {
    Json& slot = target[key];
    if (value.is_object() && slot.is_object()) {
      merge_values(slot, value);
    } else {
      slot = value;
    }
  }
}

}  // namespace

std::vector<std::string_view> builtin_names() {
  std::vector<std::string_view> names;
  for (const BuiltinPreset& p : builtin_presets()) names.push_back(p.name);
  return names;
}

std::string_view builtin_json(std::string_view name) {
  for (const BuiltinPreset& p : builtin_presets()) {
    if (p.name == name) return p.json;
  }
  return {};
}

Result<SimulationConfig> builtin(std::string_view name) {
  const std::string_view json = builtin_json(name);
  if (json.empty()) {
    return invalid_argument("preset '" + excerpt(name) + "' is unknown: must be " + builtin_list());
  }
  return from_json(json);
}

struct Document::Impl {
  Json document = detail::to_value(SimulationConfig{});
};

Document::Document() : impl_(std::make_unique<Impl>()) {}
Document::~Document() = default;
Document::Document(Document&&) noexcept = default;
Document& Document::operator=(Document&&) noexcept = default;
Document::Document(const Document& other) : impl_(std::make_unique<Impl>(*other.impl_)) {}
Document& Document::operator=(const Document& other) {
  if (this != &other) impl_ = std::make_unique<Impl>(*other.impl_);
  return *this;
}

Status Document::merge_preset(std::string_view name_or_path, std::string_view label) {
  Result<Json> preset = read_preset(name_or_path, label);
  if (!preset.ok()) return preset.status();
  // A preset document is an object (from_value reports anything else); a non-object replaces
  // the document whole, so that config() names what is wrong with it.
  if (preset.value().is_object() && impl_->document.is_object()) {
    merge_values(impl_->document, preset.value());
  } else {
    impl_->document = std::move(preset).value();
  }
  return {};
}

Status Document::set(std::string_view assignment, std::string_view label_text) {
  const std::string label(label_text);
  const auto fail = [&](const std::string& what) {
    return invalid_argument(label + " '" + excerpt(assignment) + "': " + what);
  };
  const std::size_t eq = assignment.find('=');
  if (eq == std::string_view::npos || eq == 0) return fail("expected key=value");
  const std::string_view key = assignment.substr(0, eq);
  const std::string_view text = assignment.substr(eq + 1);
  if (key.size() > kMaxKeyBytes)
    return fail("the key is " + std::to_string(key.size()) + " bytes: must be at most " +
                std::to_string(kMaxKeyBytes));
  if (text.size() > kMaxValueBytes)
    return fail("the value is " + std::to_string(text.size()) + " bytes: must be at most " +
                std::to_string(kMaxValueBytes));
  // The document stays within kMaxPresetDepth: one level per part of the key, then the value's.
  const auto parts = static_cast<int>(std::count(key.begin(), key.end(), '.')) + 1;
  detail::Parsed parsed = detail::parse_bounded(text, std::max(0, kMaxPresetDepth - parts));
  if (parts > kMaxPresetDepth || parsed.outcome == detail::Parse::too_deep)
    return fail("nests deeper than " + std::to_string(kMaxPresetDepth) + " levels");
  // Not JSON: a bare string, as in normals=analytic.
  Json value = parsed.outcome == detail::Parse::ok ? std::move(parsed.value) : Json(text);
  Json* node = &impl_->document;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = key.find('.', start);
    const std::string part(
        key.substr(start, dot == std::string_view::npos ? key.npos : dot - start));
    if (part.empty()) return fail("empty key part");
    if (!node->is_object())
      return invalid_argument(label + " " + excerpt(key) + ": '" + excerpt(part) +
                              "' is not inside an object");
    if (dot == std::string_view::npos) {
      (*node)[part] = std::move(value);
      return {};
    }
    Json& next = (*node)[part];
    if (next.is_null()) next = Json::object();
    node = &next;
    start = dot + 1;
  }
}

Result<SimulationConfig> Document::config() const { return detail::from_value(impl_->document); }

Result<PictureSettings> Document::picture() const {
  return detail::picture_from_value(impl_->document);
}

}  // namespace ocean::preset
