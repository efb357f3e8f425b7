// main.js — the page: loads the WebAssembly core, starts WebGPU, wires the panel and animates.
// URL options (for tests and small screens): n (resolution, default 256), patch (the cascades'
// patch sides in m, largest first, comma-separated; default the native 1000,233,57),
// seed (default 1), t (a fixed time in s: no animation), panel=0 (hide the panel), sun (the sun's
// azimuth and elevation in degrees, default 35,20 as natively).
// The camera flies with the mouse, touch and keys (controls.js); the panel's quality picks the
// cascades' resolution; the readout gives the frame time, the GPU time where the adapter has
// timestamp queries, and the adapter, with a note when it is a software one.
// window.ocean publishes { ready, error, core, ocean, simulation (cascade 0), renderer, sea,
// camera, controls, adapter, ... } for tests.
import { loadCore } from './core.js';
import { Renderer } from './renderer.js';
import { Ocean } from './cascades.js';
import { CpuView } from './fallback.js';
import { attachControls, describeAdapter, FrameTimes } from './controls.js';

const params = new URLSearchParams(location.search);
const state = (window.ocean = { ready: false, error: null });

function say(text) {
  const box = document.getElementById('message');
  box.textContent = text;
  box.style.display = 'block';
}

function note(text) {
  const box = document.getElementById('note');
  box.textContent = text;
  box.style.display = 'block';
}

async function start() {
  const adapter = navigator.gpu ? await navigator.gpu.requestAdapter() : null;
  if (!adapter) {
    await startCpu(navigator.gpu ? 'no GPU adapter was found' : 'this browser has no WebGPU');
    return;
  }
  const adapterInfo = describeAdapter(adapter);
  const device = await adapter.requestDevice({
    requiredFeatures: adapter.features.has('timestamp-query') ? ['timestamp-query'] : [] });
  state.path = 'webgpu';
  state.adapter = adapterInfo;
  if (adapterInfo.software) {
    note(`WebGPU runs on a software adapter (${adapterInfo.label}): the CPU draws every frame, ` +
         'so expect a few frames a second; a browser on a hardware GPU runs this page at its ' +
         'display rate.');
  }
  device.lost.then((info) => say(`WebGPU device lost: ${info.message}`));
  device.addEventListener('uncapturederror', (e) => {
    state.error = e.error.message;
    console.error(`webgpu: ${e.error.message}`);
  });

  const { form, value, sea, canvas } = setUp();
  const core = await loadCore();
  let ocean = await Ocean.create(device, core, sea);
  let renderer = await Renderer.create(device, canvas, ocean);
  const camera = { xM: 0, zM: 0, heightM: 12, yawRad: 0, pitchRad: 0,
                   fovYRad: (55 * Math.PI) / 180 };
  let timeScale = 1;
  // The panel's sliders follow what the mouse, touch and keys do to the camera.
  const showCamera = () => {
    const set = (name, v) => {
      const input = form.elements[name];
      input.value = String(Math.round(v));
      input.parentElement.querySelector('output').textContent = input.value;
    };
    set('height', camera.heightM);
    set('pitch', (camera.pitchRad * 180) / Math.PI);
    set('yaw', ((((camera.yawRad * 180) / Math.PI) % 360) + 360) % 360);
  };
  const controls = attachControls(canvas, camera, showCamera);
  // The canvas follows the window's size (the renderer remakes its depth target to match).
  window.addEventListener('resize', () => fitCanvas(canvas));

  // Re-reads the panel; a new wind or fetch rebuilds the spectrum in the core and on the GPU.
  async function applyPanel() {
    for (const input of form.querySelectorAll('label input'))
      input.parentElement.querySelector('output').textContent = input.value;
    camera.heightM = value('height');
    camera.pitchRad = (value('pitch') * Math.PI) / 180;
    camera.yawRad = (value('yaw') * Math.PI) / 180;
    timeScale = value('timeScale');
    if (value('wind') !== sea.windMps || value('fetch') * 1000 !== sea.fetchM ||
        value('quality') !== sea.resolution) {
      sea.windMps = value('wind');
      sea.fetchM = value('fetch') * 1000;
      sea.resolution = value('quality');
      const next = await Ocean.create(device, core, sea);
      const nextRenderer = await Renderer.create(device, canvas, next);
      ocean.destroy();
      ocean = next;
      renderer = nextRenderer;
      Object.assign(state, { ocean, simulation: ocean.simulations[0], renderer });
    }
    ocean.choppiness = value('choppiness');
  }
  form.addEventListener('input', () => applyPanel().catch((e) => say(e.message)));
  await applyPanel();

  const times = new FrameTimes();
  const readout = document.getElementById('stats');
  let lastReadout = 0, lastFrame = null;
  const showReadout = (now) => {
    const ms = times.medianMs();
    const gpu = !renderer.timer ? 'GPU time n/a (the adapter has no timestamp queries)'
      : renderer.gpuMs === null ? 'GPU … ms' : `GPU ${renderer.gpuMs.toFixed(2)} ms (render pass)`;
    readout.textContent = `${ms === null ? '…' : ms.toFixed(1)} ms a frame` +
      `${ms ? ` (${(1000 / ms).toFixed(1)} fps)` : ''} · ${gpu} · n = ${sea.resolution} · ` +
      adapterInfo.label + (adapterInfo.software ? ' (software)' : '');
    lastReadout = now;
  };
  Object.assign(state, { core, ocean, simulation: ocean.simulations[0], renderer, sea, camera,
                         device, applyPanel, controls, times, showReadout });
  animate((t) => {
    const now = performance.now();
    times.tick(now);
    if (controls.step(lastFrame === null ? 0 : Math.min(0.25, (now - lastFrame) / 1000)))
      showCamera();
    lastFrame = now;
    const encoder = device.createCommandEncoder();
    renderer.frame(encoder, t, camera);
    device.queue.submit([encoder.finish()]);
    renderer.collectGpuTime();
    if (now - lastReadout > 250) showReadout(now);
  }, () => timeScale);
  await device.queue.onSubmittedWorkDone();
  state.ready = true;
}

