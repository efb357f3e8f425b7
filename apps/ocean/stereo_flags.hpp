// The stereo flags of `ocean render`: --stereo draws both eyes of the camera in one pass
// (VK_KHR_multiview; docs/rendering.md R.25) side by side, --ipd sets their separation.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "ocean/core.hpp"
#include "ocean/vk.hpp"

namespace ocean::cli {

struct StereoFlags {
  bool stereo = false;
  std::string ipd;  // m; empty: render::kDefaultIpd_m
};
/// Registers --stereo and --ipd M.
void add_stereo_flags(CLI::App& command, StereoFlags& flags);
/// The IPD of a stereo picture, or none for a mono one. invalid_argument for an IPD that is not
/// a number in [0, 1] m (negative, NaN) or given without --stereo.
Result<std::optional<double>> parse_stereo_flags(const StereoFlags& flags);
/// unsupported, one line, when a stereo picture is asked of a device without multiview.
Status check_stereo_device(const std::optional<double>& ipd, const vk::Context& context);

}  // namespace ocean::cli
