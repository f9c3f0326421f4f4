// Shared pieces of the browser tests: Debian's chromium through playwright-core (never a
// downloaded browser), the static server, pictures read back from the canvas.
import { chromium } from 'playwright-core';
import fs from 'node:fs';
import { spawnSync } from 'node:child_process';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { serve, defaultRoot } from './server.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
export const artifacts = path.resolve(here, '../../out/web-tests');

// The waits' limits say when a test has hung, not how fast the page is: SwiftShader's frames
// take seconds on a slow or busy machine (the flight with reflections drew 4 frames in over
// 30 s beside the GPU tests on CI). Every limit is a nominal figure times this factor
// (DRAUGHT_WEB_PATIENCE, 4 unless set); it costs time only when a test fails.
const PATIENCE = Number(process.env.DRAUGHT_WEB_PATIENCE) > 0 ? Number(process.env.DRAUGHT_WEB_PATIENCE) : 4;
export const patience = (ms) => ms * PATIENCE;

// Software WebGL (SwiftShader through ANGLE): no GPU or display needed.
export const chromiumFlags = [
  '--headless',
  '--no-sandbox',
  '--use-gl=angle',
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--no-first-run',
  '--disable-quic',
  // The camera: chromium's own test pattern (a moving picture), granted without asking.
  '--use-fake-device-for-media-stream',
  '--use-fake-ui-for-media-stream',
  '--autoplay-policy=no-user-gesture-required',
];

// The fake camera plays a clip whose colours turn a full circle every second, so every part
// of its picture moves (chromium's own pattern moves only a small disc); without ffmpeg,
// chromium's own.
function fakeCamera() {
  const clip = path.join(artifacts, 'fake-camera.y4m');
  const made = spawnSync('ffmpeg', ['-nostdin', '-y', '-loglevel', 'error', '-f', 'lavfi', '-i',
    'testsrc2=size=320x180:rate=15:duration=2,hue=H=2*PI*t', '-pix_fmt', 'yuv420p', clip]);
  return made.status === 0 ? [`--use-file-for-fake-video-capture=${clip}`] : [];
}

export async function start() {
  if (!fs.existsSync(path.join(defaultRoot, 'draught.wasm'))) throw new Error(`${defaultRoot}/draught.wasm is missing: run scripts/build-web.sh`);
  fs.mkdirSync(artifacts, { recursive: true });
  const server = await serve(0);
  const executablePath = process.env.CHROMIUM || '/usr/bin/chromium';
  const browser = await chromium.launch({ executablePath, args: [...chromiumFlags, ...fakeCamera()], headless: true });
  const base = `http://127.0.0.1:${server.address().port}/`;
  return {
    browser,
    base,
    async close() {
      await browser.close();
      await new Promise((r) => server.close(r));
    },
  };
}

// A page at a small fixed size and render scale, its drawing buffer kept for read-back.
export const testQuery = 'size=160x120&scale=1&preserve';

export async function openPage(env, { query = testQuery, context = {} } = {}) {
  const ctx = await env.browser.newContext({ viewport: { width: 720, height: 560 }, acceptDownloads: true, ...context });
  // Playwright's own waits (navigation, clicks, waits without a timeout) scale like ours.
  ctx.setDefaultTimeout(patience(30000));
  const page = await ctx.newPage();
  const log = [];
  page.on('console', (m) => log.push(`${m.type()}: ${m.text()}`));
  page.on('pageerror', (e) => log.push(`pageerror: ${e.message}`));
  await page.goto(env.base + 'index.html?' + query);
  await page.waitForFunction(() => window.draught && (window.draught.ready || window.draught.error), null, { timeout: patience(30000) });
  const error = await page.evaluate(() => window.draught.error);
  if (error) throw new Error('page did not start: ' + error + '\n' + log.join('\n'));
  await waitFrames(page, 2);
  page.draughtLog = log;
  return page;
}

