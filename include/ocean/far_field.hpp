// ocean/far_field.hpp — the sea beyond the simulation's tiles (docs/rendering.md R.13–R.14): seed
// 003's far field, three octaves of gradient noise (ocean/far_noise.hpp: the fit to cascade 0 and
// the CPU reference) blended with the FFT field by a Hermite ratio of the distance (VR-GIS
// FFT+Perlin, eqs. 6–7). The renderer (ocean/render.hpp) evaluates it in its shaders (one source
// with the reference: src/sim/far_noise.h, through src/render/shaders/far_noise.h).
//
// Contract: plain functions, no allocation beyond the returned values, thread-safe.
#pragma once

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
/// Seed 003's eq. 6: 0 up to near_m, 1 from far_m, the Hermite step −2t³ + 3t² between.
double far_field_ratio(const FarFieldRange& range, double distance_m);

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
