// The fused pipeline's surface and mip passes: each frame's SurfaceArgs, the surface rows in
// quads (with mip levels 1 and 2), and the remaining mip levels.
#include <algorithm>

#include "cpu_backend.hpp"

namespace ocean::cpu {

void CpuBackendImpl::prepare_surface(double dt_s, bool reset_foam, Frame& out) {
  const int n = config_.resolution;
  const float base_length = normal_length_from_roughness(static_cast<float>(config_.roughness));
  std::vector<SurfaceArgs>& args = surface_args_;  // sized at configure: no allocation here
  for (std::size_t c = 0; c < cascades_.size(); ++c) {
    CascadeState& state = cascades_[c];
    CascadeFrame& frame = out.cascades[c];
    args[c] = {.n = n,
               .displacement = frame.displacement.data(),
               .inv_spacing = static_cast<float>(n / state.patch_size_m),  // eq. 45
               .base_length = base_length,
               .smoothness = smoothness_from_normal_length(base_length),
               .foam_source = state.foam_source,
               .decay = static_cast<float>(config_.foam.decay_per_s * dt_s),
               .reset_foam = reset_foam,
               .blue_is_foam = config_.blue_channel == BlueChannel::foam,
               .foam_state = state.foam.data(),
               .jacobian = frame.jacobian.empty() ? nullptr : frame.jacobian.data(),
               .foam = frame.foam.empty() ? nullptr : frame.foam.data(),
               .normal = frame.normal.empty() ? nullptr : frame.normal.data(),
               .mip_work = state.mip_work.data(),
               .packed = frame.packed_mips.data()};
  }
}

void CpuBackendImpl::surface_fused(TaskRunner& runner, std::size_t first, std::size_t count) {
  const auto quads = static_cast<std::size_t>(config_.resolution / 4);
  runner.parallel_for(count * quads, 4, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end;) {  // runs of consecutive quads in one cascade
      const std::size_t c = i / quads, stop = std::min(end, (c + 1) * quads);
      surface_row_quads(surface_args_[first + c], static_cast<int>(i % quads),
                        static_cast<int>(stop - i));
      i = stop;
    }
  });
}

void CpuBackendImpl::mips_fused(TaskRunner& runner, int first_level, std::size_t first,
                                std::size_t count, Frame& out) {
  const int n = config_.resolution;
  const int levels = std::countr_zero(static_cast<unsigned>(n));
  const auto level_rows = [&](int level) { return static_cast<std::size_t>(n >> level); };
  // Levels of at least 64 rows: one parallel loop each (each reads the level above). The levels
  // under 64 rows (at most 1365 texels per cascade): each cascade's rest of the chain on one
  // worker, one loop for all, so the frame does not wait on a barrier per small level.
  int level = first_level;
  for (; level <= levels && level_rows(level) >= 64; ++level) {
    const std::size_t rows = level_rows(level);
    runner.parallel_for(count * rows, 8, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        const std::size_t c = first + i / rows;
        mip_row(n, level, static_cast<int>(i % rows), cascades_[c].mip_work.data(),
                cascades_[c].mip_work_level, out.cascades[c].packed_mips.data());
      }
    });
  }
  if (level > levels) return;
  runner.parallel_for(count, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t c = first + begin; c < first + end; ++c) {
      for (int l = level; l <= levels; ++l) {
        for (std::size_t row = 0; row < level_rows(l); ++row) {
          mip_row(n, l, static_cast<int>(row), cascades_[c].mip_work.data(),
                  cascades_[c].mip_work_level, out.cascades[c].packed_mips.data());
        }
      }
    }
  });
}

}  // namespace ocean::cpu
