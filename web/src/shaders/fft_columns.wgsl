// fft_columns.wgsl — the second FFT axis: each workgroup transforms one column of one plane and
// applies the (−1)^(col+row) sign that moves DC from the centre of the spectrum (Aebi, VR Ocean,
// eqs. 42–43). Dispatch (N, 2). Mirrors fft_columns.comp and fft::Plan2D::inverse.

@compute @workgroup_size(WG)
fn main(@builtin(workgroup_id) group: vec3u, @builtin(local_invocation_id) local: vec3u) {
  let col = group.x;
  let base = group.y * N * N + col;
  for (var row = local.x; row < N; row += WG) {
    line[row] = planes[base + row * N];
  }
  workgroupBarrier();
  inverse_fft_shared(local.x);
  for (var row = local.x; row < N; row += WG) {
    planes[base + row * N] = select(line[row], -line[row], ((row + col) & 1u) != 0u);
  }
}
