// no_webgpu.test.mjs — Chromium without --enable-unsafe-webgpu has no WebGPU adapter here: the page
// says so in one visible line, names the path it takes instead, and runs the CPU backend in
// WebAssembly drawn in a 2D canvas: the picture is not blank, and it moves.
import { openPage, run } from './browser.mjs';

await run('no-webgpu', async (check) => {
  const { browser, page, server, logs } = await openPage({ query: 'n=64&t=1', webgpu: false });
  const message = await page.evaluate(() => {
    const box = document.getElementById('message');
    const style = getComputedStyle(box);
    return { text: box.textContent, visible: style.display !== 'none' && box.offsetHeight > 0 };
  });
  check(message.visible, `the message is visible: "${message.text}"`);
  check(/WebGPU is not available/.test(message.text), 'it says that WebGPU is not available');
  check(/CPU backend \(WebAssembly\)/.test(message.text), 'it says that the CPU backend runs');
  check(!message.text.includes('\n'), 'it is one line of text');

  // Two frames, t = 1 s and t = 3 s: luminance spread over the canvas, and pixels that change.
  const frames = await page.evaluate(() => {
    const { view, error } = window.ocean;
    if (error || !view) return { error: error ?? 'no CPU view' };
    const canvas = document.getElementById('view');
    const grab = (t) => {
      view.draw(t);
      return canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
    };
    const a = grab(1);
    const b = grab(3);
    const lum = [];
    let black = 0, changed = 0;
    for (let i = 0; i < a.length; i += 4) {
      lum.push(0.2126 * a[i] + 0.7152 * a[i + 1] + 0.0722 * a[i + 2]);
      if (a[i] + a[i + 1] + a[i + 2] === 0) black++;
      if (a[i + 2] !== b[i + 2]) changed++;
    }
    const mean = lum.reduce((s, v) => s + v, 0) / lum.length;
    const sd = Math.sqrt(lum.reduce((s, v) => s + (v - mean) ** 2, 0) / lum.length);
    return { path: window.ocean.path, pixels: lum.length, black, changed, mean, sd };
  });
  check(!frames.error && frames.path === 'cpu', `the page runs the CPU path ${frames.error ?? ''}`);
  if (frames.error) {
    console.log(logs.join('\n'));
  } else {
    const { pixels, black, changed, mean, sd } = frames;
    check(black === 0, `no black pixels (${black} of ${pixels})`);
    check(sd > 5, `the canvas shows waves: luminance ${mean.toFixed(1)} ± ${sd.toFixed(1)}`);
    check(changed > 0.05 * pixels, `the sea moves: ${changed} of ${pixels} pixels ` +
          'differ between t = 1 s and t = 3 s');
  }
  await browser.close();
  server.close();
});
