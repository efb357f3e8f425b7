// ocean/conformance.hpp — backend conformance: the written error bounds of a backend against the
// CPU backend's scalar reference pipeline, one comparison of two frames, and the case list that
// `ocean validate` and tests/backends/conformance_test.cpp both run.
//
// The reference is the scalar reference pipeline (cpu::CpuPipeline::scalar_reference of
// ocean/backends/cpu.hpp: scalar evolution, radix-2 FFT, scalar finalize and mips). The backend
// under test is a backend of the table (ocean/backends.hpp): "cpu" runs the fused SIMD pipeline,
// so its conformance compares the two CPU pipelines; "vulkan" runs the compute shaders.
//
// Two sets of bounds, each a small multiple of the largest error measured over every case run at
// each of 64…1024 texels (bench/conformance_errors; docs/vulkan.md, "Conformance bounds", has the
// table and the reasons):
//   kCpuBounds     the fused SIMD pipeline: 4× the measured maxima, rounded up to one digit;
//   kDeviceBounds  a GPU backend: measured on lavapipe only; 4× the larger of that and of the
//                  error a GPU with NVIDIA's documented sin/cos accuracy (2^-21.19 absolute on
//                  [−π, π], CUDA guide) adds, rounded up to one digit.
// Hs = 4·√(Σ_c var h_c) of the reference frame. Displacement FP16 (half4): max |ΔD| ≤ 2^-10·|D| +
// the FP32 bound·Hs (one FP16 ulp plus the FP32 bound: derived, ratio ≤ 1). Packed RGBA8 (all
// mips): every channel within 1 LSB (a value at a rounding boundary flips with any difference),
// and a bounded share of texels that differ at all.
//
// Pure functions of their arguments: thread-safe, no allocation except the case list and
// run_case's result; errors are Status values from the backends.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "ocean/sim.hpp"

namespace ocean::conformance {

/// Bounds of one kind of backend. A frame conforms when every error is at most its bound.
struct Bounds {
  double height_rel_hs = 0.0;        ///< max |Δh| / Hs, FP32 height (the y of the displacement)
  double displacement_rel_hs = 0.0;  ///< max |ΔD| / Hs over x, y and z, FP32 displacement
  /// max |ΔD| of the half4 displacement / (2^-10·|D| + displacement_rel_hs·Hs)
  double displacement_half_rel_bound = 1.0;
  double normal = 0.0;           ///< max |Δn|, unit-vector components
  double jacobian = 0.0;         ///< max |ΔJ|
  double foam = 0.0;             ///< max |Δfoam|, foam in [0, 1]
  int packed_lsb = 1;            ///< max channel difference of the packed RGBA8 maps, LSB
  double packed_fraction = 0.0;  ///< share of packed texels (all mips) that differ at all
};

/// The CPU backend's fused SIMD pipeline against the scalar reference pipeline: 4× the largest
/// error measured (both on the CPU, float32, FFTs in other orders and sin/cos by another
/// polynomial), rounded up to one significant digit. Comments: measured.
inline constexpr Bounds kCpuBounds{.height_rel_hs = 2e-6,        // 3.9e-7
                                   .displacement_rel_hs = 2e-6,  // 4.3e-7
                                   .normal = 9e-6,               // 2.0e-6
                                   .jacobian = 7e-6,             // 1.7e-6
                                   .foam = 2e-5,                 // 3.4e-6
                                   .packed_fraction = 2e-4};     // 4.6e-5
/// A GPU backend (Vulkan) against the scalar reference pipeline: 4× the larger of the error
/// measured on lavapipe and the error NVIDIA's documented sin/cos accuracy adds (emulated on the
/// CPU), rounded up to one significant digit; at least twice the two together. Comments:
/// measured on lavapipe, emulated sin/cos.
inline constexpr Bounds kDeviceBounds{.height_rel_hs = 6e-6,        // 4.1e-7, 1.3e-6
                                      .displacement_rel_hs = 6e-6,  // 4.9e-7, 1.3e-6
                                      .normal = 9e-6,               // 1.6e-6, 2.1e-6
                                      .jacobian = 7e-6,             // 1.7e-6, 1.6e-6
                                      .foam = 2e-5,                 // 3.4e-6, 3.8e-6
                                      .packed_fraction = 4e-4};     // 2.9e-5, 9.2e-5

/// The far field's noise map (SimulationConfig::far_noise, docs/rendering.md R.13a) of a GPU
/// backend (Vulkan, CUDA) against the CPU backend's: max |Δh| over the map's rms height and max
/// |Δ∂h/∂x|, |Δ∂h/∂z| over its rms slope component. Both sides run the same texel arithmetic
/// (src/sim/far_noise.h) and differ by the device's sin/cos of the lattice gradients' angles (and
/// contracted multiply-adds). Bound: 4× the worst case NVIDIA's documented sin/cos accuracy
/// (2^-21.19 absolute, CUDA guide) allows, rounded up to one digit — every corner's error aligned:
/// a gradient off by δ = 2^-21.19 per component moves g·d by at most 2δ (|d| ≤ √2) and the height
/// by a_o·2δ, the slope by a_o/s_o·(δ + 2δ·Σ|∂W|), Σ|∂W| ≤ 2·15/8; over the rms of three
/// octaves (√(G·Σa²), G = 0.0465 and G_s = 0.390 of unit noise) at most √3·2δ/√G = 6.7e-6 and
/// √3·8.5δ/√G_s = 1.0e-5. Measured on lavapipe: 2.3e-6 and 1.1e-6. The CUDA kernel calls the
/// accurate cosf/sinf (2 ulp: at most 2^-23 absolute on [−1, 1], inside δ) without contraction.
struct FarNoiseBounds {
  double height_rel = 0.0;
  double slope_rel = 0.0;
};
inline constexpr FarNoiseBounds kFarNoiseDeviceBounds{.height_rel = 3e-5, .slope_rel = 4e-5};

/// The bounds the backend named `backend` (a name of list_backends()) is held to: kCpuBounds
/// for "cpu", kDeviceBounds for every other.
const Bounds& bounds_for(std::string_view backend);

/// How far one frame (or, merged, several) is from the reference; fields as in Bounds.
struct Errors {
  double height_rel_hs = 0.0;
  double displacement_rel_hs = 0.0;
  double displacement_half_rel_bound = 0.0;
  double normal = 0.0;
  double jacobian = 0.0;
  double foam = 0.0;
  int packed_lsb = 0;
  double packed_fraction = 0.0;
  /// The worst of this and `other`, field by field.
  void merge(const Errors& other);
  /// Every field within `bounds`.
  [[nodiscard]] bool pass(const Bounds& bounds) const;
};

/// Hs = 4·√(Σ_c var h_c) over the texels of every cascade of `frame`, m.
double significant_height(const Frame& frame);

/// Errors of `other` against `reference`. Both frames come from the same configuration (same
/// cascades, sizes and outputs); the reference's Hs must be > 0 (a flat sea has no relative
/// error). `bounds` sets the FP32 part of the half map's allowance (displacement_rel_hs).
Errors compare(const Frame& reference, const Frame& other, const Bounds& bounds);

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

/// Configures `reference` (the scalar reference pipeline, above) and `other` for the case
/// (reference first; the first failure is returned), steps both through its times and compares
/// every frame against `bounds`' half-map allowance. Backend-specific checks (e.g. a Vulkan
/// backend's status() after a frame) are the caller's.
Result<std::vector<FrameResult>> run_case(const Case& c, Backend& reference, Backend& other,
                                          TaskRunner& runner, const Bounds& bounds);

}  // namespace ocean::conformance
