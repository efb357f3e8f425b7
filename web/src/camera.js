// camera.js — column-major 4×4 matrices for WebGPU clip space (z ∈ [0, 1]) and the page's camera:
// an eye at a height above the sea looking along a yaw and pitch.

export function perspective(fovYRad, aspect, near, far) {
  const f = 1 / Math.tan(fovYRad / 2);
  const m = new Float32Array(16);
  m[0] = f / aspect;
  m[5] = f;
  m[10] = far / (near - far);
  m[11] = -1;
  m[14] = (near * far) / (near - far);
  return m;
}

export function lookAt(eye, target, up) {
  const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                           a[0] * b[1] - a[1] * b[0]];
  const norm = (a) => { const l = Math.hypot(...a); return a.map((x) => x / l); };
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const z = norm(sub(eye, target));
  const x = norm(cross(up, z));
  const y = cross(z, x);
  return new Float32Array([x[0], y[0], z[0], 0, x[1], y[1], z[1], 0, x[2], y[2], z[2], 0,
                           -dot(x, eye), -dot(y, eye), -dot(z, eye), 1]);
}

export function multiply(a, b) {
  const m = new Float32Array(16);
  for (let c = 0; c < 4; ++c)
    for (let r = 0; r < 4; ++r)
      for (let k = 0; k < 4; ++k) m[c * 4 + r] += a[k * 4 + r] * b[c * 4 + k];
  return m;
}

export function invert(m) {
  // Gauss–Jordan on a copy in double precision.
  const a = Array.from({ length: 4 }, (_, r) => [0, 1, 2, 3].map((c) => m[c * 4 + r]));
  const inv = [0, 1, 2, 3].map((r) => [0, 1, 2, 3].map((c) => (r === c ? 1 : 0)));
  for (let c = 0; c < 4; ++c) {
    let p = c;
    for (let r = c + 1; r < 4; ++r) if (Math.abs(a[r][c]) > Math.abs(a[p][c])) p = r;
    [a[c], a[p]] = [a[p], a[c]];
    [inv[c], inv[p]] = [inv[p], inv[c]];
    const d = a[c][c];
    for (let k = 0; k < 4; ++k) { a[c][k] /= d; inv[c][k] /= d; }
    for (let r = 0; r < 4; ++r) {
      if (r === c) continue;
      const f = a[r][c];
      for (let k = 0; k < 4; ++k) { a[r][k] -= f * a[c][k]; inv[r][k] -= f * inv[c][k]; }
    }
  }
  const out = new Float32Array(16);
  for (let r = 0; r < 4; ++r) for (let c = 0; c < 4; ++c) out[c * 4 + r] = inv[r][c];
  return out;
}

// camera: { xM, zM, heightM, yawRad, pitchRad, fovYRad } (x, z 0 when absent); returns
// { eye, viewProj, invViewProj }.
export function cameraMatrices(camera, aspect) {
  const eye = [camera.xM ?? 0, camera.heightM, camera.zM ?? 0];
  const dir = [Math.cos(camera.pitchRad) * Math.cos(camera.yawRad), Math.sin(camera.pitchRad),
               Math.cos(camera.pitchRad) * Math.sin(camera.yawRad)];
  const view = lookAt(eye, [eye[0] + dir[0], eye[1] + dir[1], eye[2] + dir[2]], [0, 1, 0]);
  const viewProj = multiply(perspective(camera.fovYRad, aspect, 0.1, 40000), view);
  return { eye, viewProj, invViewProj: invert(viewProj) };
}
