// The renderer's analytic sky and the sky-view table the shaders sample (ocean/render.hpp).
//
// This work is based on:
//   - Nishita, T., Sirai, T., Tadamura, K., Nakamae, E. (1993) Display of the Earth taking into
//     account atmospheric scattering, SIGGRAPH '93: Rayleigh scattering coefficients at sea level
//     β_R = (5.8, 13.5, 33.1)·10⁻⁶ m⁻¹ (680, 550, 440 nm) and scale heights H_R = 8 km,
//     H_M = 1.2 km; the Rayleigh phase 3/(16π)(1 + μ²).
//   - Henyey, L. G., Greenstein, J. L. (1941) Diffuse radiation in the galaxy, ApJ 93: the
//     aerosol phase function p(μ) = (1 − g²)/(4π(1 + g² − 2gμ)^{3/2}).
//   - Kasten, F., Young, A. T. (1989) Revised optical air mass tables and approximation formula,
//     Applied Optics 28(22): m(z) = 1/(cos z + 0.50572·(96.07995° − z)^−1.6364).
//   - Hillaire, S. (2020) A scalable and production ready sky and atmosphere rendering
//     technique, EGSR: a low-resolution sky-view table sampled per pixel instead of evaluating
//     the atmosphere per pixel, with more texels near the horizon (v = √(elevation/(π/2))).
// Equations: docs/rendering.md (R.1–R.4). shaders/render_common.glsl samples the table.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "ocean/render.hpp"

namespace ocean::render {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr std::array<double, 3> kRayleighBeta = {5.8e-6, 13.5e-6, 33.1e-6};  // 1/m
constexpr double kRayleighHeight = 8000.0;                                   // m
constexpr double kMieBeta = 2.0e-5;                                          // 1/m, clear day
constexpr double kMieHeight = 1200.0;                                        // m

double henyey_greenstein(double mu, double g) {
  const double d = 1.0 + g * g - 2.0 * g * mu;
  return (1.0 - g * g) / (4.0 * kPi * d * std::sqrt(d));
}

}  // namespace

std::array<double, 3> sun_direction(double azimuth_deg, double elevation_deg) {
  const double a = azimuth_deg * std::numbers::pi / 180.0;
  const double e = elevation_deg * std::numbers::pi / 180.0;
  return {std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)};
}

Result<ShadingParams> sky_preset(std::string_view name) {
  ShadingParams p;
  if (name == kSkyNames[0]) return p;  // clear: the defaults
  if (name == kSkyNames[1]) {          // hazy
    p.aerosol = 6.0;
    p.fog_density_per_m = 1.2e-4;
    return p;
  }
  if (name ==
      kSkyNames[2]) {  // overcast:  // a thick, forward-scattering-poor layer: diffuse grey light
    p.sun_elevation_deg = 55.0;
    p.aerosol = 40.0;
    p.aerosol_g = 0.3;
    p.sky_brightness = 1.0;
    p.fog_density_per_m = 1.5e-4;
    p.exposure = 0.55;
    p.water_colour = {0.008, 0.014, 0.016};
    return p;
  }
  if (name == kSkyNames[3]) {  // sunset
    p.sun_elevation_deg = 4.0;
    p.sun_azimuth_deg = 15.0;
    p.aerosol = 2.0;
    p.exposure = 0.6;
    return p;
  }
  return invalid_argument("sky = " + excerpt(name) + " is not a sky: must be " +
                          name_list(kSkyNames, ", ", " or "));
}

double air_mass(double mu) {
  mu = std::clamp(mu, 0.0, 1.0);
  const double zenith_deg = std::acos(mu) * 180.0 / kPi;
  return 1.0 / (mu + 0.50572 * std::pow(96.07995 - zenith_deg, -1.6364));
}

Sky::Sky(const ShadingParams& p)
    : params(p), sun(sun_direction(p.sun_azimuth_deg, p.sun_elevation_deg)) {}

std::array<double, 3> Sky::radiance(std::array<double, 3> v) const {
  v[1] = std::max(v[1], 0.0) + 1e-4;
  const double len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (double& c : v) c /= len;
  const double mu = v[0] * sun[0] + v[1] * sun[1] + v[2] * sun[2];
  const double tau_m = kMieBeta * kMieHeight * params.aerosol;
  const double m_view = air_mass(v[1]);
  const double m_sun = air_mass(std::max(sun[1], 0.0));
  // Below the horizon the sun still lights the upper sky a little (twilight), fading out.
  const double sun_visible = std::clamp(1.0 + sun[1] * 10.0, 0.0, 1.0);
  std::array<double, 3> out{};
  for (std::size_t c = 0; c < 3; ++c) {
    const double tau_r = kRayleighBeta[c] * kRayleighHeight;
    const double tau = tau_r + tau_m;
    // R.2: the phase function weighted by each process's share of the scattering.
    const double phase = (tau_r * 3.0 / (16.0 * kPi) * (1.0 + mu * mu) +
                          tau_m * henyey_greenstein(mu, params.aerosol_g)) /
                         tau;
    const double multiple = 0.25 * tau_r / tau / (4.0 * kPi);  // R.4
    const double scattered = 1.0 - std::exp(-tau * m_view);    // R.1
    // R.3: scatterers at height z see the sun through exp(−a·e^(−z/H)) of the column's depth a;
    // averaged over the exponential density of scatterers that is (1 − e^(−a))/a. A view ray
    // near the horizon scatters mostly low down, where the sun crosses the whole column: the
    // two are blended by √μ_v.
    const double a = tau * m_sun;
    const double column_mean = a > 1e-9 ? -std::expm1(-a) / a : 1.0;
    const double w = std::sqrt(std::clamp(v[1], 0.0, 1.0));
    const double through = w * column_mean + (1.0 - w) * std::exp(-a);
    const double sun_light = params.sun_irradiance * through * sun_visible;
    out[c] = params.sky_brightness * sun_light * scattered * (phase + multiple);
  }
  return out;
}

