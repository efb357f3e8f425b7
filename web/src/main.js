// main.js — the page: loads the WebAssembly core, starts WebGPU, wires the panel and animates.
// URL options (for tests and small screens): n (resolution, default 256), patch (the cascades'
// patch sides in m, largest first, comma-separated; default the native 1000,233,57),
// seed (default 1), t (a fixed time in s: no animation), panel=0 (hide the panel).
// window.ocean publishes { ready, error, core, ocean, simulation (cascade 0), renderer, sea,
// camera, ... } for tests.
import { loadCore } from './core.js';
import { Renderer } from './renderer.js';
import { Ocean } from './cascades.js';
import { CpuView } from './fallback.js';

const params = new URLSearchParams(location.search);
const state = (window.ocean = { ready: false, error: null });

function say(text) {
  const box = document.getElementById('message');
  box.textContent = text;
  box.style.display = 'block';
}

async function start() {
  const adapter = navigator.gpu ? await navigator.gpu.requestAdapter() : null;
  if (!adapter) {
    await startCpu(navigator.gpu ? 'no GPU adapter was found' : 'this browser has no WebGPU');
    return;
  }
  const device = await adapter.requestDevice();
  state.path = 'webgpu';
  device.lost.then((info) => say(`WebGPU device lost: ${info.message}`));
  device.addEventListener('uncapturederror', (e) => {
    state.error = e.error.message;
    console.error(`webgpu: ${e.error.message}`);
  });

  const { form, value, sea, canvas } = setUp();
  const core = await loadCore();
  let ocean = await Ocean.create(device, core, sea);
  let renderer = await Renderer.create(device, canvas, ocean);
  const camera = { heightM: 12, yawRad: 0, pitchRad: 0, fovYRad: (55 * Math.PI) / 180 };
  let timeScale = 1;

  // Re-reads the panel; a new wind or fetch rebuilds the spectrum in the core and on the GPU.
  async function applyPanel() {
    for (const label of form.querySelectorAll('label'))
      label.querySelector('output').textContent = label.querySelector('input').value;
    camera.heightM = value('height');
    camera.pitchRad = (value('pitch') * Math.PI) / 180;
    camera.yawRad = (value('yaw') * Math.PI) / 180;
    timeScale = value('timeScale');
    if (value('wind') !== sea.windMps || value('fetch') * 1000 !== sea.fetchM) {
      sea.windMps = value('wind');
      sea.fetchM = value('fetch') * 1000;
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

  Object.assign(state, { core, ocean, simulation: ocean.simulations[0], renderer, sea, camera,
                         device, applyPanel });
  animate((t) => {
    const encoder = device.createCommandEncoder();
    renderer.frame(encoder, t, camera);
    device.queue.submit([encoder.finish()]);
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
  };
  const canvas = document.getElementById('view');
  canvas.width = Math.max(1, Math.round(canvas.clientWidth * devicePixelRatio));
  canvas.height = Math.max(1, Math.round(canvas.clientHeight * devicePixelRatio));
  return { form, value, sea, canvas };
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
  for (const name of ['height', 'pitch', 'yaw']) {
    form.elements[name].parentElement.style.display = 'none';  // no camera from above
  }
  const core = await loadCore();
  let view = new CpuView(core, sea, canvas);
  let timeScale = 1;
  const applyPanel = () => {
    for (const label of form.querySelectorAll('label'))
      label.querySelector('output').textContent = label.querySelector('input').value;
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
