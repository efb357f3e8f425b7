// ocean_web.cpp — the page's WebAssembly surface: plain C functions over the library's spectrum
// module (S(ω), h0(k)) and the CPU backend's scalar reference synthesis (the in-browser oracle of
// the WebGPU kernels). One sea at a time, held in this module; JavaScript reads the arrays it
// returns straight out of the WebAssembly memory (HEAPF32/HEAPF64 views).
//
// Contract: ocean_web_configure validates and allocates; every other call reads the configured
// sea and never allocates. Pointers stay valid until the next ocean_web_configure. Errors are the
// library's Status messages, one line, from ocean_web_error(). Single-threaded.
#include <emscripten/emscripten.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>
#include <optional>
#include <string>

#include "cpu_backend.hpp"
#include "ocean/fft.hpp"
#include "ocean/plan.hpp"
#include "ocean/sim.hpp"
#include "ocean/spectrum.hpp"
#include "ocean/task_runner.hpp"

namespace {

struct WebSea {
  std::optional<ocean::SeaState> sea;
  double loop_period_s = 0.0;
  ocean::cpu::CascadeState state;  // spectrum, plane factors and the reference planes
  std::optional<ocean::fft::Plan2D> plan;
  std::unique_ptr<ocean::TaskRunner> runner = ocean::make_serial_runner();
  std::vector<float> phase_rate;       // EvolutionPhase::rate per texel (the GPU's phase input)
  std::vector<double> h0;              // re, im per texel
  ocean::SimulationConfig config;      // normals, roughness and foam parameters of the finalize
  ocean::CascadeFrame frame;           // the reference outputs
  std::vector<float> surface;          // (nx, ny, nz, J) per texel, the GPU's layout
  double choppiness = -1.0;            // λ the plane factors were built for
  double geometry_wavelength_m = 0.0;  // the plan's tiling wavelength of this cascade (R.9)
  std::string error;
};

WebSea& sea() {
  static WebSea s;
  return s;
}

int fail(const ocean::Status& status) {
  sea().error = status.message();
  sea().sea.reset();
  return 1;
}

}  // namespace

