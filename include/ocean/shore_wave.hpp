// ocean/shore_wave.hpp — one wave train refracted and shoaled towards a shore over a bathymetry
// (docs/waves.md W.32–W.37): linear ray theory on the bathymetry's grid, the deterministic wave
// that the depth law (W.12) takes out of the spectral sea's bands near the shore.
#pragma once

#include <array>
#include <vector>

#include "ocean/core.hpp"
#include "ocean/waves.hpp"

namespace ocean::waves {

/// The wavenumber of a linear wave of angular frequency ω over water of depth d (W.32): the root
/// k > 0 of the dispersion relation ω² = g·k·tanh(k·d), rad/m. ω²/g for d = +∞; +∞ for d ≤ 0.
/// Newton's method to a relative 1e-14. Never allocates.
double shore_wavenumber(double omega_radps, double depth_m, double gravity_mps2);
/// The group velocity of that wave (W.33): c_g = (ω/k)·½·(1 + 2kd/sinh 2kd), m/s; g/(2ω) in deep
/// water, 0 for d ≤ 0.
double shore_group_velocity(double omega_radps, double depth_m, double gravity_mps2);

/// One deterministic wave train refracted and shoaled over a bathymetry (W.32–W.37): a sea's peak
/// wave entering the map from deep water, carried towards the shore by linear ray theory.
struct ShoreWaveParams {
  /// Water depth over the map's grid, m (as DampingParams::bathymetry; negative: land). The wave
  /// enters through the map's edge that faces it (its offshore edge); its phase and flux are
  /// computed on the map's own cells.
  PlacedMap bathymetry;
  double period_s = 8.0;       ///< T, s, in [0.5, 60]; ω = 2π/T
  double deep_height_m = 1.0;  ///< H0, crest-to-trough height in deep water, m, in [0, 100]
  double direction_deg = 0.0;  ///< where the wave travels in deep water: 0 = +x, 90 = +z; finite
  double gravity_mps2 = 9.81;  ///< g, in [0.1, 100]
  double breaking_index = kMcCowanBreakingIndex;  ///< γ: H ≤ γ·d (W.25, W.36), in [0.3, 1.5]
};
/// invalid_argument naming the field: no map or a bad placement, non-finite depths, a period,
/// height, direction, g or index out of range.
Status validate(const ShoreWaveParams& params);

/// The shore wave at one point (W.32–W.37).
struct ShoreWavePoint {
  double depth_m = 0.0;           ///< d (the map's bilinear value)
  double wavenumber_radpm = 0.0;  ///< k(d) (W.32); 0 on land and where the wave does not reach
  double phase_rad = 0.0;         ///< S, the eikonal's phase (W.34); crests at S − ω·t = 2πn
  /// Unit direction of travel (x, z), ∇S/|∇S| (W.34); (0, 0) where the wave does not reach.
  std::array<double, 2> direction{0.0, 0.0};
  double shoaling = 0.0;    ///< K_s = √(c_g0/c_g) (W.35)
  double refraction = 0.0;  ///< K_r = √(b0/b), the rays' convergence (W.35)
  double height_m = 0.0;    ///< H = min(H0·K_s·K_r, γ·d) (W.35–W.36)
  bool breaking = false;    ///< H0·K_s·K_r ≥ γ·d: the wave has broken here (W.36)
};

/// The shore wave's phase, direction and height over its bathymetry's grid, computed once by
/// make(): the eikonal |∇S| = k(d) by fast sweeping from the offshore edge (W.34) and the energy
/// flux's balance ∇·(E·c_g·∇S/|∇S|) = 0 by an upwind, conservative sweep in the order of S
/// (W.35). Immutable; const methods are thread-safe and never allocate.
class ShoreWave {
 public:
  /// Validates and solves on the map's rows × cols cells: four sweeps per round until no cell
  /// changes (at most 64 rounds), then one sort and one pass for the flux. Allocates.
  static Result<ShoreWave> make(ShoreWaveParams params);
  [[nodiscard]] const ShoreWaveParams& params() const { return params_; }
  [[nodiscard]] double omega_radps() const { return omega_; }
  /// The wave at world (x, z): the cells' values bilinear between cell centres (clamped at the
  /// map's edge cells); off the map, the deep-water wave (K_s = K_r = 1, S = k0·d̂·x).
  [[nodiscard]] ShoreWavePoint at(double x, double z) const;
  /// Linear (Airy) surface of the wave at (x, z), time t (W.37): (Dx, h, Dz) with
  /// h = (H/2)·cos(S − ω·t) and a horizontal displacement −(H/2)·d̂·sin(S − ω·t)/tanh(k·d),
  /// the latter times `choppiness`. Never allocates.
  [[nodiscard]] std::array<double, 3> displacement_at(double x, double z, double time_s,
                                                      double choppiness = 1.0) const;

 private:
  ShoreWaveParams params_;
  double omega_ = 0.0;
  double deep_wavenumber_ = 0.0;
  // Per cell (row·cols + col): the phase S (+inf where unreached), the unit direction and the
  // height H; k and the coefficients follow from the cell's depth.
  std::vector<double> phase_, dir_x_, dir_z_, ray_density_;
};

}  // namespace ocean::waves
