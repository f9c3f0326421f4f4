import { start, openPage, waitFrames } from './lib.mjs';
const env = await start();
for (let i = 0; i < 3; ++i) {
  const t0 = Date.now();
  const ctx = await env.browser.newContext({ viewport: { width: 720, height: 560 } });
  const page = await ctx.newPage();
  await page.goto(env.base + 'index.html?size=160x120&scale=1&preserve');
  const t1 = Date.now();
  await page.waitForFunction(() => window.draught && (window.draught.ready || window.draught.error), null, { timeout: 120000 });
  const t2 = Date.now();
  await waitFrames(page, 2);
  const t3 = Date.now();
  await waitFrames(page, 10);
  const t4 = Date.now();
  console.log(`open ${i}: goto ${t1-t0} ms, ready ${t2-t1} ms, 2 frames ${t3-t2} ms, 10 frames ${t4-t3} ms`);
  await ctx.close();
}
await env.close();
