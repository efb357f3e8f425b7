// ocean/conformance.hpp — backend conformance: the written error bounds of a backend against the
// CPU reference backend, one comparison of two frames, and the case list that `ocean validate`
// and tests/backends/conformance_test.cpp both run.
//
// Bounds (src/backends/vulkan/README.md), Hs = 4·√(Σ_c var h_c) of the reference frame:
//   displacement (FP32)       max |ΔD| ≤ 1e-4·Hs
//   displacement (FP16 half4) max |ΔD| ≤ 2^-10·|D| + 1e-4·Hs (one half ulp plus the FP32 bound)
//   normal                    max |Δn| ≤ 1e-4 (unit vector components)
//   Jacobian                  max |ΔJ| ≤ 1e-4
//   foam                      max |Δfoam| ≤ 1e-4
//   packed RGBA8 (all mips)   every channel within 1 LSB; ≤ 0.1 % of texels differ at all
//
// Pure functions of their arguments: thread-safe, no allocation except the case list and
// run_case's result; errors are Status values from the backends.
#pragma once

#include <string>
#include <vector>

#include "ocean/sim.hpp"

namespace ocean::conformance {

/// The bounds above. A frame conforms when every error is at most its bound.
struct Bounds {
  double displacement_rel_hs = 1e-4;  ///< max |ΔD| / Hs, FP32 displacement
  /// max |ΔD| of the half4 displacement / (2^-10·|D| + displacement_rel_hs·Hs)
  double displacement_half_rel_bound = 1.0;
  double normal = 1e-4;           ///< max |Δn|, unit-vector components
  double jacobian = 1e-4;         ///< max |ΔJ|
  double foam = 1e-4;             ///< max |Δfoam|, foam in [0, 1]
  int packed_lsb = 1;             ///< max channel difference of the packed RGBA8 maps, LSB
  double packed_fraction = 1e-3;  ///< share of packed texels (all mips) that differ at all
};
inline constexpr Bounds kBounds{};

/// How far one frame (or, merged, several) is from the reference; fields as in Bounds.
struct Errors {
  double displacement_rel_hs = 0.0;
  double displacement_half_rel_bound = 0.0;
  double normal = 0.0;
  double jacobian = 0.0;
  double foam = 0.0;
  int packed_lsb = 0;
  double packed_fraction = 0.0;
  /// The worst of this and `other`, field by field.
  void merge(const Errors& other);
  /// Every field within kBounds.
  [[nodiscard]] bool pass() const;
};

/// Hs = 4·√(Σ_c var h_c) over the texels of every cascade of `frame`, m.
double significant_height(const Frame& frame);

/// Errors of `other` against `reference`. Both frames come from the same configuration (same
/// cascades, sizes and outputs); the reference's Hs must be > 0 (a flat sea has no relative
/// error).
Errors compare(const Frame& reference, const Frame& other);

/// One configuration and the consecutive times it is stepped through (foam accumulates between
/// them). Wind sea 14 m/s, choppiness 1.2; JONSWAP/TMA over an 80 km fetch, TMA at 20 m depth.
struct Case {
  std::string name;
  int resolution = 0;
  std::vector<double> patches_m;  ///< cascade patch sizes, m, largest first
  SpectrumModel model = SpectrumModel::jonswap;
  NormalMethod normals = NormalMethod::central_difference;
  double loop_period_s = 0.0;  ///< 0 = no loop
  std::vector<double> times_s;
};

/// The cases every backend runs: 64…1024 texels, 1–3 cascades, Phillips/JONSWAP/TMA, each normal
/// method, looping and not, times from 0 to three days; small enough for lavapipe on two cores.
const std::vector<Case>& cases();

/// The configuration of a case.
SimulationConfig make_config(const Case& c);

/// One compared frame of a case.
struct FrameResult {
  double time_s = 0.0;        ///< the time stepped to
  double other_time_s = 0.0;  ///< the time `other` stamped on its frame (must equal time_s)
  Errors errors;
};

/// Configures `reference` and `other` for the case (reference first; the first failure is
/// returned), steps both through its times and compares every frame. Backend-specific checks
/// (e.g. a Vulkan backend's status() after a frame) are the caller's.
Result<std::vector<FrameResult>> run_case(const Case& c, Backend& reference, Backend& other,
                                          TaskRunner& runner);

}  // namespace ocean::conformance
