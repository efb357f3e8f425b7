// core.js — the WebAssembly core (web/wasm/ocean_web.cpp, the library's spectrum module and its
// scalar reference synthesis) behind a small JavaScript object. Arrays are copies, so they stay
// valid after the next configure.
import OceanCore from './ocean_core.mjs';

export async function loadCore() {
  const m = await OceanCore();
  let texels = 0;
  const f32 = (ptr, count) => new Float32Array(m.HEAPF32.buffer, ptr, count).slice();
  return {
    // sea: { windMps, fetchM, directionRad, resolution, patchSizesM (largest first), seed,
    // loopPeriodS }; configures cascade `cascade` of it (its band and seed, as natively).
    // Throws an Error with the library's one-line message when the sea is invalid.
    configure(sea, cascade = 0) {
      const sizes = sea.patchSizesM;
      const ptr = m._malloc(8 * sizes.length);
      new Float64Array(m.HEAPF64.buffer, ptr, sizes.length).set(sizes);
      const rc = m._ocean_web_configure(sea.windMps, sea.fetchM, sea.directionRad, sea.resolution,
                                        ptr, sizes.length, cascade, sea.seed, sea.loopPeriodS);
      m._free(ptr);
      if (rc !== 0) throw new Error(m.UTF8ToString(m._ocean_web_error()));
      texels = sea.resolution * sea.resolution;
    },
    spectrum: (omega) => m._ocean_web_spectrum(omega),  // S(ω), m²·s/rad
    peakOmega: () => m._ocean_web_peak_omega(),         // ωp, rad/s
    hs: () => m._ocean_web_hs(),                        // 4·√m0, m
    // The configured cascade's geometry fade length, m (the native renderer's, R.9).
    geometryWavelength: () => m._ocean_web_geometry_wavelength(),
    // The breaking foam source at choppiness λ: [threshold, gain, the cascade's foam weight].
    foamTerms: (lambda) => Array.from(f32(m._ocean_web_foam_terms(lambda), 3)),
    // The short waves' slope variance (the renderer's α₀², R.5).
    unresolvedSlopeVariance: () => m._ocean_web_unresolved_slope_variance(),
    // The native renderer's sky for the sun at (azimuth, elevation) degrees: { lut: the sky-view
    // table (128 × 64 RGBA floats, R.1–R.4), light: the 24 numbers ocean_web_sky lists }.
    sky(azimuthDeg, elevationDeg) {
      const lut = f32(m._ocean_web_sky(azimuthDeg, elevationDeg), 4 * 128 * 64);
      return { lut, width: 128, height: 64, light: f32(m._ocean_web_light(), 24) };
    },
    packed: () => f32(m._ocean_web_packed(), 4 * texels),
    phaseRate: () => f32(m._ocean_web_phase_rate(), texels),
    h0: () => new Float64Array(m.HEAPF64.buffer, m._ocean_web_h0(), 2 * texels).slice(),
    // The CPU reference stepped to time t with choppiness λ, foam accumulated over dtS (restarted
    // when reset): { displacement: (Dx, h, Dz), surface: (nx, ny, nz, J), foam } per texel.
    reference(timeS, choppiness, dtS = 0, reset = true) {
      const d = m._ocean_web_reference(timeS, choppiness, dtS, reset ? 1 : 0);
      return { displacement: f32(d, 3 * texels), surface: f32(m._ocean_web_surface(), 4 * texels),
               foam: f32(m._ocean_web_foam(), texels) };
    },
  };
}
