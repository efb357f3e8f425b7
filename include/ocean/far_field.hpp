// ocean/far_field.hpp — the sea beyond the simulation's tiles (docs/rendering.md R.13–R.14): seed
// 003's far field, three octaves of gradient noise (ocean/far_noise.hpp: the fit to cascade 0 and
// the CPU reference) blended with the FFT field by a Hermite ratio of the distance (VR-GIS
// FFT+Perlin, eqs. 6–7). The renderer (ocean/render.hpp) evaluates it in its shaders (one source
// with the reference: src/sim/far_noise.h, through src/render/shaders/far_noise.h).
//
// Contract: plain functions, no allocation beyond the returned values, thread-safe.
#pragma once

#include <array>

#include "ocean/core.hpp"
#include "ocean/far_noise.hpp"

namespace ocean::render {

/// Where the far field takes over: VR-GIS FFT+Perlin's D_min and D_max, distances from the camera
/// to the undisplaced sea point, m. Nearer than near_m the picture is the simulation alone (what
/// height queries, wakes and floating objects see); beyond far_m it is the far field alone.
struct FarFieldRange {
  double near_m = 1000.0;  ///< D_min, finite, ≥ 0
  double far_m = 2500.0;   ///< D_max, finite, > near_m
};
/// invalid_argument for a negative or non-finite distance, or near_m ≥ far_m (one line).
Status validate(const FarFieldRange& range);
/// [VR-GIS FFT+Perlin], eq. 6: 0 up to near_m, 1 from far_m, the Hermite step −2t³ + 3t² between.
double far_field_ratio(const FarFieldRange& range, double distance_m);

/// The far field's noise map around a moving camera (docs/rendering.md R.13b, eqs. R.13b-2 and
/// R.13b-3). The window's origin is snapped to kFarNoiseSnapTexels texels, so the map's texels
/// (and its first log2(32) = 5 mip levels) lie on the same world points however the camera
/// moves, and the renderer fades the map out over its outer kFarNoiseFadeTexels texels.
inline constexpr int kFarNoiseSnapTexels = 32;
inline constexpr int kFarNoiseFadeTexels = 16;
/// Resolutions the renderer takes: 0 (no map) or [kFarNoiseMinResolution, 4096].
inline constexpr int kFarNoiseMinResolution = 128;
/// The map's default resolution in `ocean render` and `ocean view` (docs/performance.md: its
/// cost on the CPU backend and on lavapipe).
inline constexpr int kFarNoiseDefaultResolution = 512;
/// The window of N = `resolution` texels whose full-weight part holds the disc of radius
/// range.far_m about every camera that far_noise_origin places in it: side
/// S = 2·D_max/(1 − 2(32 + 16 + 1)/N) (R.13b-3), origin from far_noise_origin for the camera at
/// (x, z). invalid_argument (one line) for a bad range or a resolution outside
/// [kFarNoiseMinResolution, 4096], or a window beyond the simulation's 1e6 m.
Result<FarNoiseConfig> far_noise_window(const FarFieldRange& range, int resolution, double x_m,
                                        double z_m);
/// The origin of `window` (its size and resolution) for a camera at world (x, z): the corner
/// S/2 before the camera, rounded down to a multiple of 32 texels (R.13b-2); the camera then lies
/// within [S/2, S/2 + 32 texels) of the origin on each axis.
std::array<double, 2> far_noise_origin(const FarNoiseConfig& window, double x_m, double z_m);

// The noise and its fit, as the renderer's callers have always named them.
using ocean::BandStatistics;
using ocean::cascade0_statistics;
using ocean::far_field_noise;
using ocean::FarFieldNoise;
using ocean::FarFieldSample;
using ocean::fit_far_field_noise;
using ocean::unit_noise_moments;
using ocean::UnitNoiseMoments;

}  // namespace ocean::render
