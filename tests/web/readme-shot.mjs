// The README's picture of the web page (docs/images/web.png): the page in headless chromium
// on SwiftShader (lib.mjs), 720 x 560, the canvas at 360 x 420 CSS pixels and render scale
// 1, the default drink, once the floor's light is refined. Not a test: `node
// readme-shot.mjs [OUT.png]` after scripts/build-web.sh.
import path from 'node:path';
import { artifacts, openPage, start, waitFrames } from './lib.mjs';

const out = process.argv[2] || path.join(artifacts, 'web.png');
const env = await start();
try {
  const page = await openPage(env, { query: 'size=360x420&scale=1' });
  await waitFrames(page, 104);  // the floor's light refines over a hundred frames once still
  await page.screenshot({ path: out });
  console.log(`wrote ${out}`);
} finally {
  await env.close();
}
