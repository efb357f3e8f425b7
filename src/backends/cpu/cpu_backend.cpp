// CPU reference backend: configuration (spectra per cascade band, plans, buffers) and the
// per-frame stage chain evolve → FFT → finalize → mips (seed 000 §4.2).
#include "cpu_backend.hpp"

#include <cmath>
#include <string>

namespace ocean::cpu {

Status CpuBackend::configure(const SimulationConfig& config, TaskRunner& runner) {
  if (Status s = validate(config); !s.ok()) return s;
  Result<SeaState> sea = SeaState::make(config.sea);
  if (!sea.ok()) return sea.status();
  Result<fft::Plan2D> plan = fft::Plan2D::make(config.resolution);
  if (!plan.ok()) return plan.status();
  std::vector<CascadeState> cascades(config.cascade_patch_sizes_m.size());
  const auto texels =
      static_cast<std::size_t>(config.resolution) * static_cast<std::size_t>(config.resolution);
  for (std::size_t c = 0; c < cascades.size(); ++c) {
    CascadeState& state = cascades[c];
    state.resolution = config.resolution;
    state.patch_size_m = config.cascade_patch_sizes_m[c];
    Result<InitialSpectrum> spectrum =
        make_initial_spectrum(sea.value(), cascade_spectrum_params(config, c));
    if (!spectrum.ok()) {
      return Status(spectrum.status().code(),
                    "cascade " + std::to_string(c) + ": " + spectrum.status().message());
    }
    state.spectrum = std::move(spectrum).value();
    build_plane_factors(state, config.normals, config.choppiness);
    const auto planes = static_cast<std::size_t>(plane_count(config.normals));
    state.plane_re.assign(planes, std::vector<float>(texels));
    state.plane_im.assign(planes, std::vector<float>(texels));
    state.foam.assign(texels, 0.0f);
    state.mip_work.assign(4 * mip_chain_texels(config.resolution), 0.0f);
  }
  config_ = config;
  runner_ = &runner;
  plan_ = std::move(plan).value();
  cascades_ = std::move(cascades);
  has_stepped_ = false;
  return {};
}

void CpuBackend::allocate(Frame& frame) const {
  frame.cascades.resize(cascades_.size());
  for (std::size_t c = 0; c < cascades_.size(); ++c) {
    CascadeFrame& f = frame.cascades[c];
    const auto texels =
        static_cast<std::size_t>(config_.resolution) * static_cast<std::size_t>(config_.resolution);
    f.resolution = config_.resolution;
    f.patch_size_m = cascades_[c].patch_size_m;
    f.displacement.assign(3 * texels, 0.0f);
    f.displacement_half.assign(4 * texels, 0);
    f.normal.assign(3 * texels, 0.0f);
    f.jacobian.assign(texels, 1.0f);
    f.foam.assign(texels, 0.0f);
    f.packed_mips.assign(mip_chain_texels(config_.resolution), 0u);
  }
}

void CpuBackend::step(double time_s, Frame& out) {
  // Foam accumulates over the time since the previous step; a first step or a jump back in
  // time starts it afresh.
  const bool reset_foam = !has_stepped_ || time_s < last_time_s_;
  const double dt = reset_foam ? 0.0 : time_s - last_time_s_;
  for (std::size_t c = 0; c < cascades_.size(); ++c) {
    CascadeState& state = cascades_[c];
    evolve(state, time_s, config_.loop_period_s, *runner_);
    fft::SplitComplex planes[fft::kMaxPlanes];
    for (std::size_t p = 0; p < state.plane_re.size(); ++p) {
      planes[p] = {state.plane_re[p].data(), state.plane_im[p].data()};
    }
    plan_.inverse({planes, state.plane_re.size()}, *runner_, true);
    finalize(state, config_, dt, reset_foam, out.cascades[c], *runner_);
    build_mips(state, out.cascades[c], *runner_);
  }
  out.time_s = time_s;
  ++out.index;
  last_time_s_ = time_s;
  has_stepped_ = true;
}

}  // namespace ocean::cpu
