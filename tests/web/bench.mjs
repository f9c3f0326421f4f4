// A benchmark, not a test (nothing is asserted, CTest does not run it): the web page's frame
// rate in headless chromium on SwiftShader (the tests' browser, lib.mjs), for the droplets
// scenes of issue 13 at the size. `node bench.mjs [runs] [seconds] [WxH]` after
// scripts/build-web.sh (scripts/test-web.sh installs playwright-core).
//
// Method: the canvas pinned at W x H CSS pixels and render scale 1 (?size=WxH&scale=1: the
// backing store is W x H at devicePixelRatio 1; no adaptive quality), the preset chosen in
// the page's picker, a mouse moving round a circle over the canvas (pointermove events every
// 16 ms, so the trail keeps stretching), 4 s of warm-up (the shaders compile), then `runs`
// runs of `seconds` each: frames drawn (window.draught.frames) over the wall time between
// them. Prints each run and the median. Each scene in the full tier and in the MatCap tier
// (render.tier matcap: where a slow device's adaptive quality falls).
import { benchArgs, framesPerSecond, median, openPage, start } from './lib.mjs';

const { runs, seconds, size } = benchArgs('bench.mjs', { runs: 5, seconds: 8 });

const env = await start();
try {
  console.log(`chromium ${env.browser.version()}, SwiftShader (lib.mjs flags); ${size} CSS px at scale 1; ${runs} runs of ${seconds} s after 4 s of warm-up`);
  for (const [preset, tier] of [['droplets-seed', 'full'], ['droplets', 'full'], ['droplets-seed', 'matcap'], ['droplets', 'matcap']]) {
    const page = await openPage(env, { query: `size=${size}&scale=1` });
    try {
      await page.selectOption('#drink', preset);
      await page.waitForFunction(() => window.draught.droplets().droplets === true, null, { timeout: 30000 });
      if (tier === 'matcap') {
        const refused = await page.evaluate(() => window.draught.setParam('render.tier', 'matcap'));
        if (refused) throw new Error(refused);
      }
      // The mouse circles over the canvas: real pointermove events, as a hand makes them.
      await page.evaluate(() => {
        const canvas = document.getElementById('canvas');
        let a = 0;
        window.benchMouse = setInterval(() => {
          const r = canvas.getBoundingClientRect();
          a += 0.06;
          canvas.dispatchEvent(new PointerEvent('pointermove', {
            clientX: r.left + r.width * (0.5 + 0.3 * Math.cos(a)), clientY: r.top + r.height * (0.5 + 0.25 * Math.sin(a)),
            pointerType: 'mouse', bubbles: true,
          }));
        }, 16);
      });
      await page.waitForTimeout(4000);
      const fps = await framesPerSecond(page, runs, seconds);
      const st = await page.evaluate(() => window.draught.status());
      const moved = await page.evaluate(() => window.draught.droplets());
      const spread = Math.max(...moved.spheres.map((s) => Math.hypot(s[0] - moved.spheres[0][0], s[1] - moved.spheres[0][1])));
      console.log(`${preset.padEnd(14)} ${st.width}x${st.height} tier ${st.tier}: fps ${fps.map((f) => f.toFixed(1)).join(' ')}; ` +
                  `median ${median(fps).toFixed(1)} fps (${(1000 / median(fps)).toFixed(1)} ms a frame; the module's CPU part ${st.cpu_ms.toFixed(1)} ms); ` +
                  `trail spread ${(100 * spread).toFixed(1)} cm`);
    } finally {
      await page.context().close();
    }
  }
} finally {
  await env.close();
}
