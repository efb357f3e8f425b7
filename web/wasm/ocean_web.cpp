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
#include "ocean/render.hpp"
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
  // The breaking foam source of this cascade at λ = 1 (FoamPlan, M.7.4): J_thr = 1 − α/β and
  // gain β/s₁; at λ the plan's formulas give 1 − λ·α/β and β/(λ·s₁). Then the cascade's foam
  // weight (FoamPlan::weights, R.11) and the short waves' slope variance (R.5).
  double foam_threshold_1 = 0.0, foam_gain_1 = 0.0, foam_weight = 1.0;
  double unresolved_slope_variance = 0.0;
  float foam_terms[3] = {};  // threshold, gain, weight at the last λ asked for
  std::string error;
};

WebSea& sea() {
  static WebSea s;
  return s;
}

float* light_values() {
  static float values[24] = {};
  return values;
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
  config.choppiness = 1.0;  // the foam terms at λ = 1; other λ follow (ocean_web_foam_terms)
  // config.foam.source stays the native default, FoamSource::breaking (M.7.4).
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
  const ocean::FoamPlan& foam = made.value().foam();
  s.foam_threshold_1 = foam.cascades[static_cast<std::size_t>(cascade)].threshold;
  s.foam_gain_1 = foam.cascades[static_cast<std::size_t>(cascade)].gain;
  s.foam_weight = foam.weights.empty() ? 1.0 : foam.weights[static_cast<std::size_t>(cascade)];
  const std::optional<ocean::SlopeVariance>& tail = made.value().unresolved_slope_variance();
  s.unresolved_slope_variance = tail ? tail->total() : 0.0;
  s.config.foam = config.foam;
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

/// The breaking foam source's terms of the configured cascade at choppiness λ ≥ 0, as floats
/// (threshold J_thr, gain, and the cascade's foam weight of R.11): FoamPlan's
/// 1 − λα/β and β/(λ·s₁) (M.7.4; λ = 0 makes no foam: threshold 0, gain 10⁹, as the plan's);
/// nullptr when nothing is configured. The reference's finalize uses the same terms.
EMSCRIPTEN_KEEPALIVE const float* ocean_web_foam_terms(double choppiness) {
  WebSea& s = sea();
  if (!s.sea) return nullptr;
  const bool foams = choppiness > 0.0;
  s.state.foam_source = {
      static_cast<float>(foams ? 1.0 - choppiness * (1.0 - s.foam_threshold_1) : 0.0),
      static_cast<float>(foams ? s.foam_gain_1 / choppiness : 1e9), true};
  s.foam_terms[0] = s.state.foam_source.threshold;
  s.foam_terms[1] = s.state.foam_source.gain;
  s.foam_terms[2] = static_cast<float>(s.foam_weight);
  return s.foam_terms;
}

/// The slope variance of the waves shorter than the finest cascade (M.9; the renderer's α₀²,
/// R.5), 0 for a sea that names no wind; NaN when nothing is configured.
EMSCRIPTEN_KEEPALIVE double ocean_web_unresolved_slope_variance() {
  const WebSea& s = sea();
  return s.sea ? s.unresolved_slope_variance : std::nan("");
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
    ocean_web_foam_terms(choppiness);
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

/// The native renderer's sky (render::Sky, docs/rendering.md R.1–R.4) for the default shading
/// with the sun at azimuth_deg, elevation_deg: fills the sky-view table (Sky::kLutWidth ×
/// kLutHeight RGBA floats, Sky::fill_lut) and returns it; ocean_web_light() then holds the rest.
EMSCRIPTEN_KEEPALIVE const float* ocean_web_sky(double azimuth_deg, double elevation_deg) {
  static std::vector<float> lut(4 * ocean::render::Sky::kLutWidth * ocean::render::Sky::kLutHeight);
  ocean::render::ShadingParams p;
  p.sun_azimuth_deg = azimuth_deg;
  p.sun_elevation_deg = elevation_deg;
  const ocean::render::Sky sky(p);
  sky.fill_lut(lut);
  const std::array<double, 3> ground = sky.sun_irradiance_ground();
  const std::array<double, 3> ambient = sky.sky_irradiance_horizontal();
  const ocean::render::Sky::Air air = sky.air();
  // 0–2 sun direction, 3–5 sun irradiance at sea level (R.3), 6–8 sky irradiance on a
  // horizontal plane (R.4), 9–11 Rayleigh β per m, 12 H_R, 13 haze β·aerosol, 14 H_M, 15 g,
  // 16 sky brightness, 17 exposure, 18–20 water albedo, 21 crest scatter, 22 foam brightness,
  // 23 fog density per m (ShadingParams' defaults).
  std::array<double, 24> light = {sky.sun[0],
                                  sky.sun[1],
                                  sky.sun[2],
                                  ground[0],
                                  ground[1],
                                  ground[2],
                                  ambient[0],
                                  ambient[1],
                                  ambient[2],
                                  air.rayleigh_per_m[0],
                                  air.rayleigh_per_m[1],
                                  air.rayleigh_per_m[2],
                                  air.rayleigh_height_m,
                                  air.mie_per_m,
                                  air.mie_height_m,
                                  p.aerosol_g,
                                  p.sky_brightness,
                                  p.exposure,
                                  p.water_colour[0],
                                  p.water_colour[1],
                                  p.water_colour[2],
                                  p.crest_scatter,
                                  p.foam_brightness,
                                  p.fog_density_per_m};
  for (std::size_t i = 0; i < light.size(); ++i) light_values()[i] = static_cast<float>(light[i]);
  return lut.data();
}
/// The light of the last ocean_web_sky (24 floats, listed there).
EMSCRIPTEN_KEEPALIVE const float* ocean_web_light() { return light_values(); }

}  // extern "C"
