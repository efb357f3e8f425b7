// Finalisation: displacement (float3 + half4), surface gradients, normals, Jacobian, foam with
// accumulation, and the base level of the packed RGBA8 map.
//
// This work is based on:
//   - Aebi, VR Ocean, §3.7–3.8: eq. 44 (displacement assembly), eqs. 45–46 (central differences
//     with toroidal wrap), eq. 48 (Jacobian), eq. 49 (roughness → normal length), eqs. 50–51
//     (RGBA8).
//   - Mitchell 2005: Sobel-filtered normals. Vincevičius 2024, §2.4 (Jacobian foam, accumulation
//     listing 2.4).
//   - Tessendorf, J. (2001) Simulating Ocean Water §4.4 (Jacobian of the choppy map).
// Equations: docs/math.md §7.
#include <algorithm>
#include <cmath>

#include "cpu_backend.hpp"
#include "ocean/half.hpp"

namespace ocean::cpu {

float normal_length_from_roughness(float r) {
  return 1.0f - r * (0.306f + r * (0.113f + r * 0.081f));  // Aebi, VR Ocean, eq. 49
}

float smoothness_from_normal_length(float length) {
  const float t = std::clamp(3.0f * length - 2.0f, 0.0f, 1.0f);  // eq. 53: (|n| − 2/3)/(1/3)
  // r = 1 − t·(0.85 + 0.15·t), factored as (1 − t)(1 + 0.15·t) so that r(1) is exactly 0.
  const float r = (1.0f - t) * (1.0f + 0.15f * t);
  return 1.0f - std::sqrt(r);
}

std::uint32_t pack_rgba8(float nx, float nz, float blue, float smoothness) {
  const auto quantise = [](float v) {  // ⌊saturate(v)·255 + 0.5⌋   (eq. 50)
    return static_cast<std::uint32_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f);
  };
  return quantise(nx * 0.5f + 0.5f) | (quantise(nz * 0.5f + 0.5f) << 8) | (quantise(blue) << 16) |
         (quantise(smoothness) << 24);  // eq. 51
}

