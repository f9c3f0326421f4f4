// A benchmark, not a test (nothing is asserted, CTest does not run it): point clouds of 10k,
// 100k and 1M metaballs in the web page, in headless chromium on SwiftShader (the tests'
// browser, lib.mjs). `node bench-clouds.mjs [frames] [WxH]` after scripts/build-web.sh.
//
// Method: the cloud of `draught bench --scenes clouds` (points uniform in a ball of 4 cm
// radius, each blob 1.2 of the mean spacing, 1100 C), written here as a binary PLY (x, y,
// z, radius, temperature as floats) and loaded through the page's "Point cloud…" input,
// which fits it to the view (so the three cover the same pixels). Timed: the load (the
// file read, checked, fitted, its tree built and uploaded: from the input to the page's
// message) and then `frames` frames drawn, over the wall time between them, with the
// canvas pinned at W x H and render scale 1 (no adaptive quality).
import { start, openPage } from './lib.mjs';

const frames = Number(process.argv[2] || 3);
const size = process.argv[3] || '256x256';
if (!(frames >= 1 && /^\d+x\d+$/.test(size))) {
  console.error('usage: node bench-clouds.mjs [frames >= 1] [WxH]');
  process.exit(2);
}

function blobPly(n) {
  let seed = 7;
  const rand = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648) * 2 - 1;
  const radius = 0.04, spacing = Math.cbrt((4.18879 * radius ** 3) / n);
  const header = `ply\nformat binary_little_endian 1.0\nelement vertex ${n}\nproperty float x\nproperty float y\n` +
                 'property float z\nproperty float radius\nproperty float temperature\nend_header\n';
  const body = new Float32Array(5 * n);
  for (let i = 0; i < n;) {
    const x = rand(), y = rand(), z = rand();
    if (x * x + y * y + z * z > 1) continue;
    body.set([radius * x, radius * y, radius * z, 1.2 * spacing, 1373.15], 5 * i++);
  }
  return Buffer.concat([Buffer.from(header), Buffer.from(body.buffer)]);
}

const env = await start();
try {
  console.log(`chromium ${env.browser.version()}, SwiftShader (lib.mjs flags); ${size} CSS px at scale 1; ${frames} frames after the first`);
  for (const [name, n] of [['cloud-10k', 1e4], ['cloud-100k', 1e5], ['cloud-1m', 1e6]]) {
    const page = await openPage(env, { query: `size=${size}&scale=1` });
    try {
      const bytes = blobPly(n);
      const t0 = Date.now();
      await page.setInputFiles('#cloud', { name: `${name}.ply`, mimeType: 'application/octet-stream', buffer: bytes });
      await page.waitForFunction((f) => new RegExp(`point cloud ${f}|${f}.*`).test(document.getElementById('message').textContent),
                                 `${name}\\.ply`, { timeout: 600000, polling: 100 });
      const loadMs = Date.now() - t0;
      const msg = await page.evaluate(() => document.getElementById('message').textContent);
      // The first frame after the load (the shaders' variant for clouds may compile), then the timed ones.
      const first = await page.evaluate(() => window.draught.frames());
      await page.waitForFunction((f) => window.draught.frames() > f, first, { timeout: 600000, polling: 50 });
      const f0 = await page.evaluate(() => ({ frames: window.draught.frames(), t: performance.now() }));
      await page.waitForFunction((f) => window.draught.frames() >= f, f0.frames + frames, { timeout: 600000, polling: 50 });
      const f1 = await page.evaluate(() => ({ frames: window.draught.frames(), t: performance.now() }));
      const ms = (f1.t - f0.t) / (f1.frames - f0.frames);
      const st = await page.evaluate(() => window.draught.status());
      console.log(`${name.padEnd(11)} ${(bytes.length / 1048576).toFixed(1)} MiB: load ${loadMs} ms ("${msg}"); ` +
                  `${st.width}x${st.height} tier ${st.tier}: ${ms.toFixed(0)} ms a frame over ${f1.frames - f0.frames} frames ` +
                  `(the module's CPU part ${st.cpu_ms.toFixed(1)} ms)`);
    } finally {
      await page.context().close();
    }
  }
} finally {
  await env.close();
}
