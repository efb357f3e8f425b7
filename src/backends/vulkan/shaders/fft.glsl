// fft.glsl — inverse FFT of one row or column held in shared memory, one workgroup per line.
//
// This work is based on:
//   - Stockham autosort FFT (Stockham 1966; Cochran et al. 1967, "What is the fast Fourier
//     transform?"), in the formulation of E. Bainville, "OpenCL Fast Fourier Transform" (2010):
//     pass with sub-length p reads x[j + r·N/R], twiddles by e^{±2πi·k·r/(p·R)} with k = j mod p,
//     and writes y[(j − k)·R + k + r·p].
//   - Radix-4 passes, then one radix-2 pass when log2 N is odd.
// Convention (docs/conventions.md): x[n] = Σ_k X[k]·e^{+2πi·kn/N}, unnormalised, as
// fft::Plan2D::inverse. Twiddles come from a table computed in double precision on the host.

layout(local_size_x_id = 2) in;  // N/4 threads (at least 1)

layout(std430, binding = OCEAN_BINDING_TWIDDLE) readonly buffer Twiddle { vec2 twiddle[]; };
layout(std430, binding = OCEAN_BINDING_PLANES) buffer Planes { vec2 planes[]; };

shared vec2 line[N];

// Transforms line[0..N) in place. Every thread of the workgroup must call it.
void inverse_fft_shared() {
  const uint quarter = N / 4u;
  const uint j = gl_LocalInvocationID.x;
  uint p = 1u;
  for (uint pass = 0u; pass < LOG2N / 2u; ++pass) {
    const uint k = j & (p - 1u);
    const uint stride = N / (4u * p);  // twiddle index step: e^{2πi·k·r/(4p)} = tw[k·r·stride]
    vec2 a0 = line[j];
    vec2 a1 = cmul(line[j + quarter], twiddle[k * stride]);
    vec2 a2 = cmul(line[j + 2u * quarter], twiddle[2u * k * stride]);
    vec2 a3 = cmul(line[j + 3u * quarter], twiddle[3u * k * stride]);
    // Inverse radix-4 butterfly: y_m = Σ_r a_r·i^{r·m}.
    vec2 s02 = a0 + a2, d02 = a0 - a2, s13 = a1 + a3, d13 = a1 - a3;
    vec2 i_d13 = vec2(-d13.y, d13.x);
    barrier();
    const uint base = (j - k) * 4u + k;
    line[base] = s02 + s13;
    line[base + p] = d02 + i_d13;
    line[base + 2u * p] = s02 - s13;
    line[base + 3u * p] = d02 - i_d13;
    barrier();
    p *= 4u;
  }
  if ((LOG2N & 1u) != 0u) {  // one radix-2 pass: N/2 butterflies, two per thread
    vec2 y[4];
    uint base[2];
    for (uint b = 0u; b < 2u; ++b) {
      const uint jj = j + b * quarter;
      const uint k = jj & (p - 1u);
      vec2 a0 = line[jj];
      vec2 a1 = cmul(line[jj + N / 2u], twiddle[k * (N / (2u * p))]);
      y[2u * b] = a0 + a1;
      y[2u * b + 1u] = a0 - a1;
      base[b] = (jj - k) * 2u + k;
    }
    barrier();
    for (uint b = 0u; b < 2u; ++b) {
      line[base[b]] = y[2u * b];
      line[base[b] + p] = y[2u * b + 1u];
    }
    barrier();
  }
}