// The panel, the sea it describes and the canvas at the device's pixel size.
function setUp() {
  const form = document.getElementById('panel');
  if (params.get('panel') === '0') form.style.display = 'none';
  const value = (name) => Number(form.elements[name].value);
  const sea = {
    windMps: value('wind'), fetchM: value('fetch') * 1000, directionRad: 0.3,
    resolution: Number(params.get('n') ?? 256),
    patchSizesM: (params.get('patch') ?? '1000,233,57').split(',').map(Number),
    seed: Number(params.get('seed') ?? 1), loopPeriodS: 200,
    // The sun's azimuth and elevation, degrees (ShadingParams' 35 and 20 by default).
    sunDeg: params.has('sun') ? params.get('sun').split(',').map(Number) : undefined,
  };
  const quality = form.elements.quality;
  if (![...quality.options].some((o) => Number(o.value) === sea.resolution)) {
    quality.add(new Option(`n = ${sea.resolution}`, String(sea.resolution)));
  }
  quality.value = String(sea.resolution);
  const canvas = document.getElementById('view');
  fitCanvas(canvas);
  return { form, value, sea, canvas };
}

// The canvas's pixels: its size on the page at the device's pixel ratio.
function fitCanvas(canvas) {
  canvas.width = Math.max(1, Math.round(canvas.clientWidth * devicePixelRatio));
  canvas.height = Math.max(1, Math.round(canvas.clientHeight * devicePixelRatio));
}

// Without WebGPU: the CPU backend in WebAssembly, drawn from above in a 2D canvas (fallback.js).
// The panel's wind, fetch, choppiness and time scale apply; the camera does not.
async function startCpu(why) {
  say(`WebGPU is not available (${why}): showing the CPU backend (WebAssembly) from above in a ` +
      '2D canvas.');
  state.path = 'cpu';
  const box = document.getElementById('message');
  box.style.top = 'auto';  // below the panel
  box.style.bottom = '8px';
  const { form, value, sea, canvas } = setUp();
  for (const name of ['height', 'pitch', 'yaw', 'quality']) {
    form.elements[name].parentElement.style.display = 'none';  // no camera from above
  }
  document.getElementById('stats').style.display = 'none';
  const core = await loadCore();
  let view = new CpuView(core, sea, canvas);
  let timeScale = 1;
  const applyPanel = () => {
    for (const input of form.querySelectorAll('label input'))
      input.parentElement.querySelector('output').textContent = input.value;
    timeScale = value('timeScale');
    if (value('wind') !== sea.windMps || value('fetch') * 1000 !== sea.fetchM) {
      sea.windMps = value('wind');
      sea.fetchM = value('fetch') * 1000;
      view = new CpuView(core, sea, canvas);
      state.view = view;
    }
    view.choppiness = value('choppiness');
  };
  form.addEventListener('input', () => {
    try {
      applyPanel();
    } catch (e) {
      say(e.message);
    }
  });
  applyPanel();
  Object.assign(state, { core, sea, view, applyPanel });
  animate((t) => view.draw(t), () => timeScale);
  state.ready = true;
}

// Calls drawAt(t) on every animation frame, t advancing with the page's clock times timeScale(),
// or once at the URL's fixed time `t`.
function animate(drawAt, timeScale) {
  const fixedTime = params.get('t');
  let simTime = fixedTime === null ? 0 : Number(fixedTime);
  let last = performance.now();
  const draw = (now) => {
    if (fixedTime === null) simTime += ((now - last) / 1000) * timeScale();
    last = now;
    drawAt(simTime);
    if (fixedTime === null) requestAnimationFrame(draw);
  };
  requestAnimationFrame(draw);
}

start().catch((e) => {
  say(e.message);
  state.error = e.message;
  state.ready = true;
});
