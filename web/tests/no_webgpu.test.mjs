// no_webgpu.test.mjs — Chromium without --enable-unsafe-webgpu has no WebGPU adapter here: the
// page says so in one visible line instead of leaving a blank canvas.
import { openPage, run } from './browser.mjs';

await run('no-webgpu', async (check) => {
  const { browser, page, server } = await openPage({ query: 'n=64', webgpu: false });
  const message = await page.evaluate(() => {
    const box = document.getElementById('message');
    const style = getComputedStyle(box);
    return { text: box.textContent, visible: style.display !== 'none' && box.offsetHeight > 0,
             lines: Math.round(box.clientHeight / parseFloat(style.lineHeight || '16')) };
  });
  check(message.visible, `the message is visible: "${message.text}"`);
  check(/WebGPU is not available/.test(message.text), 'it says that WebGPU is not available');
  check(!message.text.includes('\n'), 'it is one line of text');
  await browser.close();
  server.close();
});
