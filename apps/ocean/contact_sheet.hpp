// A contact sheet of a simulated frame: per cascade, height, normal map, foam and the
// smoothness a mip level encodes, as one PNG a person can look at.
#pragma once

#include <filesystem>
#include <string>

#include "ocean/sim.hpp"

namespace ocean::cli {

/// Renders and writes (atomically) the contact sheet of `frame`; `title` is drawn on top.
Status write_contact_sheet(const Frame& frame, const std::string& title,
                           const std::filesystem::path& path);

}  // namespace ocean::cli
