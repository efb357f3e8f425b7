// The soak program's command line (options.hpp).
#include "options.hpp"

#include <algorithm>
#include <charconv>
#include <limits>
#include <string_view>

namespace ocean::soak {

namespace {

Status parse_int(std::string_view flag, std::string_view text, int lo, int hi, int& out) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || end != text.data() + text.size())
    return invalid_argument(std::string(flag) + " = \"" + excerpt(text) + "\" is not an integer");
  if (value < lo || value > hi)
    return invalid_argument(std::string(flag) + " = " + std::to_string(value) +
                            " is out of range: must be in [" + std::to_string(lo) + ", " +
                            std::to_string(hi) + "]");
  out = value;
  return {};
}

}  // namespace

const char* usage() {
  return "usage: soak [options]\n"
         "  --frames N        frames simulated and drawn, 60 per simulated second (10000)\n"
         "  --warmup N        frames before growth is judged (frames / 10)\n"
         "  --backend NAME    simulation backend: cpu or vulkan (cpu)\n"
         "  --size N          simulation grid per cascade, a power of two (64)\n"
         "  --width W         render target width, pixels (128)\n"
         "  --height H        render target height, pixels (72)\n"
         "  --windows K       reporting windows after the warm-up (4)\n"
         "exit status: 0 no growth, 1 growth beyond the thresholds, 2 bad usage or a failure\n";
}

Result<Options> parse_options(int argc, char** argv) {
  Options o;
  constexpr int kMaxInt = std::numeric_limits<int>::max();
  constexpr int kMaxSide = 16384;  // RendererParams' range
  for (int i = 1; i < argc; ++i) {
    const std::string_view flag = argv[i];
    if (flag == "--help" || flag == "-h") {
      o.help = true;
      continue;
    }
    if (i + 1 >= argc) {
      if (flag.starts_with("--"))
        return invalid_argument(std::string(excerpt(flag)) + " needs a value (see soak --help)");
      return invalid_argument("unknown argument \"" + excerpt(flag) + "\" (see soak --help)");
    }
    const std::string_view value = argv[++i];
    Status s;
    if (flag == "--frames") {
      s = parse_int(flag, value, 2, kMaxInt, o.frames);
    } else if (flag == "--warmup") {
      s = parse_int(flag, value, 1, kMaxInt, o.warmup);
    } else if (flag == "--backend") {
      if (value != "cpu" && value != "vulkan")
        return invalid_argument("--backend = \"" + excerpt(value) + "\": must be cpu or vulkan");
      o.backend = value;
    } else if (flag == "--size") {
      s = parse_int(flag, value, 1, kMaxInt, o.size);
    } else if (flag == "--width") {
      s = parse_int(flag, value, 1, kMaxSide, o.width);
    } else if (flag == "--height") {
      s = parse_int(flag, value, 1, kMaxSide, o.height);
    } else if (flag == "--windows") {
      s = parse_int(flag, value, 1, 100, o.windows);
    } else {
      return invalid_argument("unknown option \"" + excerpt(flag) + "\" (see soak --help)");
    }
    if (!s.ok()) return s;
  }
  if (o.warmup < 0) o.warmup = std::max(o.frames / 10, 1);
  if (o.warmup >= o.frames)
    return invalid_argument(
        "--warmup = " + std::to_string(o.warmup) +
        " leaves nothing to judge: must be < --frames = " + std::to_string(o.frames));
  return o;
}

}  // namespace ocean::soak