// Waits for n more frames; fails only when one frame takes longer than `stall` (so n slow
// frames never add up to a failure).
export async function waitFrames(page, n, stall = patience(30000)) {
  const frames = () => page.evaluate(() => window.draught.frames());
  const target = (await frames()) + n;
  for (let seen = target - n; seen < target; seen = await frames()) {
    try {
      await page.waitForFunction((f) => window.draught.frames() > f, seen, { timeout: stall, polling: 20 });
    } catch (e) {
      throw new Error(`no frame drawn in ${(stall / 1000).toFixed(0)} s (waiting for frame ${target}, at ${seen}): ${e.message}`);
    }
  }
}

// The canvas as RGBA bytes (needs ?preserve), with its size.
export async function snapshot(page) {
  return page.evaluate(() => {
    const c = document.getElementById('canvas');
    const o = document.createElement('canvas');
    o.width = c.width;
    o.height = c.height;
    const g = o.getContext('2d');
    g.drawImage(c, 0, 0);
    return { width: o.width, height: o.height, data: Array.from(g.getImageData(0, 0, o.width, o.height).data) };
  });
}

// Mean absolute difference per colour channel, 0..255.
export function difference(a, b) {
  if (a.width !== b.width || a.height !== b.height) throw new Error(`sizes differ: ${a.width}x${a.height} vs ${b.width}x${b.height}`);
  let sum = 0;
  for (let i = 0; i < a.data.length; i += 4)
    for (let c = 0; c < 3; ++c) sum += Math.abs(a.data[i + c] - b.data[i + c]);
  return sum / ((a.data.length / 4) * 3);
}

// Mean absolute difference per colour channel over the pixels of `box` ({x0, y0, x1, y1},
// ends excluded), of k x k block means: rising bubbles are small and move on their own, a
// tilt moves large areas, so blocks keep the one and average the other out.
export function blockDifference(a, b, box, k = 4) {
  let sum = 0, n = 0;
  for (let by = Math.max(0, box.y0); by + k <= Math.min(a.height, box.y1); by += k)
    for (let bx = Math.max(0, box.x0); bx + k <= Math.min(a.width, box.x1); bx += k, ++n)
      for (let c = 0; c < 3; ++c) {
        let d = 0;
        for (let y = by; y < by + k; ++y)
          for (let x = bx; x < bx + k; ++x) d += a.data[4 * (y * a.width + x) + c] - b.data[4 * (y * a.width + x) + c];
        sum += Math.abs(d) / (k * k);
      }
  return n ? sum / (n * 3) : 0;
}

// Mean brightness, 0..255, and whether anything but one flat colour was drawn.
export function stats(img) {
  let sum = 0, min = 255, max = 0;
  for (let i = 0; i < img.data.length; i += 4) {
    const v = (img.data[i] + img.data[i + 1] + img.data[i + 2]) / 3;
    sum += v;
    min = Math.min(min, v);
    max = Math.max(max, v);
  }
  return { mean: sum / (img.data.length / 4), min, max };
}

// ---- for the benchmarks (bench*.mjs) ----

// `node BENCH.mjs [runs] [seconds] [WxH]`, with these defaults; exits with a usage line
// on anything else.
export function benchArgs(name, { runs = 3, seconds = 5, size = '400x300' } = {}) {
  const r = Number(process.argv[2] || runs), s = Number(process.argv[3] || seconds), z = process.argv[4] || size;
  if (!(r >= 1 && s > 0 && /^\d+x\d+$/.test(z))) {
    console.error(`usage: node ${name} [runs >= 1] [seconds > 0] [WxH]`);
    process.exit(2);
  }
  return { runs: r, seconds: s, size: z };
}

export const median = (v) => {
  const s = [...v].sort((a, b) => a - b), n = s.length;
  return n % 2 ? s[(n - 1) / 2] : (s[n / 2 - 1] + s[n / 2]) / 2;
};

// Frames the page draws per second: `runs` runs of `seconds` each, frames counted over the
// wall time between them.
export async function framesPerSecond(page, runs, seconds) {
  const fps = [];
  for (let i = 0; i < runs; ++i) {
    const f0 = await page.evaluate(() => ({ frames: window.draught.frames(), t: performance.now() }));
    await page.waitForTimeout(seconds * 1000);
    const f1 = await page.evaluate(() => ({ frames: window.draught.frames(), t: performance.now() }));
    fps.push((1000 * (f1.frames - f0.frames)) / (f1.t - f0.t));
  }
  return fps;
}