namespace {

struct Gradients {
  // ∂/∂x and ∂/∂z of (Dx, h, Dz), world units.
  float dx_dx, h_dx, dz_dx, dx_dz, h_dz, dz_dz;
};

enum class Stencil { central, sobel };

// Derivatives of the displacement field at (col, row) with toroidal wrap (Aebi, VR Ocean, eq. 46).
template <Stencil kStencil>
Gradients stencil_gradients(const float* d, int n, int col, int row, float inv_spacing) {
  const int mask = n - 1;
  const auto at = [&](int c, int r, int comp) {
    return d[3 * static_cast<std::size_t>(((r & mask) * n) + (c & mask)) +
             static_cast<std::size_t>(comp)];
  };
  float gx[3], gz[3];
  for (int comp = 0; comp < 3; ++comp) {
    if constexpr (kStencil == Stencil::central) {  // eq. 45
      gx[comp] = (at(col + 1, row, comp) - at(col - 1, row, comp)) * 0.5f * inv_spacing;
      gz[comp] = (at(col, row + 1, comp) - at(col, row - 1, comp)) * 0.5f * inv_spacing;
    } else {  // Sobel: smoothed central difference, weights (1, 2, 1)/8
      gx[comp] = ((at(col + 1, row - 1, comp) + 2.0f * at(col + 1, row, comp) +
                   at(col + 1, row + 1, comp)) -
                  (at(col - 1, row - 1, comp) + 2.0f * at(col - 1, row, comp) +
                   at(col - 1, row + 1, comp))) *
                 0.125f * inv_spacing;
      gz[comp] = ((at(col - 1, row + 1, comp) + 2.0f * at(col, row + 1, comp) +
                   at(col + 1, row + 1, comp)) -
                  (at(col - 1, row - 1, comp) + 2.0f * at(col, row - 1, comp) +
                   at(col + 1, row - 1, comp))) *
                 0.125f * inv_spacing;
    }
  }
  return {gx[0], gx[1], gx[2], gz[0], gz[1], gz[2]};
}

template <NormalMethod kMethod>
void gradients_pass(CascadeState& state, const SimulationConfig& config, double dt_s,
                    bool reset_foam, CascadeFrame& out, TaskRunner& runner) {
  const int n = state.resolution;
  const float inv_spacing = static_cast<float>(n / state.patch_size_m);  // N/L (eq. 45)
  const float base_length = normal_length_from_roughness(static_cast<float>(config.roughness));
  const float smoothness = smoothness_from_normal_length(base_length);
  const float j_start = static_cast<float>(config.foam.jacobian_start);
  const float j_range = static_cast<float>(config.foam.jacobian_start - config.foam.jacobian_full);
  const float decay = static_cast<float>(config.foam.decay_per_s * dt_s);
  const bool blue_is_foam = config.blue_channel == BlueChannel::foam;
  const FrameOutputs want = {
      .normal = !out.normal.empty(), .jacobian = !out.jacobian.empty(), .foam = !out.foam.empty()};
  runner.parallel_for(
      static_cast<std::size_t>(n), 8, [&](std::size_t row_begin, std::size_t row_end) {
        for (int row = static_cast<int>(row_begin); row < static_cast<int>(row_end); ++row) {
          for (int col = 0; col < n; ++col) {
            const std::size_t i = static_cast<std::size_t>(row * n + col);
            Gradients g;
            if constexpr (kMethod == NormalMethod::analytic) {
              g = {state.plane_im[2][i], state.plane_im[1][i], state.plane_im[3][i],
                   state.plane_im[3][i], state.plane_re[2][i], state.plane_re[3][i]};
              // ∂Dz/∂x = ∂Dx/∂z for the irrotational choppy field (both are −λ·kx·kz/k·h̃).
            } else if constexpr (kMethod == NormalMethod::sobel) {
              g = stencil_gradients<Stencil::sobel>(out.displacement.data(), n, col, row,
                                                    inv_spacing);
            } else {
              g = stencil_gradients<Stencil::central>(out.displacement.data(), n, col, row,
                                                      inv_spacing);
            }
            // Jacobian of the horizontal map x → x + D (eq. 48).
            const float jxx = 1.0f + g.dx_dx, jzz = 1.0f + g.dz_dz;
            const float jacobian = jxx * jzz - g.dx_dz * g.dz_dx;
            // Normal of the displaced surface: ∂p/∂z × ∂p/∂x (M.7.5; eq. 47 when λ = 0).
            float nx = g.h_dz * g.dz_dx - jzz * g.h_dx;
            float ny = jacobian;
            float nz = g.dx_dz * g.h_dx - g.h_dz * jxx;
            const float length = std::sqrt(nx * nx + ny * ny + nz * nz);
            if (length > 0.0f) {
              nx /= length, ny /= length, nz /= length;
            } else {
              nx = 0.0f, ny = 1.0f, nz = 0.0f;
            }
            // Foam: a ramp on J, accumulated with the decay of Vincevičius 2024, §2.4.2
            // (M.7.4).
            const float now = std::clamp((j_start - jacobian) / j_range, 0.0f, 1.0f);
            float foam = now;
            if (!reset_foam) {
              const float accumulated = state.foam[i] - decay / std::max(now, 0.5f);
              foam = std::clamp(std::max(accumulated, now), 0.0f, 1.0f);
            }
            state.foam[i] = foam;
            if (want.jacobian) out.jacobian[i] = jacobian;
            if (want.foam) out.foam[i] = foam;
            if (want.normal) {
              out.normal[3 * i + 0] = nx;
              out.normal[3 * i + 1] = ny;
              out.normal[3 * i + 2] = nz;
            }
            const float blue = blue_is_foam ? foam : std::clamp(jacobian * 0.5f + 0.5f, 0.0f, 1.0f);
            float* work =
                &state.mip_work[4 * i];  // level 0: roughness-scaled normal and blue value
            work[0] = nx * base_length;
            work[1] = ny * base_length;
            work[2] = nz * base_length;
            work[3] = blue;
            out.packed_mips[i] = pack_rgba8(nx, nz, blue, smoothness);
          }
        }
      });
}

}  // namespace

void assemble_displacement_reference(const CascadeState& state, const float* dz, CascadeFrame& out,
                                     TaskRunner& runner) {
  const int n = state.resolution;
  // Displacement assembly (eq. 44): the FFT already applied the sign and λ is in the spectra.
  runner.parallel_for(static_cast<std::size_t>(n), 8,
                      [&](std::size_t row_begin, std::size_t row_end) {
                        for (std::size_t i = row_begin * static_cast<std::size_t>(n);
                             i < row_end * static_cast<std::size_t>(n); ++i) {
                          const float d[3] = {state.plane_im[0][i], state.plane_re[0][i], dz[i]};
                          for (std::size_t c = 0; c < 3; ++c) {
                            out.displacement[3 * i + c] = d[c];
                            out.displacement_half[4 * i + c] = float_to_half(d[c]);
                          }
                          out.displacement_half[4 * i + 3] = 0;
                        }
                      });
}

void finalize(CascadeState& state, const SimulationConfig& config, double dt_s, bool reset_foam,
              CascadeFrame& out, TaskRunner& runner) {
  switch (config.normals) {
    case NormalMethod::central_difference:
      gradients_pass<NormalMethod::central_difference>(state, config, dt_s, reset_foam, out,
                                                       runner);
      break;
    case NormalMethod::analytic:
      gradients_pass<NormalMethod::analytic>(state, config, dt_s, reset_foam, out, runner);
      break;
    case NormalMethod::sobel:
      gradients_pass<NormalMethod::sobel>(state, config, dt_s, reset_foam, out, runner);
      break;
  }
}

}  // namespace ocean::cpu
