// The host-side plan of a CUDA frame (plan.hpp): memory layout, mip passes, schedule.
#include "plan.hpp"

#include <algorithm>
#include <bit>

#include "sim/far_noise.h"

namespace ocean::cuda::detail {
namespace {

// Tiles of the mip passes: a 16×16 thread block reduces 16² texels by four levels in shared
// memory (256 threads, the block size the per-texel kernels use).
constexpr int kTile = 16;

std::size_t align(std::size_t bytes) { return (bytes + kAlignment - 1) / kAlignment * kAlignment; }

// Appends a region of `bytes` at `cursor` and advances it (aligned).
Region take(std::size_t& cursor, std::size_t bytes) {
  const Region r{cursor, bytes};
  cursor += align(bytes);
  return r;
}

}  // namespace

Result<Layout> make_layout(const SimulationConfig& config) {
  if (Status s = validate(config); !s.ok()) return s;
  Layout l;
  l.resolution = config.resolution;
  l.log2_resolution = std::countr_zero(static_cast<unsigned>(config.resolution));
  l.cascades = static_cast<int>(config.cascade_patch_sizes_m.size());
  l.planes = config.normals == NormalMethod::analytic ? 4 : 2;
  l.texels = static_cast<std::size_t>(l.resolution) * static_cast<std::size_t>(l.resolution);
  l.chain = mip_chain_texels(l.resolution);

  // The readback block: the requested outputs in Frame's order, each aligned.
  const FrameOutputs& want = config.outputs;
  const std::array<std::size_t, kOutputs> bytes = {12 * l.texels,
                                                   8 * l.texels,
                                                   want.normal ? 12 * l.texels : 0,
                                                   want.jacobian ? 4 * l.texels : 0,
                                                   want.foam ? 4 * l.texels : 0,
                                                   4 * l.chain};
  std::size_t cursor = 0;
  for (int o = 0; o < kOutputs; ++o) {
    l.outputs[o] = bytes[o] == 0 ? Region{cursor, 0} : take(cursor, bytes[o]);
  }
  // Copied in one piece: up to the last output's end (packed_mips, always read back).
  const std::size_t readback_bytes = l.outputs[packed_mips].offset + l.outputs[packed_mips].bytes;

  cursor = 0;
  l.spectrum = take(cursor, 16 * l.texels);
  l.phase_rate = take(cursor, 8 * l.texels);
  l.twiddle = take(cursor, 8 * static_cast<std::size_t>(l.resolution));
  l.fft_planes = take(cursor, 8 * l.texels * static_cast<std::size_t>(l.planes));
  l.mip_work = take(cursor, 16 * l.chain);
  l.foam_state = want.foam ? Region{} : take(cursor, 4 * l.texels);
  l.readback = take(cursor, readback_bytes);
  l.readback.bytes = readback_bytes;
  if (want.foam) {
    l.foam_state = {l.readback.offset + l.outputs[foam].offset, l.outputs[foam].bytes};
  }
  l.cascade_bytes = cursor;

  // The far field's noise map: its parameters and the map after every cascade's block, the
  // pinned parameters and the map's readback after every cascade's readback block.
  if (config.far_noise.resolution > 0) {
    const auto m = static_cast<std::size_t>(config.far_noise.resolution);
    l.noise_resolution = config.far_noise.resolution;
    cursor = l.cascade_bytes * static_cast<std::size_t>(l.cascades);
    l.noise_params_device = take(cursor, sizeof(noise::FarNoiseMapParams));
    l.noise_map = take(cursor, 12 * m * m);
    cursor = align(l.readback.bytes * static_cast<std::size_t>(l.cascades));
    l.noise_params_host = take(cursor, sizeof(noise::FarNoiseMapParams));
    l.noise_readback = take(cursor, 12 * m * m);
  }

  // Mip passes: the first inside finalize (source 0), then one per four levels.
  for (int source = 0; source < l.log2_resolution;) {
    const int size = l.resolution >> source;
    const int tile = std::min(size, kTile);
    const int levels = std::countr_zero(static_cast<unsigned>(tile));
    l.mip_passes.push_back({source, levels, tile});
    source += levels;
  }
  return l;
}

Schedule make_schedule(const Layout& layout, const ScheduleParts& parts) {
  const bool concurrent = parts.concurrent;
  const bool noise = parts.noise && layout.noise_resolution > 0;
  const int slots = 1 + layout.cascades + (layout.noise_resolution > 0 ? 1 : 0);
  Schedule s;
  s.streams = concurrent ? slots : 1;
  s.events = concurrent ? slots : 0;
  if (parts.cascades) {
    s.ops.push_back({.kind = Op::upload_params, .records = concurrent ? 0 : -1});
  } else if (concurrent) {
    s.ops.push_back({.kind = Op::fork, .records = 0});
  }
  Op join{.kind = Op::join};
  // The map first: its one kernel is issued before the cascades' chains fill the device.
  if (noise) {
    const int stream = concurrent ? noise_stream(layout) : 0;
    const std::size_t first = s.ops.size();
    s.ops.push_back({.kind = Op::noise_params, .stream = stream});
    s.ops.push_back({.kind = Op::noise, .stream = stream});
    if (parts.readback) s.ops.push_back({.kind = Op::noise_readback, .stream = stream});
    if (concurrent) {
      s.ops[first].waits = {0};
      s.ops.back().records = noise_event(layout);
    }
  }
  for (int c = 0; parts.cascades && c < layout.cascades; ++c) {
    const int stream = concurrent ? 1 + c : 0;
    const std::size_t first = s.ops.size();
    s.ops.push_back({.kind = Op::evolve, .cascade = c, .stream = stream});
    s.ops.push_back({.kind = Op::fft, .cascade = c, .stream = stream});
    s.ops.push_back({.kind = Op::finalize, .cascade = c, .stream = stream});
    for (std::size_t p = 1; p < layout.mip_passes.size(); ++p) {
      s.ops.push_back(
          {.kind = Op::mips, .cascade = c, .pass = static_cast<int>(p), .stream = stream});
    }
    if (parts.share) s.ops.push_back({.kind = Op::share, .cascade = c, .stream = stream});
    if (parts.readback) s.ops.push_back({.kind = Op::readback, .cascade = c, .stream = stream});
    if (concurrent) {
      s.ops[first].waits = {0};
      s.ops.back().records = 1 + c;
      join.waits.push_back(1 + c);
    }
  }
  if (noise && concurrent) join.waits.push_back(noise_event(layout));
  s.ops.push_back(join);
  return s;
}

Schedule make_schedule(const Layout& layout, bool concurrent, bool with_readback, bool with_share) {
  return make_schedule(layout,
                       {.concurrent = concurrent, .readback = with_readback, .share = with_share});
}

}  // namespace ocean::cuda::detail
