// controls.js — the page's fly camera, steered by mouse, touch and keys, and the readout of frame
// and GPU times:
// - drag (mouse or one finger): look around (heading and pitch);
// - wheel or a two-finger pinch: the eye's height, by a factor per notch;
// - W/S or ↑/↓: fly forward and back along the heading, A/D or ←/→: sideways, Q/E: down and up,
//   at max(5 m, height) a second (Shift: four times as fast).
// The camera is { xM, zM, heightM, yawRad, pitchRad, fovYRad }; limits are the panel's ranges.

export const kLimits = { heightM: [2, 200], pitchRad: [(-60 * Math.PI) / 180, (20 * Math.PI) / 180] };
const kRadPerPixel = 0.004;
const kHeightPerWheelUnit = 0.0015;  // ln(height) per wheel delta unit (a notch is ~100)

const clamp = (v, [lo, hi]) => Math.min(hi, Math.max(lo, v));

// Attaches the controls to `element` (pointers) and the window (keys). onChange() runs after
// every change the pointers make; step(dtS) moves the camera by the keys held and returns
// whether it moved.
export function attachControls(element, camera, onChange) {
  const pointers = new Map();  // pointerId → last { x, y }
  const pinchDistance = () => {
    const [a, b] = [...pointers.values()];
    return Math.hypot(a.x - b.x, a.y - b.y);
  };
  element.style.touchAction = 'none';  // the page scrolls and zooms nothing itself
  element.addEventListener('pointerdown', (e) => {
    try {
      element.setPointerCapture(e.pointerId);  // keeps the drag when the pointer leaves
    } catch {
      // a pointer the browser does not track (a synthetic event): no capture needed
    }
    pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
  });
  element.addEventListener('pointermove', (e) => {
    const last = pointers.get(e.pointerId);
    if (!last) return;
    if (pointers.size === 1) {
      camera.yawRad += (e.clientX - last.x) * kRadPerPixel;
      camera.pitchRad = clamp(camera.pitchRad - (e.clientY - last.y) * kRadPerPixel,
                              kLimits.pitchRad);
      pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
    } else if (pointers.size === 2) {
      const before = pinchDistance();
      pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
      const after = pinchDistance();
      if (before > 0 && after > 0)
        camera.heightM = clamp(camera.heightM * (before / after), kLimits.heightM);
    }
    onChange();
  });
  const release = (e) => pointers.delete(e.pointerId);
  element.addEventListener('pointerup', release);
  element.addEventListener('pointercancel', release);
  element.addEventListener('wheel', (e) => {
    e.preventDefault();
    camera.heightM = clamp(camera.heightM * Math.exp(e.deltaY * kHeightPerWheelUnit),
                           kLimits.heightM);
    onChange();
  }, { passive: false });

  const held = new Set();
  const keyOf = (e) => e.key.length === 1 ? e.key.toLowerCase() : e.key;
  window.addEventListener('keydown', (e) => {
    if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement) return;
    held.add(keyOf(e));
    if (e.shiftKey) held.add('Shift');
  });
  window.addEventListener('keyup', (e) => {
    held.delete(keyOf(e));
    if (!e.shiftKey) held.delete('Shift');
  });
  window.addEventListener('blur', () => held.clear());

  return {
    held,
    step(dtS) {
      const axis = (plus, minus) => (plus.some((k) => held.has(k)) ? 1 : 0) -
                                    (minus.some((k) => held.has(k)) ? 1 : 0);
      const forward = axis(['w', 'ArrowUp'], ['s', 'ArrowDown']);
      const right = axis(['d', 'ArrowRight'], ['a', 'ArrowLeft']);
      const up = axis(['e'], ['q']);
      if (!forward && !right && !up) return false;
      const speed = Math.max(5, camera.heightM) * (held.has('Shift') ? 4 : 1) * dtS;
      const [c, s] = [Math.cos(camera.yawRad), Math.sin(camera.yawRad)];
      camera.xM += speed * (forward * c - right * s);
      camera.zM += speed * (forward * s + right * c);
      camera.heightM = clamp(camera.heightM + speed * up, kLimits.heightM);
      return true;
    },
  };
}

// Frame times: the median of the last 60 intervals between animation frames, ms.
export class FrameTimes {
  constructor() {
    this.intervals = [];
    this.last = null;
  }
  tick(nowMs) {
    if (this.last !== null) {
      this.intervals.push(nowMs - this.last);
      if (this.intervals.length > 60) this.intervals.shift();
    }
    this.last = nowMs;
  }
  medianMs() {
    if (this.intervals.length === 0) return null;
    const sorted = [...this.intervals].sort((a, b) => a - b);
    return sorted[Math.floor(sorted.length / 2)];
  }
}

// What the adapter is, and whether it is a software one (SwiftShader, llvmpipe, a fallback
// adapter): { label, software }.
export function describeAdapter(adapter) {
  const info = adapter.info ?? {};
  const label = [info.vendor, info.architecture, info.device, info.description]
    .filter((s) => s).join(' ') || 'unknown adapter';
  const software = Boolean(info.isFallbackAdapter || adapter.isFallbackAdapter) ||
    /swiftshader|llvmpipe|lavapipe|software/i.test(label);
  return { label, software };
}
