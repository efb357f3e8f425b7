// The presets of presets/ (calm, moderate, storm), compiled into the tool.
#pragma once

#include <string_view>
#include <vector>

namespace ocean::cli {

struct BuiltinPreset {
  std::string_view name;  ///< "calm", "moderate", "storm"
  std::string_view json;  ///< the file's text
};
const std::vector<BuiltinPreset>& builtin_presets();

}  // namespace ocean::cli
