// src/bake/quoted.hpp — a path as the bake's messages echo it (private to the bake module).
#pragma once

#include <filesystem>
#include <string>

#include "ocean/core.hpp"

namespace ocean::bake::detail {

/// `path` in single quotes, made safe and short for a one-line message (ocean::excerpt).
inline std::string quoted(const std::filesystem::path& path) {
  // Built with append rather than operator+ to dodge a g++ 12 -O3 -Wrestrict false positive.
  std::string text(1, '\'');
  text.append(excerpt(path.string(), 240)).append(1, '\'');
  return text;
}

}  // namespace ocean::bake::detail
