#version 450
// fft_columns.comp — the second FFT axis: each workgroup transforms one column of one plane of
// one cascade and applies the (−1)^(col+row) sign that moves DC from the centre of the spectrum
// (Aebi, VR Ocean, eqs. 42–43). Dispatch (N, planes, cascades). Mirrors fft::Plan2D::inverse.
#include "common.glsl"
#include "fft.glsl"

void main() {
  const uint col = gl_WorkGroupID.x, plane = gl_WorkGroupID.y, cascade = gl_WorkGroupID.z;
  const uint base = (cascade * params.planes + plane) * N * N + col;
  for (uint row = gl_LocalInvocationID.x; row < N; row += gl_WorkGroupSize.x)
    line[row] = planes[base + row * N];
  barrier();
  inverse_fft_shared();
  for (uint row = gl_LocalInvocationID.x; row < N; row += gl_WorkGroupSize.x)
    planes[base + row * N] = ((row + col) & 1u) != 0u ? -line[row] : line[row];
}
