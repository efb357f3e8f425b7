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

namespace {

using packing::Gradients;

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
  const packing::FoamTerms source = state.foam_source;
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
            const packing::SurfacePoint p = packing::surface_point(g);
            const float jacobian = p.jacobian;
            const float nx = p.normal[0], ny = p.normal[1], nz = p.normal[2];
            // Foam: the source on J, accumulated with the decay of Vincevičius 2024, §2.4.2
            // (M.7.4).
            const float foam = packing::accumulate_foam(packing::foam_source(jacobian, source),
                                                        state.foam[i], reset_foam, decay);
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
