// controls.test.mjs — the page as a user drives it (controls.js): a mouse drag turns the camera
// by the drag times the look rate and the panel's sliders follow, the wheel and a two-finger pinch
// change the height by their factor, held keys fly the camera along its heading, the canvas
// follows a window resize, the quality switch rebuilds the cascades at its resolution, the readout
// gives the frame time (and the GPU time where the adapter has timestamp queries), and a software
// adapter (SwiftShader here) is named in a visible note. No WebGPU error on the way.
import { openPage, run } from './browser.mjs';

const near = (a, b, tol) => Math.abs(a - b) <= tol;

await run('controls', async (check) => {
  const { browser, page, server, logs } = await openPage({ query: 'n=64&panel=0', width: 320, height: 180 });
  const cam = () => page.evaluate(() => ({ ...window.ocean.camera }));
  try {
    check(!(await page.evaluate(() => window.ocean.error)), 'page ready without WebGPU errors');

    // The readout: a frame time, and the GPU time or why there is none.
    await page.waitForFunction(
      () => /\d+(\.\d+)? ms a frame/.test(document.getElementById('stats').textContent),
      { timeout: 60000 });
    const readout = await page.evaluate(() => document.getElementById('stats').textContent);
    check(/GPU (\d+\.\d+ ms \(render pass\)|… ms|time n\/a \(the adapter has no timestamp queries\))/
      .test(readout), `the readout gives the frame and GPU times: "${readout}"`);

    // The adapter's note.
    const adapter = await page.evaluate(() => {
      const box = document.getElementById('note');
      return { ...window.ocean.adapter, text: box.textContent,
               visible: getComputedStyle(box).display !== 'none' && box.offsetHeight > 0 };
    });
    check(adapter.software, `SwiftShader is recognised as a software adapter ("${adapter.label}")`);
    check(adapter.visible && /software adapter/.test(adapter.text),
          `the note says so: "${adapter.text}"`);

    // Drag 40 px right and 20 px up: heading +0.16 rad, pitch +0.08 rad (0.004 rad a pixel).
    const before = await cam();
    await page.mouse.move(160, 90);
    await page.mouse.down();
    await page.mouse.move(200, 70, { steps: 4 });
    await page.mouse.up();
    const dragged = await cam();
    check(near(dragged.yawRad - before.yawRad, 0.16, 1e-6) &&
          near(dragged.pitchRad - before.pitchRad, 0.08, 1e-6),
          `a drag turns the camera: heading +${(dragged.yawRad - before.yawRad).toFixed(4)}, ` +
          `pitch +${(dragged.pitchRad - before.pitchRad).toFixed(4)} rad`);
    const slider = await page.evaluate(() => Number(document.forms.panel.elements.pitch.value));
    check(slider === Math.round((dragged.pitchRad * 180) / Math.PI),
          `the pitch slider follows (${slider}°)`);

    // The wheel: a delta of 100 multiplies the height by e^0.15.
    await page.mouse.wheel({ deltaY: 100 });
    const wheeled = await cam();
    check(near(wheeled.heightM / dragged.heightM, Math.exp(0.15), 1e-9),
          `the wheel raises the eye ${dragged.heightM.toFixed(2)} → ${wheeled.heightM.toFixed(2)} m`);

    // A pinch: two touches moving apart from 40 to 80 px halve the height.
    const pinched = await page.evaluate(() => {
      const canvas = document.getElementById('view');
      const at = (id, x, type) => canvas.dispatchEvent(new PointerEvent(type, {
        pointerId: id, pointerType: 'touch', clientX: x, clientY: 90, bubbles: true }));
      const h0 = window.ocean.camera.heightM;
      at(11, 140, 'pointerdown');
      at(12, 180, 'pointerdown');
      at(12, 220, 'pointermove');
      at(11, 140, 'pointerup');
      at(12, 220, 'pointerup');
      return window.ocean.camera.heightM / h0;
    });
    check(near(pinched, 0.5, 1e-9), `a pinch out lowers the eye by the spread's ratio (×${pinched})`);

    // Held W flies along the heading: x grows with cos(heading), z with sin(heading).
    await page.evaluate(() => { window.ocean.camera.yawRad = 0; });
    const start = await cam();
    await page.keyboard.down('w');
    await page.waitForFunction((x0) => window.ocean.camera.xM > x0 + 1, { timeout: 60000 }, start.xM);
    await page.keyboard.up('w');
    const flown = await cam();
    check(flown.xM > start.xM + 1 && near(flown.zM, start.zM, 1e-9) &&
          near(flown.heightM, start.heightM, 1e-9),
          `W flies forward: x ${start.xM.toFixed(1)} → ${flown.xM.toFixed(1)} m, z and height kept`);

    // The canvas follows the window.
    await page.setViewport({ width: 400, height: 240 });
    await page.waitForFunction(() => document.getElementById('view').width === 400 &&
                               document.getElementById('view').height === 240, { timeout: 30000 });
    check(true, 'the canvas follows a resize to 400 × 240');

    // The quality switch: 128² cascades.
    await page.evaluate(() => {
      const select = document.forms.panel.elements.quality;
      select.value = '128';
      select.dispatchEvent(new Event('input', { bubbles: true }));
    });
    await page.waitForFunction(() => window.ocean.ocean.n === 128, { timeout: 60000 });
    const quality = await page.evaluate(() => ({ n: window.ocean.ocean.n, sea: window.ocean.sea.resolution,
                                                 error: window.ocean.error }));
    check(quality.n === 128 && quality.sea === 128, 'the quality switch rebuilds the cascades at 128²');
    check(!quality.error, `no WebGPU error after all that ${quality.error ?? ''}`);
  } finally {
    if (logs.some((l) => l.startsWith('pageerror'))) console.log(logs.join('\n'));
    await browser.close();
    server.close();
  }
});
