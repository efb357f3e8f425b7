// The stereo flags (stereo_flags.hpp).
#include "stereo_flags.hpp"

#include "ocean/render.hpp"
#include "options.hpp"

namespace ocean::cli {

namespace {

// An IPD beyond human (50–80 mm) is allowed for hyperstereo, up to a metre.
constexpr NumberOption<double> kIpd{
    .flag = "--ipd", .accept = Accept::in_range, .lo = 0.0, .hi = 1.0, .unit = "m"};

}  // namespace

void add_stereo_flags(CLI::App& command, StereoFlags& flags) {
  command.add_flag("--stereo", flags.stereo,
                   "both eyes in one pass (multiview), side by side: the image is 2 x --width "
                   "wide, each eye --width x --height");
  command.add_option("--ipd", flags.ipd,
                     "with --stereo: the distance between the eyes, m, [0, 1] (default 0.064)");
}

Result<std::optional<double>> parse_stereo_flags(const StereoFlags& flags) {
  if (!flags.stereo) {
    if (!flags.ipd.empty()) return invalid_argument("--ipd needs --stereo");
    return std::optional<double>{};
  }
  if (flags.ipd.empty()) return std::optional<double>{render::kDefaultIpd_m};
  Result<double> ipd = parse(kIpd, flags.ipd);
  if (!ipd.ok()) return ipd.status();
  return std::optional<double>{ipd.value()};
}

Status check_stereo_device(const std::optional<double>& ipd, const vk::Context& context) {
  if (ipd.has_value() && !context.multiview)
    return unsupported("--stereo: the Vulkan device '" + context.info.name +
                       "' lacks multiview (VK_KHR_multiview)");
  return {};
}

}  // namespace ocean::cli
