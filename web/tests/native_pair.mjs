// native_pair.mjs OUT.png — the page (left) beside `ocean render`'s picture (right) of the same
// sea, camera, sun and exposure, 480×270 each, N = 256, t = 12 s after 4 s of foam warm-up, for
// docs/web.md. Run from web/ after web/build.sh, with OCEAN_NATIVE the built apps/ocean/ocean:
//   OCEAN_NATIVE=../build/release/apps/ocean/ocean node tests/native_pair.mjs ../docs/images/web_vs_native.png
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';
import { openPage, requireChromium } from './browser.mjs';
import { readPng } from './png.mjs';

const kWidth = 480, kHeight = 270, kGap = 6;
requireChromium();
const out = process.argv[2] ?? 'web_vs_native.png';
const native = process.env.OCEAN_NATIVE;
if (!native) {
  console.error('native_pair: set OCEAN_NATIVE to the built apps/ocean/ocean');
  process.exit(1);
}


// RGB rows as a PNG (filter 0 on every row).
function writePng(file, width, height, rgb) {
  const crcTable = Array.from({ length: 256 }, (_, n) => {
    let c = n;
    for (let k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    return c >>> 0;
  });
  const crc = (bytes) => {
    let c = 0xffffffff;
    for (const b of bytes) c = crcTable[(c ^ b) & 0xff] ^ (c >>> 8);
    return (c ^ 0xffffffff) >>> 0;
  };
  const chunk = (type, data) => {
    const head = Buffer.alloc(8);
    head.writeUInt32BE(data.length, 0);
    head.write(type, 4, 'latin1');
    const tail = Buffer.alloc(4);
    tail.writeUInt32BE(crc(Buffer.concat([head.subarray(4), data])), 0);
    return Buffer.concat([head, data, tail]);
  };
  const ihdr = Buffer.alloc(13);
  ihdr.writeUInt32BE(width, 0);
  ihdr.writeUInt32BE(height, 4);
  ihdr.set([8, 2, 0, 0, 0], 8);
  const raw = Buffer.alloc(height * (3 * width + 1));
  for (let y = 0; y < height; ++y)
    raw.set(rgb.subarray(3 * width * y, 3 * width * (y + 1)), y * (3 * width + 1) + 1);
  writeFileSync(file, Buffer.concat([Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]),
    chunk('IHDR', ihdr), chunk('IDAT', zlib.deflateSync(raw)), chunk('IEND', Buffer.alloc(0))]));
}

const { browser, page, server } = await openPage({ query: 'panel=0&t=0&n=256', width: kWidth, height: kHeight });
// `ocean render --warmup 4`: 30 Hz steps before t, ten to a call (SwiftShader is slow at 256²).
for (let first = 120; first > 0; first -= 10) {
  await page.evaluate(async (first) => {
    const o = window.ocean;
    if (first === 120) for (const s of o.ocean.simulations) s.lastTime = null;
    for (let i = first; i > first - 10; --i) {
      const encoder = o.device.createCommandEncoder();
      o.ocean.step(encoder, 12 - i / 30);
      o.device.queue.submit([encoder.finish()]);
    }
    await o.device.queue.onSubmittedWorkDone();
  }, first);
}
const pageRgba = await page.evaluate(async () => {
  const o = window.ocean, rad = Math.PI / 180;
  const camera = { ...o.camera, heightM: 12, pitchRad: -8 * rad, yawRad: 20 * rad, fovYRad: 55 * rad };
  return Array.from((await o.renderer.capture(12, camera)).rgba);
});
await browser.close();
server.close();

const dir = mkdtempSync(path.join(os.tmpdir(), 'ocean-web-pair-'));
const yaw = (20 * Math.PI) / 180, pitch = (-8 * Math.PI) / 180;
const target = [100 * Math.cos(pitch) * Math.cos(yaw), 12 + 100 * Math.sin(pitch),
                100 * Math.cos(pitch) * Math.sin(yaw)];
execFileSync(native, ['render', '--wind-speed', '10', '--fetch', '100000',
  '--set', `sea.wind_sea.direction_deg=${(0.3 * 180) / Math.PI}`, '--cascades', '1000,233,57',
  '--resolution', '256', '--seed', '1', '--loop-period', '200', '--choppiness', '1',
  '--time', '12', '--warmup', '4', '--camera', '0,12,0', '--target', target.join(','),
  '--fov', '55', '--width', String(kWidth), '--height', String(kHeight), '--sun-azimuth', '35',
  '--sun-elevation', '20', '--exposure', '0.45', '--planet-radius', 'inf',
  '--out', path.join(dir, 'native.png')], { stdio: ['ignore', 'ignore', 'inherit'] });
const nativePicture = readPng(path.join(dir, 'native.png'));
rmSync(dir, { recursive: true, force: true });

const width = 2 * kWidth + kGap;
const rgb = new Uint8Array(width * kHeight * 3).fill(255);
for (let y = 0; y < kHeight; ++y) {
  for (let x = 0; x < kWidth; ++x) {
    for (let k = 0; k < 3; ++k) {
      rgb[3 * (y * width + x) + k] = pageRgba[4 * (y * kWidth + x) + k];
      rgb[3 * (y * width + kWidth + kGap + x) + k] = nativePicture.rgba[4 * (y * kWidth + x) + k];
    }
  }
}
writePng(out, width, kHeight, rgb);
console.log(`native_pair: wrote ${out}`);
