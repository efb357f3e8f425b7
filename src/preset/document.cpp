// Presets assembled in layers and the built-in presets by name (see ocean/preset.hpp).
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "json_format.hpp"
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
    return invalid_argument(std::string(label) + " = " + path.string() +
                            " is neither a file nor a preset: must be " + builtin_list() +
                            " or a JSON file");
  }
  std::ifstream in(path);
  if (!in) {
    return io_error("cannot read preset '" + path.string() + "': " + std::strerror(errno));
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  Json doc = Json::parse(buffer.str(), nullptr, false);
  if (doc.is_discarded()) {
    return invalid_argument("preset '" + path.string() + "' is not valid JSON");
  }
  return doc;
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
    return invalid_argument("preset '" + std::string(name) + "' is unknown: must be " +
                            builtin_list());
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

Status Document::merge_preset(std::string_view name_or_path, std::string_view label) {
  Result<Json> preset = read_preset(name_or_path, label);
  if (!preset.ok()) return preset.status();
  impl_->document.merge_patch(preset.value());
  return {};
}

Status Document::set(std::string_view assignment_text, std::string_view label_text) {
  const std::string assignment(assignment_text), label(label_text);
  const std::size_t eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    return invalid_argument(label + " '" + assignment + "': expected key=value");
  }
  const std::string key = assignment.substr(0, eq);
  const std::string text = assignment.substr(eq + 1);
  Json value = Json::parse(text, nullptr, false);
  if (value.is_discarded()) value = text;  // a bare string: normals=analytic
  Json* node = &impl_->document;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = key.find('.', start);
    const std::string part =
        key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (part.empty()) return invalid_argument(label + " '" + assignment + "': empty key part");
    if (!node->is_object())
      return invalid_argument(label + " " + key + ": '" + part + "' is not inside an object");
    if (dot == std::string::npos) {
      (*node)[part] = value;
      return {};
    }
    Json& next = (*node)[part];
    if (next.is_null()) next = Json::object();
    node = &next;
    start = dot + 1;
  }
}

Result<SimulationConfig> Document::config() const { return detail::from_value(impl_->document); }

}  // namespace ocean::preset
