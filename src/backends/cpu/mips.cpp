// The mip chain of the packed normal/foam/smoothness map: 2×2 box filter of the unnormalised,
// roughness-scaled normals, whose shrinking length becomes smoothness.
//
// This work is based on:
//   - Aebi, VR Ocean, §3.9 and §4.4: eq. 52 (box filter of unnormalised normals), eq. 53 (normal
//     length → smoothness), eq. 55 (contiguous mip offsets); Toksvig, M. (2005) Mipmapping
//     normal maps, J. Graphics Tools 10(3) (normal length as a variance measure).
// Equations: docs/math.md (M.7.5).
#include <bit>
#include <cmath>

#include "cpu_backend.hpp"

namespace ocean::cpu {

void build_mips(CascadeState& state, CascadeFrame& out, TaskRunner& runner) {
  const int n = state.resolution;
  const int levels = std::countr_zero(static_cast<unsigned>(n));
  for (int level = 1; level <= levels; ++level) {
    const int size = n >> level;
    const std::size_t src_offset = mip_offset(n, level - 1);
    const std::size_t dst_offset = mip_offset(n, level);
    const int src_size = size * 2;
    runner.parallel_for(
        static_cast<std::size_t>(size), 8, [&](std::size_t row_begin, std::size_t row_end) {
          for (int row = static_cast<int>(row_begin); row < static_cast<int>(row_end); ++row) {
            for (int col = 0; col < size; ++col) {
              float sum[4] = {0.0f, 0.0f, 0.0f, 0.0f};
              for (int j = 0; j < 2; ++j) {
                for (int i = 0; i < 2; ++i) {  // eq. 52
                  const std::size_t s =
                      src_offset + static_cast<std::size_t>((2 * row + j) * src_size + 2 * col + i);
                  for (int c = 0; c < 4; ++c)
                    sum[c] += state.mip_work[4 * s + static_cast<std::size_t>(c)];
                }
              }
              const std::size_t d = dst_offset + static_cast<std::size_t>(row * size + col);
              for (int c = 0; c < 4; ++c)
                state.mip_work[4 * d + static_cast<std::size_t>(c)] = 0.25f * sum[c];
              const float* v = &state.mip_work[4 * d];
              const float length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
              const float smoothness = smoothness_from_normal_length(length);  // eq. 53
              const float inv = length > 0.0f ? 1.0f / length : 0.0f;
              out.packed_mips[d] = pack_rgba8(v[0] * inv, v[2] * inv, v[3], smoothness);
            }
          }
        });
  }
}

}  // namespace ocean::cpu