extern "C" {

/// Configures cascade `cascade` of a sea of `cascade_count` cascades with the patch sides
/// patch_sizes_m[0 … cascade_count) m, largest first (the native SimulationConfig's
/// cascade_patch_sizes_m): a fetch-limited JONSWAP wind sea with Donelan–Banner spreading (the
/// library's default_sea_state with the given wind U10 m/s, fetch m and direction rad) on that
/// cascade's N×N patch, restricted to its wavenumber band and drawn from its own seed as the native
/// simulation does (cascade_spectrum_params), from seed (an integer below 2^53), loop period T s
/// (0 = none). One cascade is one full-band patch. Returns 0, or 1 with ocean_web_error() saying
/// why (the library's validate message for a bad list).
EMSCRIPTEN_KEEPALIVE int ocean_web_configure(double wind_mps, double fetch_m, double direction_rad,
                                             int resolution, const double* patch_sizes_m,
                                             int cascade_count, int cascade, double seed,
                                             double loop_period_s) {
  WebSea& s = sea();
  if (!(seed >= 0.0 && seed < 9007199254740992.0 && std::floor(seed) == seed))
    return fail(ocean::invalid_argument("seed must be an integer in [0, 2^53)"));
  if (cascade_count < 1 || cascade_count > 8 || cascade < 0 || cascade >= cascade_count)
    return fail(ocean::invalid_argument("cascade " + std::to_string(cascade) + " of " +
                                        std::to_string(cascade_count) + " is out of range"));
  ocean::SimulationConfig config;
  config.sea.wind_sea.spectrum.wind_speed_mps = wind_mps;
  config.sea.wind_sea.spectrum.fetch_m = fetch_m;
  config.sea.wind_sea.direction_rad = direction_rad;
  config.resolution = resolution;
  config.cascade_patch_sizes_m.assign(patch_sizes_m, patch_sizes_m + cascade_count);
  config.loop_period_s = loop_period_s;
  config.seed = static_cast<std::uint64_t>(seed);
  config.foam.source = ocean::FoamSource::ramp;  // the page's compute shader's (common.wgsl)
  ocean::Result<ocean::SimulationPlan> made = ocean::SimulationPlan::make(config);
  if (!made.ok()) return fail(made.status());
  const double patch_size_m = config.cascade_patch_sizes_m[static_cast<std::size_t>(cascade)];
  ocean::Result<ocean::InitialSpectrum> spectrum = ocean::make_initial_spectrum(
      made.value().sea(), made.value().cascades()[static_cast<std::size_t>(cascade)].spectrum);
  if (!spectrum.ok()) return fail(spectrum.status());
  ocean::Result<ocean::fft::Plan2D> plan = ocean::fft::Plan2D::make(resolution);
  if (!plan.ok()) return fail(plan.status());

  s.sea.emplace(made.value().sea());
  s.plan.emplace(std::move(plan.value()));
  s.loop_period_s = loop_period_s;
  s.state = {};
  s.state.resolution = resolution;
  s.state.patch_size_m = patch_size_m;
  s.state.spectrum = std::move(spectrum.value());
  const auto texels = static_cast<std::size_t>(resolution) * static_cast<std::size_t>(resolution);
  s.state.plane_re.assign(2, std::vector<float>(texels));
  s.state.plane_im.assign(2, std::vector<float>(texels));
  s.phase_rate.resize(texels);
  s.h0.resize(2 * texels);
  for (std::size_t i = 0; i < texels; ++i) {
    s.phase_rate[i] =
        static_cast<float>(ocean::EvolutionPhase::rate(s.state.spectrum.omega[i], loop_period_s));
    s.h0[2 * i] = s.state.spectrum.h0[i].real();
    s.h0[2 * i + 1] = s.state.spectrum.h0[i].imag();
  }
  s.state.foam.assign(texels, 0.0f);
  s.state.foam_source = ocean::packing::foam_terms(config.foam, {});
  s.state.mip_work.assign(4 * texels, 0.0f);
  s.frame = {};
  s.frame.resolution = resolution;
  s.frame.patch_size_m = patch_size_m;
  s.frame.displacement.assign(3 * texels, 0.0f);
  s.frame.displacement_half.assign(4 * texels, 0);
  s.frame.normal.assign(3 * texels, 0.0f);
  s.frame.jacobian.assign(texels, 1.0f);
  s.frame.foam.assign(texels, 0.0f);
  s.frame.packed_mips.assign(texels, 0);  // level 0 only: the reference computes no mips
  s.surface.resize(4 * texels);
  s.choppiness = -1.0;
  s.geometry_wavelength_m =
      made.value().cascades()[static_cast<std::size_t>(cascade)].tiling_wavelength_m;
  s.error.clear();
  return 0;
}

/// The configured cascade's geometry fade length, m (CascadePlan::tiling_wavelength_m); NaN
/// when nothing is configured.
EMSCRIPTEN_KEEPALIVE double ocean_web_geometry_wavelength() {
  const WebSea& s = sea();
  return s.sea ? s.geometry_wavelength_m : std::nan("");
}

/// The last configuration error, one line ("" after a success).
EMSCRIPTEN_KEEPALIVE const char* ocean_web_error() { return sea().error.c_str(); }

/// S(ω) of the wind sea, m²·s/rad, for ω ≥ 0 rad/s; NaN when nothing is configured.
EMSCRIPTEN_KEEPALIVE double ocean_web_spectrum(double omega) {
  const WebSea& s = sea();
  if (!s.sea || !(omega >= 0.0)) return std::nan("");
  return s.sea->systems().front().spectrum()(omega);
}

/// ωp of the wind sea, rad/s, and Hs = 4·√m0 of the whole sea, m; NaN when nothing is configured.
EMSCRIPTEN_KEEPALIVE double ocean_web_peak_omega() {
  const WebSea& s = sea();
  return s.sea ? s.sea->systems().front().spectrum().peak_omega() : std::nan("");
}
EMSCRIPTEN_KEEPALIVE double ocean_web_hs() {
  const WebSea& s = sea();
  return s.sea ? 4.0 * std::sqrt(s.sea->variance_m2()) : std::nan("");
}

/// h0(k) as (re, im) doubles per texel (index row·N + col, k = 2π/L·(col − N/2, row − N/2)).
EMSCRIPTEN_KEEPALIVE const double* ocean_web_h0() { return sea().h0.data(); }
/// The packed amplitudes S' (4 floats per texel, M.6.5): what the GPU evolution reads.
EMSCRIPTEN_KEEPALIVE const float* ocean_web_packed() {
  return sea().state.spectrum.packed.front().data();
}
/// EvolutionPhase::rate per texel (float): the loop harmonic j, or ω/2π without a loop (M.7.3).
EMSCRIPTEN_KEEPALIVE const float* ocean_web_phase_rate() { return sea().phase_rate.data(); }

/// Steps the CPU reference to time_s with choppiness λ ≥ 0: the CPU backend's scalar evolution,
/// the radix-2 Plan2D with the (−1)^(x+y) shift, its reference assembly and its finalize
/// (central-difference normals, Jacobian, foam accumulated over dt_s since the previous step, or
/// restarted when reset_foam ≠ 0). Returns the displacement (Dx, h, Dz) per texel, or nullptr when
/// nothing is configured; ocean_web_surface and ocean_web_foam then hold the rest.
EMSCRIPTEN_KEEPALIVE const float* ocean_web_reference(double time_s, double choppiness, double dt_s,
                                                      int reset_foam) {
  WebSea& s = sea();
  if (!s.sea) return nullptr;
  if (choppiness != s.choppiness) {
    ocean::cpu::build_plane_factors(s.state, ocean::NormalMethod::central_difference, choppiness);
    s.config.choppiness = choppiness;
    s.choppiness = choppiness;
  }
  ocean::cpu::evolve(s.state, time_s, s.loop_period_s, *s.runner, nullptr);
  ocean::fft::SplitComplex planes[2] = {ocean::cpu::plane_of(s.state, 0),
                                        ocean::cpu::plane_of(s.state, 1)};
  s.plan->inverse(planes, *s.runner, true);
  ocean::cpu::assemble_displacement_reference(s.state, s.state.plane_re[1].data(), s.frame,
                                              *s.runner);
  ocean::cpu::finalize(s.state, s.config, dt_s, reset_foam != 0, s.frame, *s.runner);
  for (std::size_t i = 0; i < s.frame.jacobian.size(); ++i) {
    for (std::size_t c = 0; c < 3; ++c) s.surface[4 * i + c] = s.frame.normal[3 * i + c];
    s.surface[4 * i + 3] = s.frame.jacobian[i];
  }
  return s.frame.displacement.data();
}
/// (nx, ny, nz, J) per texel of the last ocean_web_reference.
EMSCRIPTEN_KEEPALIVE const float* ocean_web_surface() { return sea().surface.data(); }
/// Accumulated foam per texel of the last ocean_web_reference.
EMSCRIPTEN_KEEPALIVE const float* ocean_web_foam() { return sea().frame.foam.data(); }

}  // extern "C"
