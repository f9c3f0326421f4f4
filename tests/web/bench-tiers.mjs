// A benchmark, not a test (nothing is asserted, CTest does not run it): the default pint of
// lager in the full tier and in the MatCap tier (issue 11, docs/MATCAP.md) on the web page
// in headless chromium on SwiftShader, with the camera still and with it moving.
// `node bench-tiers.mjs [runs] [seconds] [WxH]` after scripts/build-web.sh
// (scripts/test-web.sh installs playwright-core).
//
// Method: the canvas pinned at W x H CSS pixels and render scale 1 (?size=WxH&scale=1),
// auto-framing off and the camera where the preset frames it; "moving": at every animation
// frame the page's camera.eye steps 2 mm to one side and back (a new view each frame: the
// MatCap tier keeps no background). 4 s of warm-up (the shaders compile), then `runs` runs of
// `seconds` each: frames drawn over the wall time. The four states one after another in
// one browser; prints each run, the medians and the ratios full / MatCap.
import { benchArgs, framesPerSecond, median, openPage, start } from './lib.mjs';

const { runs, seconds, size } = benchArgs('bench-tiers.mjs', { runs: 3, seconds: 6 });

const env = await start();
const ms = {};
try {
  console.log(`chromium ${env.browser.version()}, SwiftShader (lib.mjs flags); ${size} CSS px at scale 1; ${runs} runs of ${seconds} s after 4 s of warm-up`);
  for (const [tier, moving] of [['full', false], ['matcap', false], ['full', true], ['matcap', true]]) {
    const page = await openPage(env, { query: `size=${size}&scale=1` });
    try {
      await page.selectOption('#drink', 'lager');
      await page.waitForTimeout(1000);
      const eye = await page.evaluate(() => JSON.parse(window.draught.api.values())['camera.eye']);
      for (const [path, value] of [['camera.auto_frame', 'false'], ['camera.eye', eye], ['render.tier', tier]]) {
        const refused = await page.evaluate(([p, v]) => window.draught.setParam(p, v), [path, value]);
        if (refused) throw new Error(`${path}: ${refused}`);
      }
      if (moving) {
        await page.evaluate((eye) => {
          const [x, y, z] = eye.split(',').map(Number);
          let side = 0;
          const step = () => {  // once per animation frame: each picture a new view
            side ^= 1;
            window.draught.setParam('camera.eye', `${x + 0.002 * side},${y},${z}`);
            requestAnimationFrame(step);
          };
          requestAnimationFrame(step);
        }, eye);
      }
      await page.waitForTimeout(4000);
      const fps = await framesPerSecond(page, runs, seconds);
      const st = await page.evaluate(() => window.draught.status());
      const key = `${tier}${moving ? ', camera moving' : ''}`;
      ms[key] = 1000 / median(fps);
      console.log(`${key.padEnd(22)} ${st.width}x${st.height} tier ${st.tier}: fps ${fps.map((f) => f.toFixed(1)).join(' ')}; ` +
                  `median ${median(fps).toFixed(2)} fps (${ms[key].toFixed(0)} ms a frame; the module's CPU part ${st.cpu_ms.toFixed(1)} ms)`);
    } finally {
      await page.context().close();
    }
  }
  console.log(`full / MatCap: camera still ${(ms['full'] / ms['matcap']).toFixed(1)}x, ` +
              `camera moving ${(ms['full, camera moving'] / ms['matcap, camera moving']).toFixed(1)}x`);
} finally {
  await env.close();
}
