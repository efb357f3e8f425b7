// src/bake/frame_files.hpp — the files of one cascade of one frame (private to the bake module).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "ocean/bake.hpp"

namespace ocean::bake::detail {

/// Writes the maps of cascade `c` in every format of `formats` into `dir`, naming each file
/// "<map>_<stem>.<ext>" (stem "c<k>_f<fffff>"; see ocean/bake.hpp for the list), and appends the
/// name of every file it writes to `names`, in writing order. PNG height maps map
/// [−height_range_m, +height_range_m] to [0, 65535]. Stops at the first failing write and returns
/// its Status.
Status write_cascade_files(const CascadeFrame& c, const std::string& stem,
                           const std::filesystem::path& dir, const Formats& formats,
                           double height_range_m, std::vector<std::string>& names);

}  // namespace ocean::bake::detail
