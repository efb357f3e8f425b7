// The scalar reference pipeline's synthesis (also the external-FFT pipeline's): scalar
// evolution, the radix-2 Plan2D or an ExternalFft with the (−1)^(x+y) shift applied after it,
// scalar assembly.
#include "cpu_backend.hpp"

namespace ocean::cpu {

namespace {

// (−1)^(x+y) on every plane, for FFT engines that do not fold it in (eq. 43).
void apply_sign(CascadeState& state, TaskRunner& runner) {
  const auto n = static_cast<std::size_t>(state.resolution);
  runner.parallel_for(n, 8, [&](std::size_t row_begin, std::size_t row_end) {
    for (std::size_t p = 0; p < state.plane_re.size(); ++p) {
      for (std::size_t row = row_begin; row < row_end; ++row) {
        float* re = state.plane_re[p].data() + row * n;
        float* im = state.plane_im[p].data() + row * n;
        for (std::size_t col = (row + 1) & 1u; col < n; col += 2)
          re[col] = -re[col], im[col] = -im[col];
      }
    }
  });
}

}  // namespace

void CpuBackendImpl::synthesise_unfused(double time_s, Frame& out) {
  for (const CascadeGroup& group : groups_) {
    CascadeState& first = cascades_[group.first];
    fft::SplitComplex planes[fft::kMaxPlanes];
    std::size_t count = 0;
    for (std::size_t c = group.first; c < group.first + group.count; ++c) {
      CascadeState& state = cascades_[c];
      evolve(state, time_s, config_.loop_period_s, *runner_, c == group.first ? nullptr : &first);
      for (std::size_t p = 0; p < state.plane_re.size(); ++p) planes[count++] = plane_of(state, p);
    }
    const std::span<const fft::SplitComplex> view{planes, count};
    if (options_.pipeline == CpuPipeline::external_fft) {
      options_.fft->inverse(view);
      for (std::size_t c = group.first; c < group.first + group.count; ++c)
        apply_sign(cascades_[c], *runner_);
    } else {
      plan_.inverse(view, *runner_, true);
    }
    for (std::size_t c = group.first; c < group.first + group.count; ++c) {
      const float* dz = c == group.first ? first.plane_re[1].data() : first.plane_im[1].data();
      assemble_displacement_reference(cascades_[c], dz, out.cascades[c], *runner_);
    }
  }
}

}  // namespace ocean::cpu
