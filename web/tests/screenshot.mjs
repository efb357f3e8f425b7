// screenshot.mjs OUT.png — a picture of the page (N = 256, t = 12 s, 960×540) for the docs.
// Run from web/ after web/build.sh: node tests/screenshot.mjs ../docs/images/web_page.png
import { openPage, requireChromium } from './browser.mjs';

requireChromium();
const out = process.argv[2] ?? 'web_page.png';
const { browser, page, server, logs } = await openPage({ query: 't=12', width: 960, height: 540 });
const error = await page.evaluate(() => window.ocean.error);
if (error) {
  console.error(`screenshot: ${error}\n${logs.join('\n')}`);
  process.exit(1);
}
await page.screenshot({ path: out });
await browser.close();
server.close();
console.log(`screenshot: wrote ${out}`);