Sky::Air Sky::air() const {
  return {kRayleighBeta, kRayleighHeight, kMieBeta * params.aerosol, kMieHeight};
}

namespace {

// The mean of e^(−y/H) over heights from y_low to y_high (a straight path's mean density in a
// plane-parallel exponential atmosphere): e^(−y_low/H)·(1 − e^(−x))/x, x = (y_high − y_low)/H.
double mean_density(double y_low, double y_high, double scale_height_m) {
  const double x = (y_high - y_low) / scale_height_m;
  return std::exp(-y_low / scale_height_m) * (x < 1e-9 ? 1.0 : -std::expm1(-x) / x);
}

}  // namespace

Sky::AerialPerspective Sky::aerial_perspective(double eye_y_m, double point_y_m,
                                               double distance_m,
                                               std::array<double, 3> view_dir) const {
  const Air a = air();
  const double low = std::min(eye_y_m, point_y_m), high = std::max(eye_y_m, point_y_m);
  const double tau_m = a.mie_per_m * distance_m * mean_density(low, high, a.mie_height_m);
  const double rayleigh_density = mean_density(low, high, a.rayleigh_height_m);
  const double mu = view_dir[0] * sun[0] + view_dir[1] * sun[1] + view_dir[2] * sun[2];
  const std::array<double, 3> sun_ground = sun_irradiance_ground();
  AerialPerspective out{};
  for (std::size_t c = 0; c < 3; ++c) {
    const double tau_r = a.rayleigh_per_m[c] * distance_m * rayleigh_density;
    const double tau = tau_r + tau_m;
    out.transmittance[c] = std::exp(-tau);
    if (!(tau > 0.0)) continue;
    // R.2 and R.4's phase and multiple-scattering share, weighted by the segment's own depths.
    const double phase = (tau_r * 3.0 / (16.0 * kPi) * (1.0 + mu * mu) +
                          tau_m * henyey_greenstein(mu, params.aerosol_g) +
                          0.25 * tau_r / (4.0 * kPi)) /
                         tau;
    out.inscattered[c] = params.sky_brightness * sun_ground[c] * -std::expm1(-tau) * phase;
  }
  return out;
}

std::array<double, 3> Sky::sun_irradiance_ground() const {
  const double tau_m = kMieBeta * kMieHeight * params.aerosol;
  const double m = air_mass(std::max(sun[1], 0.0));
  const double visible = sun[1] > 0.0 ? 1.0 : 0.0;
  std::array<double, 3> out{};
  for (std::size_t c = 0; c < 3; ++c)
    out[c] = params.sun_irradiance * visible *
             std::exp(-(kRayleighBeta[c] * kRayleighHeight + tau_m) * m);
  return out;
}

std::array<double, 3> Sky::sky_irradiance_horizontal() const {
  // Midpoint rule over 16 elevations × 32 azimuths of the upper hemisphere.
  constexpr int kElevations = 16, kAzimuths = 32;
  std::array<double, 3> sum{};
  for (int i = 0; i < kElevations; ++i) {
    const double e = (i + 0.5) / kElevations * kPi / 2.0;
    const double d_omega = std::cos(e) * (kPi / 2.0 / kElevations) * (2.0 * kPi / kAzimuths);
    for (int j = 0; j < kAzimuths; ++j) {
      const double a = (j + 0.5) / kAzimuths * 2.0 * kPi;
      const std::array<double, 3> l =
          radiance({std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)});
      for (std::size_t c = 0; c < 3; ++c) sum[c] += l[c] * std::sin(e) * d_omega;
    }
  }
  return sum;
}

void Sky::fill_lut(std::span<float> rgba) const {
  for (int y = 0; y < kLutHeight; ++y) {
    const double v = (y + 0.5) / kLutHeight;
    const double e = v * v * kPi / 2.0;
    for (int x = 0; x < kLutWidth; ++x) {
      const double a = (x + 0.5) / kLutWidth * 2.0 * kPi;
      const std::array<double, 3> l =
          radiance({std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a)});
      float* t = &rgba[static_cast<std::size_t>(4 * (y * kLutWidth + x))];
      for (int c = 0; c < 3; ++c) t[c] = static_cast<float>(l[static_cast<std::size_t>(c)]);
      t[3] = 1.0f;
    }
  }
}

}  // namespace ocean::render
