// fft.wgsl — inverse FFT of one row or column held in workgroup memory, one workgroup per line.
// Mirrors src/backends/vulkan/shaders/fft.glsl line by line.
//
// This work is based on:
//   - Stockham autosort FFT (Stockham 1966; Cochran et al. 1967), in the formulation of
//     E. Bainville, "OpenCL Fast Fourier Transform" (2010): radix-4 passes, then one radix-2
//     pass when log2 N is odd.
// Convention (docs/conventions.md): x[n] = Σ_k X[k]·e^{+2πi·kn/N}, unnormalised, as
// fft::Plan2D::inverse. Twiddles come from a table computed in double precision on the host.

var<workgroup> line: array<vec2f, N>;

// Transforms line[0..N) in place. Every invocation of the workgroup must call it.
fn inverse_fft_shared(j: u32) {
  let quarter = N / 4u;
  var p = 1u;
  for (var stage = 0u; stage < LOG2N / 2u; stage++) {
    let k = j & (p - 1u);
    let stride = N / (4u * p);
    let a0 = line[j];
    let a1 = cmul(line[j + quarter], twiddle[k * stride]);
    let a2 = cmul(line[j + 2u * quarter], twiddle[2u * k * stride]);
    let a3 = cmul(line[j + 3u * quarter], twiddle[3u * k * stride]);
    // Inverse radix-4 butterfly: y_m = Σ_r a_r·i^{r·m}.
    let s02 = a0 + a2;
    let d02 = a0 - a2;
    let s13 = a1 + a3;
    let d13 = a1 - a3;
    let i_d13 = vec2f(-d13.y, d13.x);
    workgroupBarrier();
    let base = (j - k) * 4u + k;
    line[base] = s02 + s13;
    line[base + p] = d02 + i_d13;
    line[base + 2u * p] = s02 - s13;
    line[base + 3u * p] = d02 - i_d13;
    workgroupBarrier();
    p *= 4u;
  }
  if ((LOG2N & 1u) != 0u) {  // one radix-2 pass: N/2 butterflies, two per invocation
    var y: array<vec2f, 4>;
    var base: array<u32, 2>;
    for (var b = 0u; b < 2u; b++) {
      let jj = j + b * quarter;
      let k = jj & (p - 1u);
      let a0 = line[jj];
      let a1 = cmul(line[jj + N / 2u], twiddle[k * (N / (2u * p))]);
      y[2u * b] = a0 + a1;
      y[2u * b + 1u] = a0 - a1;
      base[b] = (jj - k) * 2u + k;
    }
    workgroupBarrier();
    for (var b = 0u; b < 2u; b++) {
      line[base[b]] = y[2u * b];
      line[base[b] + p] = y[2u * b + 1u];
    }
    workgroupBarrier();
  }
}
