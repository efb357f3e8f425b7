// browser.mjs — what every browser test shares: a static server for build/web on 127.0.0.1, Debian's
// Chromium driven by puppeteer-core (no browser download) with the flags that give WebGPU through
// SwiftShader on machines without a GPU (docs/web.md), and the skip rule.
import { existsSync, readFileSync } from 'node:fs';
import http from 'node:http';
import path from 'node:path';

export const kChromium = process.env.OCEAN_CHROMIUM ?? '/usr/bin/chromium';
export const kWebGpuFlags = ['--enable-unsafe-webgpu', '--enable-features=Vulkan',
                             '--use-vulkan=swiftshader', '--use-angle=swiftshader'];
const kSkip = 77;  // ctest SKIP_RETURN_CODE

// Exits with the skip code when Chromium or puppeteer-core is missing, or fails when
// OCEAN_REQUIRE_DEVICES=1.
export function requireChromium() {
  const missing = !existsSync(kChromium) ? `${kChromium} not found (apt-get install chromium)`
    : !existsSync(new URL('../node_modules/puppeteer-core', import.meta.url))
      ? 'web/node_modules/puppeteer-core not found (cd web && npm ci)' : null;
  if (!missing) return;
  const required = process.env.OCEAN_REQUIRE_DEVICES === '1';
  console.log(`${required ? 'FAIL' : 'SKIP'}: ${missing}`);
  process.exit(required ? 1 : kSkip);
}

const kTypes = { '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript',
                 '.wgsl': 'text/plain', '.png': 'image/png' };

// Serves dir on an ephemeral port; resolves to { url, close }.
export function serve(dir) {
  const server = http.createServer((req, res) => {
    const file = path.join(dir, path.normalize(decodeURIComponent(req.url.split('?')[0])));
    if (!file.startsWith(dir) || !existsSync(file)) {
      res.writeHead(404).end();
      return;
    }
    res.writeHead(200, { 'Content-Type': kTypes[path.extname(file)] ?? 'application/octet-stream' });
    res.end(readFileSync(file));
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve({
    url: `http://127.0.0.1:${server.address().port}`,
    close: () => server.close(),
  })));
}

// Launches Chromium, opens the page and waits until it says it is ready (or failed).
// Returns { browser, page, server, logs }.
export async function openPage({ query, webgpu = true, width = 320, height = 180 }) {
  const { default: puppeteer } = await import('puppeteer-core');
  const dir = path.resolve(process.env.OCEAN_WEB_DIR ?? 'build/web');
  if (!existsSync(path.join(dir, 'index.html'))) throw new Error(`no page in ${dir}: run web/build.sh`);
  const server = await serve(dir);
  process.env.XDG_RUNTIME_DIR ??= '/tmp';
  const browser = await puppeteer.launch({
    executablePath: kChromium, headless: true,
    args: ['--no-sandbox', ...(webgpu ? kWebGpuFlags : [])],
  });
  const page = await browser.newPage();
  const logs = [];
  page.on('console', (m) => logs.push(`${m.type()}: ${m.text()}`));
  page.on('pageerror', (e) => logs.push(`pageerror: ${e.message}`));
  await page.setViewport({ width, height });
  await page.goto(`${server.url}/index.html?${query}`);
  await page.waitForFunction(() => window.ocean && window.ocean.ready, { timeout: 120000 });
  return { browser, page, server, logs };
}

// Runs body(check) and exits 0 when every check passed, 1 otherwise, printing each.
export async function run(name, body) {
  requireChromium();
  let failures = 0;
  const check = (ok, text) => {
    console.log(`${ok ? 'ok  ' : 'FAIL'} ${text}`);
    if (!ok) failures++;
  };
  const start = Date.now();
  try {
    await body(check);
  } catch (e) {
    check(false, `${name}: ${e.stack ?? e}`);
  }
  console.log(`${name}: ${failures ? 'FAILED' : 'passed'} in ${((Date.now() - start) / 1000).toFixed(1)} s`);
  process.exit(failures ? 1 : 0);
}
