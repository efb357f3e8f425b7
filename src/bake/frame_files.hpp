// src/bake/frame_files.hpp — the files of one cascade of one frame (private to the bake module).
#pragma once

#include <atomic>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "ocean/bake.hpp"

namespace ocean::bake::detail {

/// The names of the maps a bake writes, each followed by "_c<k>_f<fffff>" (see ocean/bake.hpp).
inline constexpr std::string_view kFileStems[] = {"displacement_", "normal_", "jacobian_", "foam_",
                                                  "maps_",         "nfs_",    "height_"};

/// Writes the maps of cascade `c` in every format of `formats` into `dir`, naming each file
/// "<map>_<stem>.<ext>" (stem "c<k>_f<fffff>"; see ocean/bake.hpp for the list), and appends the
/// name of every file written to `names`, in writing order. PNG height maps map
/// [−height_range_m, +height_range_m] to [0, 65535]. Stops at the first failing write and returns
/// its Status (the failed file is not in `names`); before each file, stops with
/// ErrorCode::cancelled if `cancel` is set and true.
Status write_cascade_files(const CascadeFrame& c, const std::string& stem,
                           const std::filesystem::path& dir, const Formats& formats,
                           double height_range_m, const std::atomic<bool>* cancel,
                           std::vector<std::string>& names);

}  // namespace ocean::bake::detail
