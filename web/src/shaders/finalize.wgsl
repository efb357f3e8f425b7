// finalize.wgsl — per texel: displacement (Dx, h, Dz), central-difference gradients with toroidal
// wrap, normal, Jacobian and foam with accumulation. Dispatch (N/8, N/8). Mirrors finalize.comp
// (its central-difference branch) and cpu::finalize.
//
// This work is based on:
//   - Aebi, VR Ocean, §3.7–3.8: eq. 44 (displacement), eqs. 45–46 (central differences),
//     eq. 48 (Jacobian).
//   - Longuet-Higgins 1969 (breaking where the downward acceleration exceeds g/2; M.7.4).
//   - Vincevičius 2024, §2.4 (foam accumulation, listing 2.4).
// Equations: docs/math.md §7.

// (Dx, h, Dz) at a wrapped texel: plane 0 = h + i·Dx, plane 1 = Dz + i·(…) (M.7.2).
fn displacement_at(col: i32, row: i32) -> vec3f {
  let i = u32(row & i32(N - 1u)) * N + u32(col & i32(N - 1u));
  let p0 = planes[i];
  return vec3f(p0.y, p0.x, planes[N * N + i].x);
}

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3u) {
  if (id.x >= N || id.y >= N) {
    return;
  }
  let i = id.y * N + id.x;
  let c = i32(id.x);
  let r = i32(id.y);
  let d = displacement_at(c, r);
  displacement[i] = vec4f(d, 0.0);  // eq. 44: the FFT applied the sign, λ is in the spectra

  // Gradients ∂/∂x (gx) and ∂/∂z (gz) of (Dx, h, Dz), eq. 45.
  let gx = (displacement_at(c + 1, r) - displacement_at(c - 1, r)) * 0.5 * params.inv_spacing;
  let gz = (displacement_at(c, r + 1) - displacement_at(c, r - 1)) * 0.5 * params.inv_spacing;

  // Jacobian of x → x + D (eq. 48) and the normal ∂p/∂z × ∂p/∂x (M.7.5).
  let jxx = 1.0 + gx.x;
  let jzz = 1.0 + gz.z;
  let jacobian = jxx * jzz - gz.x * gx.z;
  var n = vec3f(gz.y * gx.z - jzz * gx.y, jacobian, gz.x * gx.y - gz.y * jxx);
  let len = length(n);
  n = select(vec3f(0.0, 1.0, 0.0), n / len, len > 0.0);

  // Foam: the probability that the sea breaks given this cascade's J (Longuet-Higgins 1969;
  // the native default source "breaking", M.7.4), accumulated with Vincevičius's (2024) decay,
  // listing 2.4.
  let now = normal_cdf((params.j_threshold - jacobian) * params.j_gain);
  var f = now;
  if (params.reset_foam == 0u) {
    let accumulated = foam[i] - params.foam_decay / max(now, 0.5);
    f = clamp(max(accumulated, now), 0.0, 1.0);
  }
  foam[i] = f;
  surface[i] = vec4f(n, jacobian);
}
