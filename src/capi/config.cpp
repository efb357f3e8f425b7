// src/capi/config.cpp — ocean_config: a preset document assembled in layers (ocean/preset.hpp),
// each change tried on a copy and kept only when the whole configuration is valid.
#include <cstring>
#include <span>

#include "capi_internal.hpp"
#include "ocean/io.hpp"

namespace ocean::capi {
namespace {

// The labels the `ocean` tool gives these inputs, so that messages read as its flags do.
constexpr std::string_view kPresetLabel = "--preset";
constexpr std::string_view kSetLabel = "--set";

// Applies `change` to a copy of the configuration's document; keeps it when it reads as a valid
// configuration, so that a failed call leaves the configuration as it was.
template <typename Change>
Status change_document(ocean_config& config, Change&& change) {
  preset::Document trial = config.document;
  if (Status s = change(trial); !s.ok()) return s;
  Result<SimulationConfig> parsed = trial.config();
  if (!parsed.ok()) return parsed.status();
  config.document = std::move(trial);
  config.config = std::move(parsed).value();
  return {};
}

// The built-in presets' names as NUL-terminated strings in static storage (the library's are
// views into larger literals). Empty if even this allocation fails.
const std::vector<std::string>& builtin_names_c() noexcept {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    try {
      for (std::string_view name : preset::builtin_names()) list.emplace_back(name);
    } catch (...) {
      list.clear();
    }
    return list;
  }();
  return names;
}

}  // namespace
}  // namespace ocean::capi

extern "C" {

using namespace ocean::capi;

OCEAN_API ocean_status ocean_config_create(ocean_config** out) {
  return guarded([&]() -> ocean::Status {
    if (ocean::Status s = require_not_null(out, "ocean_config_create", "out"); !s.ok()) return s;
    auto config = std::make_unique<ocean_config>();
    ocean::Result<ocean::SimulationConfig> parsed = config->document.config();
    if (!parsed.ok()) return parsed.status();
    config->config = std::move(parsed).value();
    *out = config.release();
    return {};
  });
}

OCEAN_API void ocean_config_destroy(ocean_config* config) { delete config; }

OCEAN_API ocean_status ocean_config_merge_preset(ocean_config* config, const char* name_or_path) {
  return guarded([&]() -> ocean::Status {
    constexpr std::string_view f = "ocean_config_merge_preset";
    if (ocean::Status s = require_not_null(config, f, "config"); !s.ok()) return s;
    if (ocean::Status s = require_not_null(name_or_path, f, "name_or_path"); !s.ok()) return s;
    return change_document(*config, [&](ocean::preset::Document& doc) {
      return doc.merge_preset(name_or_path, kPresetLabel);
    });
  });
}

OCEAN_API ocean_status ocean_config_set(ocean_config* config, const char* assignment) {
  return guarded([&]() -> ocean::Status {
    constexpr std::string_view f = "ocean_config_set";
    if (ocean::Status s = require_not_null(config, f, "config"); !s.ok()) return s;
    if (ocean::Status s = require_not_null(assignment, f, "assignment"); !s.ok()) return s;
    return change_document(
        *config, [&](ocean::preset::Document& doc) { return doc.set(assignment, kSetLabel); });
  });
}

OCEAN_API ocean_status ocean_config_to_json(const ocean_config* config, char* buffer,
                                            size_t capacity, size_t* length) {
  return guarded([&]() -> ocean::Status {
    constexpr std::string_view f = "ocean_config_to_json";
    if (ocean::Status s = require_not_null(config, f, "config"); !s.ok()) return s;
    if (ocean::Status s = require_not_null(length, f, "length"); !s.ok()) return s;
    if (capacity > 0) {
      if (ocean::Status s = require_not_null(buffer, f, "buffer"); !s.ok()) return s;
    }
    const std::string text = ocean::preset::to_json(config->config, 2);
    if (capacity > 0) {
      const std::size_t copied = std::min(text.size(), capacity - 1);
      std::memcpy(buffer, text.data(), copied);
      buffer[copied] = '\0';
    }
    *length = text.size();
    return {};
  });
}

OCEAN_API ocean_status ocean_config_save(const ocean_config* config, const char* path) {
  return guarded([&]() -> ocean::Status {
    constexpr std::string_view f = "ocean_config_save";
    if (ocean::Status s = require_not_null(config, f, "config"); !s.ok()) return s;
    if (ocean::Status s = require_not_null(path, f, "path"); !s.ok()) return s;
    const std::string text = ocean::preset::to_json(config->config, 2) + "\n";
    return ocean::io::write_bytes_atomically(path,
                                             {std::as_bytes(std::span(text.data(), text.size()))});
  });
}

OCEAN_API size_t ocean_builtin_preset_count(void) { return builtin_names_c().size(); }

OCEAN_API const char* ocean_builtin_preset_name(size_t index) {
  const std::vector<std::string>& names = builtin_names_c();
  return index < names.size() ? names[index].c_str() : nullptr;
}

}  // extern "C"
