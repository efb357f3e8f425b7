// src/bake/manifest.hpp — the end of a bake's or a merge's transaction: the manifest completed
// and written last (private to the bake module).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string_view>

#include "ocean/core.hpp"

namespace ocean::bake::detail {

using Json = nlohmann::ordered_json;

/// The manifest's file name in a bake's folder.
inline constexpr const char* kManifestName = "manifest.json";

/// Sets "complete" (stop.ok()) and "stopped" (erased when complete, "cancelled" or the stop's
/// message otherwise) in `manifest`, writes it atomically as <dir>/manifest.json (two-space
/// indent, a final newline) and returns what ended the run: the write's Status when `stop` is ok,
/// `stop` itself when it failed, and for a cancellation ErrorCode::cancelled "<what> cancelled
/// after <frames_written> of <frames_asked> frames; '<manifest>' says "complete": false" (or
/// "...; no manifest: <why>" when the write failed too). Never throws.
Status finish_manifest(const std::filesystem::path& dir, Json& manifest, const Status& stop,
                       long long frames_asked, std::string_view what) noexcept;

}  // namespace ocean::bake::detail
