// Browser tests of the web page (out/web) in Debian's chromium with software WebGL2. Plain
// node + assert; ends with "web tests: N passed, M failed" and a non-zero exit on failure.
// `node run.mjs [substring]` runs only the tests whose name contains it.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { start, openPage, waitFrames, snapshot, difference, blockDifference, stats, artifacts, patience } from './lib.mjs';

const tests = [];
const test = (name, fn) => tests.push({ name, fn });

let env;        // browser + server
let desk;       // the desktop page most tests share (mouse, no touch)
const desktop = async () => (desk ??= await openPage(env));

// Pixels move a little on their own (rising bubbles, the foam's big bubbles): a change must
// stand well above that.
// (A change just made, whose frame may not be drawn yet, is let through first: it is not noise.)
async function noise(page) {
  await waitFrames(page, 2);
  const a = await snapshot(page);
  await waitFrames(page, 3);
  return { before: a, noise: difference(a, await snapshot(page)) };
}
const changed = (d, n) => Math.max(2.0, 4 * n);
const notes = [];  // measured differences, printed with the test's result
const note = (text) => notes.push(text);

const values = (page) => page.evaluate(() => JSON.parse(window.draught.api.values()));
const status = (page) => page.evaluate(() => window.draught.status());
const message = (page) => page.evaluate(() => ({ text: document.getElementById('message').textContent,
  error: document.getElementById('message').classList.contains('error') }));
async function canvasCentre(page) {
  const r = await page.evaluate(() => {
    const b = document.getElementById('canvas').getBoundingClientRect();
    return { x: b.left, y: b.top, w: b.width, h: b.height };
  });
  return { x: r.x + r.w / 2, y: r.y + r.h / 2, ...r };
}

// ---- the tests ----

test('the page loads, builds its pickers and draws without errors', async () => {
  const page = await desktop();
  assert.equal(await page.title(), 'draught');
  const drinks = await page.$$eval('#drink option', (o) => o.map((x) => x.value));
  const glasses = await page.$$eval('#glass option', (o) => o.map((x) => x.value));
  for (const d of ['lager', 'stout', 'red-wine']) assert.ok(drinks.includes(d), `drink ${d} in ${drinks}`);
  for (const g of ['', 'pint', 'nonic', 'wine']) assert.ok(glasses.includes(g), `glass ${g} in ${glasses}`);
  const bad = page.draughtLog.filter((l) => l.startsWith('error') || l.startsWith('pageerror'));
  assert.deepEqual(bad, []);
  await page.screenshot({ path: path.join(artifacts, 'page.png') });
});

test('a WebGL2 context exists', async () => {
  const page = await desktop();
  const gl = await page.evaluate(() => {
    const g = document.getElementById('canvas').getContext('webgl2');  // the module's own context
    return g && { webgl2: g instanceof WebGL2RenderingContext, version: g.getParameter(g.VERSION) };
  });
  assert.ok(gl && gl.webgl2, 'canvas has a WebGL2 context');
  assert.match(gl.version, /WebGL 2\.0/);
});

test('frames are drawn and the frame counter increases', async () => {
  const page = await desktop();
  const f0 = await page.evaluate(() => window.draught.frames());
  await waitFrames(page, 3);
  assert.ok((await page.evaluate(() => window.draught.frames())) >= f0 + 3);
  const img = await snapshot(page);
  assert.equal(img.width, 160);
  assert.equal(img.height, 120);
  const s = stats(img);
  assert.ok(s.max - s.min > 60, `a picture, not a flat colour (min ${s.min}, max ${s.max})`);
});

test('the parameter panel comes from the table; bad values are refused with a message', async () => {
  const page = await desktop();
  const table = await page.evaluate(() => JSON.parse(window.draught.api.table()));
  assert.ok(table.length > 50);
  assert.equal(await page.locator('.param').count(), table.length);
  const fill = table.find((d) => d.path === 'liquid.fill');
  assert.ok((await page.getAttribute('.param[data-path="liquid.fill"]', 'title')).includes(fill.doc));
  assert.ok((await page.locator('details').count()) >= 8, 'grouped');
  assert.equal(await page.locator('.param[data-path="bubbles.etched_base"] input[type=checkbox]').count(), 1);
  assert.equal(await page.locator('.param[data-path="liquid.haze_color"] input[type=color]').count(), 1);
  assert.equal(await page.locator('.param[data-path="env.mode"] select').count(), 1);
  assert.equal(await page.locator('.param[data-path="liquid.srm"] input[type=range]').count(), 1);

  const before = (await values(page))['liquid.fill'];
  await page.fill('#p-liquid-fill', '7');
  await page.dispatchEvent('#p-liquid-fill', 'change');
  await page.waitForFunction(() => document.getElementById('message').classList.contains('error'));
  const m = await message(page);
  assert.match(m.text, /^field 'liquid\.fill': expected .*, got "7"$/);
  assert.equal((await values(page))['liquid.fill'], before, 'the bad value was not applied');
  assert.match(await page.textContent('.param[data-path="liquid.fill"] .err'), /expected/);

  await page.fill('#p-liquid-fill', '0.5');
  await page.dispatchEvent('#p-liquid-fill', 'change');
  await page.waitForFunction(() => JSON.parse(window.draught.api.values())['liquid.fill'] === '0.5');
  assert.equal(await page.textContent('.param[data-path="liquid.fill"] .err'), '');

  // The drink's colour rows say which is in effect: the lager's SRM 3.5, shown as EBC
  // beside an EBC of 0; an EBC typed in takes over, and the SRM row says so.
  const note = (path) => page.textContent(`.param[data-path="${path}"] .note`);
  assert.equal(await note('liquid.srm'), '');
  assert.equal(await note('liquid.ebc'), 'in effect: 6.89 (from SRM)');
  assert.equal(await note('liquid.wine'), 'unused: SRM in effect');
  await page.fill('#p-liquid-ebc', '20');
  await page.dispatchEvent('#p-liquid-ebc', 'change');
  await page.waitForFunction(() => document.querySelector('.param[data-path="liquid.ebc"] .note').textContent === '');
  assert.equal(await note('liquid.srm'), 'in effect: 10.2 (from EBC)');
  assert.equal(await note('liquid.absorption'), 'unused: EBC in effect');
  assert.equal(await page.evaluate(() => window.draught.setParam('liquid.ebc', '0')), '');
  assert.equal(await note('liquid.ebc'), 'in effect: 6.89 (from SRM)');
});

test('switching preset changes the picture', async () => {
  const page = await desktop();
  await page.selectOption('#drink', 'lager');
  await waitFrames(page, 3);
  const { before, noise: n } = await noise(page);
  await page.selectOption('#drink', 'stout');
  await waitFrames(page, 3);
  const stout = await snapshot(page);
  const d = difference(before, stout);
  note(`lager->stout ${d.toFixed(1)}, noise ${n.toFixed(2)}`);
  assert.ok(d > changed(d, n) && d > 6, `lager -> stout: difference ${d.toFixed(2)} (noise ${n.toFixed(2)})`);
  assert.equal((await status(page)).drink, 'stout');
  assert.equal((await values(page))['glass.ior'] !== undefined, true);
  await page.selectOption('#glass', 'wine');
  await waitFrames(page, 3);
  const d2 = difference(stout, await snapshot(page));
  note(`pint->wine ${d2.toFixed(1)}`);
  assert.ok(d2 > changed(d2, n), `pint -> wine glass: difference ${d2.toFixed(2)}`);
  await page.screenshot({ path: path.join(artifacts, 'stout-in-wine-glass.png') });
  await page.selectOption('#glass', '');
  await page.selectOption('#drink', 'lager');
  await waitFrames(page, 3);
});

test('a mouse drag tilts the glass', async () => {
  const page = await desktop();
  const { before, noise: n } = await noise(page);
  const c = await canvasCentre(page);
  await page.mouse.move(c.x, c.y);
  await page.mouse.down();
  await page.mouse.move(c.x + 30, c.y, { steps: 4 });
  await waitFrames(page, 6);
  const tilted = await snapshot(page);
  await page.mouse.up();
  const d = difference(before, tilted);
  note(`drag ${d.toFixed(1)}, noise ${n.toFixed(2)}`);
  assert.ok(d > changed(d, n), `difference ${d.toFixed(2)} (noise ${n.toFixed(2)})`);
  await waitFrames(page, 12);  // back upright
});

test('a broken preset file shows the error and keeps the last good state', async () => {
  const page = await desktop();
  const v0 = await values(page);
  const { before, noise: n } = await noise(page);
  const broken = '{ "draught_preset": 1, "kind": "drink", "name": "bad",\n  "params": { "liquid": { "srm": 12, "fill": 7 } } }';
  await page.setInputFiles('#load', { name: 'broken.json', mimeType: 'application/json', buffer: Buffer.from(broken) });
  await page.waitForFunction(() => /broken\.json/.test(document.getElementById('message').textContent));
  let m = await message(page);
  assert.ok(m.error, 'shown as an error');
  assert.match(m.text, /broken\.json/);
  assert.match(m.text, /liquid\.fill/);
  assert.match(m.text, /expected/);
  assert.deepEqual(await values(page), v0, 'nothing applied (liquid.srm is unchanged too)');

  await page.setInputFiles('#load', { name: 'syntax.json', mimeType: 'application/json', buffer: Buffer.from('{ "kind": "drink", ') });
  await page.waitForFunction(() => /syntax\.json/.test(document.getElementById('message').textContent));
  m = await message(page);
  assert.ok(m.error);
  assert.deepEqual(await values(page), v0);
  await waitFrames(page, 3);
  const d = difference(before, await snapshot(page));
  note(`${d.toFixed(2)}, noise ${n.toFixed(2)}`);
  assert.ok(d < Math.max(2, 4 * n), `picture kept: difference ${d.toFixed(2)} (noise ${n.toFixed(2)})`);

  const good = JSON.stringify({ draught_preset: 1, kind: 'drink', name: 'dark', params: { liquid: { srm: 40 } } });
  await page.setInputFiles('#load', { name: 'dark.json', mimeType: 'application/json', buffer: Buffer.from(good) });
  await page.waitForFunction(() => /loaded drink "dark"/.test(document.getElementById('message').textContent));
  assert.equal((await values(page))['liquid.srm'], '40');
  await waitFrames(page, 3);  // drawn before the next test measures its noise
});

test('an HDR environment file becomes the surroundings; a broken one changes nothing', async () => {
  const page = await desktop();
  const v0 = await values(page);
  const { before, noise: n } = await noise(page);
  await page.setInputFiles('#environment', { name: 'broken.hdr', mimeType: 'image/vnd.radiance', buffer: Buffer.from('#?RADIANCE\nno pixels') });
  await page.waitForFunction(() => /broken\.hdr/.test(document.getElementById('message').textContent));
  const m = await message(page);
  assert.ok(m.error, 'shown as an error');
  assert.match(m.text, /env\.image/);
  assert.deepEqual(await values(page), v0, 'nothing applied');

  const bar = fs.readFileSync(new URL('../../presets/environments/bar.hdr', import.meta.url));
  await page.setInputFiles('#environment', { name: 'my-bar.hdr', mimeType: 'image/vnd.radiance', buffer: bar });
  await page.waitForFunction(() => /environment my-bar\.hdr/.test(document.getElementById('message').textContent));
  const v = await values(page);
  assert.equal(v['env.mode'], 'image');
  assert.match(v['env.image'], /my-bar\.hdr$/);
  await waitFrames(page, 3);
  const d = difference(before, await snapshot(page));
  note(`studio -> bar ${d.toFixed(1)}, noise ${n.toFixed(2)}`);
  assert.ok(d > changed(d, n) && d > 6, `the bar around the drink: difference ${d.toFixed(2)}`);
  await page.screenshot({ path: path.join(artifacts, 'lager-in-the-bar.png') });
  assert.equal(await page.evaluate(() => window.draught.api.setParam('env.mode', 'studio')), '');
  await waitFrames(page, 3);
});

test('export downloads the current state as a preset that loads back', async () => {
  const page = await desktop();
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#export')]);
  assert.match(download.suggestedFilename(), /\.json$/);
  const text = fs.readFileSync(await download.path(), 'utf8');
  const j = JSON.parse(text);
  assert.equal(j.draught_preset, 1);
  assert.equal(j.kind, 'scene');
  assert.equal(j.params.liquid.srm, 40);
  assert.equal(await page.evaluate((t) => window.draught.loadText(t, 'exported.json'), text), '');
  await page.selectOption('#drink', 'lager');
});

// "Save picture": the frame drawn as the CLI draws a still, a PNG at the canvas's size.
test('save picture downloads a PNG of the picture at the canvas size; drawing goes on', async () => {
  const page = await desktop();
  const [download] = await Promise.all([page.waitForEvent('download', { timeout: patience(120000) }), page.click('#save-picture')]);
  assert.match(download.suggestedFilename(), /\.png$/);
  const png = fs.readFileSync(await download.path());
  fs.writeFileSync(path.join(artifacts, 'saved-picture.png'), png);
  assert.equal(png.subarray(1, 4).toString('latin1'), 'PNG');
  assert.equal(png.subarray(12, 16).toString('latin1'), 'IHDR');
  assert.deepEqual([png.readUInt32BE(16), png.readUInt32BE(20)], [160, 120]);
  // A picture, not an empty frame: a glass over the sweep does not compress to nothing.
  assert.ok(png.length > 8000, `${png.length} bytes`);
  const message = await page.textContent('#message');
  assert.match(message, /saved lager\.png \(160 x 120/);
  note(message);
  await waitFrames(page, 3);
});

test('a transparent picture lets the page show through the canvas: the lager cut out, its gold kept', async () => {
  const page = await desktop();
  await page.selectOption('#drink', 'lager');
  await waitFrames(page, 3);
  const opaque = await snapshot(page);
  let uncovered = 0;
  for (let i = 3; i < opaque.data.length; i += 4) uncovered += opaque.data[i] !== 255;
  assert.equal(uncovered, 0, 'an opaque picture left pixels of the canvas uncovered');
  assert.equal(await page.evaluate(() => window.draught.api.setParam('render.transparent', 'true')), '');
  try {
    await waitFrames(page, 3);
    const cut = await snapshot(page);
    const { width: w, height: h } = cut;
    const px = (x, y) => cut.data.slice((y * w + x) * 4, (y * w + x) * 4 + 4);
    for (const [x, y] of [[0, 0], [w - 1, 0], [0, h - 1], [w - 1, h - 1]]) assert.equal(px(x, y)[3], 0, `corner ${x},${y} is covered`);
    let clear = 0, gold = 0;
    for (let y = 0; y < h; ++y)
      for (let x = 0; x < w; ++x) {
        const [r, g, b, a] = px(x, y);
        clear += a === 0;
        gold += a > 200 && r > 140 && r > b + 60 && g > b + 30;
      }
    note(`transparent: ${clear} of ${w * h} pixels clear, ${gold} covered and gold`);
    await page.screenshot({ path: path.join(artifacts, 'transparent-lager.png') });
    assert.ok(clear > 0.3 * w * h, `only ${clear} clear pixels`);
    assert.ok(gold > 0.03 * w * h, `only ${gold} pixels of gold lager`);
  } finally {
    assert.equal(await page.evaluate(() => window.draught.api.setParam('render.transparent', 'false')), '');
    await waitFrames(page, 3);
  }
});

test('a decal image from disk goes on the selected glass; a broken one changes nothing', async () => {
  const page = await desktop();
  await page.selectOption('#drink', 'lager');
  // No rising bubbles (they move on their own): the decal is small on the test's canvas.
  assert.equal(await page.evaluate(() => window.draught.setParam('bubbles.carbonation', '0')), '');
  await waitFrames(page, 3);
  const v0 = await values(page);
  // Measured where the glass is, in 2 x 2 blocks.
  const before = await snapshot(page);
  await waitFrames(page, 3);
  const box = { x0: Math.round(before.width * 0.3), y0: Math.round(before.height * 0.3),
                x1: Math.round(before.width * 0.7), y1: Math.round(before.height * 0.8) };
  const n = blockDifference(before, await snapshot(page), box, 2);
  await page.setInputFiles('#decal', { name: 'broken.png', mimeType: 'image/png', buffer: Buffer.from('not a picture') });
  await page.waitForFunction(() => /decal_outer/.test(document.getElementById('message').textContent));
  let m = await message(page);
  assert.ok(m.error, 'shown as an error');
  assert.match(m.text, /decal_outer\.file/);
  assert.match(m.text, /expected a PNG image/);
  assert.deepEqual(await values(page), v0, 'nothing applied');
  // A good one (the shipped wordmark's bytes, under another name), on the outer wall.
  const png = fs.readFileSync(new URL('../../presets/decals/wordmark.png', import.meta.url));
  await page.setInputFiles('#decal', { name: 'my logo.png', mimeType: 'image/png', buffer: png });
  await page.waitForFunction(() => /outer decal/.test(document.getElementById('message').textContent));
  m = await message(page);
  assert.ok(!m.error, m.text);
  const v = await values(page);
  assert.match(v['decal_outer.file'], /^\/uploads\/decals\/\d+\/my_logo\.png$/);
  assert.equal(v['decal_inner.file'], '');
  // Large and black, to stand out of the small test canvas.
  assert.equal(await page.evaluate(() => window.draught.setParam('decal_outer.color', '0.02,0.02,0.02')), '');
  assert.equal(await page.evaluate(() => window.draught.setParam('decal_outer.width', '0.08')), '');
  await waitFrames(page, 3);
  await page.screenshot({ path: path.join(artifacts, 'lager-with-a-decal.png') });
  const d = blockDifference(before, await snapshot(page), box, 2);
  note(`with the decal ${d.toFixed(2)}, noise ${n.toFixed(2)}`);
  assert.ok(d > changed(d, n), `the decal shows: difference ${d.toFixed(2)} (noise ${n.toFixed(2)})`);
  // The panel's text field takes a shipped name, and "" takes it off.
  assert.equal(await page.evaluate(() => window.draught.setParam('decal_outer.file', 'crest')), '');
  assert.equal(await page.evaluate(() => window.draught.setParam('decal_outer.file', '')), '');
  await page.selectOption('#drink', 'stout');
  await page.selectOption('#drink', 'lager');  // the preset's own values again
});

// A blob of `n` points in millimetres (x y z radius), deterministic: the page must fit it
// to the view whatever its units.
function blobXyz(n, radiusMm) {
  let seed = 7;
  const rand = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
  const lines = ['x y z radius'];
  while (lines.length <= n) {
    const p = [rand() * 2 - 1, rand() * 2 - 1, rand() * 2 - 1];
    if (p[0] * p[0] + p[1] * p[1] + p[2] * p[2] > 1) continue;
    lines.push(`${(p[0] * radiusMm).toFixed(3)} ${(p[1] * radiusMm).toFixed(3)} ${(p[2] * radiusMm).toFixed(3)} ${(radiusMm / 4).toFixed(3)}`);
  }
  return Buffer.from(lines.join('\n') + '\n');
}

test('a point cloud file is shown on its own, fitted to the view; a broken one changes nothing', async () => {
  const page = await openPage(env);  // its own page: the cloud replaces the scene
  try {
    const v0 = await values(page);
    const { before, noise: n } = await noise(page);
    const broken = 'ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n1 2 3\n4 5\n';
    await page.setInputFiles('#cloud', { name: 'broken.ply', mimeType: 'application/octet-stream', buffer: Buffer.from(broken) });
    await page.waitForFunction(() => /broken\.ply/.test(document.getElementById('message').textContent));
    const m = await message(page);
    note(m.text);
    assert.ok(m.error, 'shown as an error');
    assert.match(m.text, /broken\.ply.*(line|byte)/, 'names the file and where');
    assert.deepEqual(await values(page), v0, 'nothing applied');

    await page.setInputFiles('#cloud', { name: 'blob.xyz', mimeType: 'text/plain', buffer: blobXyz(300, 20) });
    await page.waitForFunction(() => /point cloud blob\.xyz/.test(document.getElementById('message').textContent), null, { timeout: patience(30000) });
    const ok = await message(page);
    note(ok.text);
    assert.ok(!ok.error);
    assert.match(ok.text, /300 points/);
    // Points within 20 mm of the centre, grown by their own 5 mm: at most 50 mm across, fitted
    // to 80 mm (300 random points reach close to the sphere's edge, not onto it).
    const scale = Number(/([0-9.e-]+) m per unit/.exec(ok.text)[1]);
    assert.ok(scale >= 0.08 / 50 && scale < 0.08 / 44, `scale ${scale}`);
    await waitFrames(page, 3);
    const after = await snapshot(page);
    const d = difference(before, after);
    // The hot glass glows in the middle of the picture: the centre's box is bright and warm.
    const w = after.width, h = after.height;
    let r = 0, b = 0, k = 0;
    for (let y = Math.floor(h * 0.4); y < h * 0.6; ++y)
      for (let x = Math.floor(w * 0.4); x < w * 0.6; ++x, ++k) {
        r += after.data[4 * (y * w + x)];
        b += after.data[4 * (y * w + x) + 2];
      }
    note(`scene -> cloud ${d.toFixed(1)}, noise ${n.toFixed(2)}; centre red ${(r / k).toFixed(0)}, blue ${(b / k).toFixed(0)}`);
    assert.ok(d > changed(d, n) && d > 6, `the picture changed: difference ${d.toFixed(2)}`);
    assert.ok(r / k > 100 && r / k > 1.5 * (b / k), 'the cloud glows orange in the middle');
    await page.screenshot({ path: path.join(artifacts, 'point-cloud.png') });
  } finally {
    await page.context().close();
  }
});

test('devicemotion tilts the liquid (rig picks up the gyro)', async () => {
  const page = await desktop();
  await page.selectOption('#drink', 'lager');
  await waitFrames(page, 3);
  assert.equal((await status(page)).input, 'mouse');
  const { before, noise: n } = await noise(page);
  // The device rolled 35 degrees (gravity's reaction no longer along the screen's y).
  await page.evaluate(async () => {
    const a = (35 * Math.PI) / 180, g = 9.81;
    for (let i = 0; i < 20; ++i) {
      window.dispatchEvent(new DeviceMotionEvent('devicemotion', {
        accelerationIncludingGravity: { x: g * Math.sin(a), y: g * Math.cos(a), z: 0 },
        rotationRate: { alpha: 0, beta: 0, gamma: 0 }, interval: 16 }));
      await new Promise((r) => setTimeout(r, 16));
    }
  });
  await waitFrames(page, 6);
  assert.equal((await status(page)).input, 'mouse+gyro');
  const d = difference(before, await snapshot(page));
  note(`${d.toFixed(2)}, noise ${n.toFixed(2)}`);
  assert.ok(d > changed(d, n), `difference ${d.toFixed(2)} (noise ${n.toFixed(2)})`);
  await page.screenshot({ path: path.join(artifacts, 'device-motion.png') });
});

test('adaptive quality lowers the render scale to hold the frame budget and says so', async () => {
  const page = await desktop();
  await page.evaluate(() => window.draught.api.quality(0, 5));  // adaptive, 5 ms: SwiftShader cannot
  await page.waitForFunction(() => window.draught.status().scale < 1, null, { timeout: patience(30000), polling: 100 });
  await page.waitForFunction(() => /quality \d+ %/.test(document.getElementById('quality').textContent) &&
                                   !/quality 100 %/.test(document.getElementById('quality').textContent),
                             null, { timeout: patience(5000) });
  const s = await status(page);
  assert.ok(s.width < 160 && s.height < 120, `backing store ${s.width}x${s.height}`);
  await page.screenshot({ path: path.join(artifacts, 'adaptive.png') });
  // The pages below get the (single) software GPU to themselves.
  await page.context().close();
  desk = null;
});

// An emulated phone (390 x 844 CSS px at DPR 3, touch, as issue 11 asks) given a frame
// budget no device holds (2 ms): with the MatCap tier the page falls to it and says so;
// with ?nomatcap it keeps the full tier at the smallest scale with the interactions capped.
// Either way the backing store follows the scale. Where between those a real device settles
// (higher with the MatCap tier) is the controller's logic, asserted against a model of a
// phone's frame times in tests/unit/quality: on this shared machine a budget derived from
// one moment's speed made that comparison depend on the load minutes later.
test('an emulated phone falls to the MatCap tier when the full tier misses the budget', async () => {
  const phone = { viewport: { width: 390, height: 844 }, deviceScaleFactor: 3, hasTouch: true, isMobile: true };
  // The quality readout follows the status on the page's own timer: both are read together.
  const read = async (page) => ({ ...(await status(page)), text: await page.evaluate(() => document.getElementById('quality').textContent) });
  const settle = async (query, done) => {
    const page = await openPage(env, { query, context: phone });
    try {
      const t0 = Date.now();
      let s = await read(page);
      // A decision waits 3-12 frames; each frame gets the per-frame limit.
      while (!done(s) && s.frames <= 200) {
        await waitFrames(page, 1);
        s = await read(page);
      }
      await page.screenshot({ path: path.join(artifacts, `phone-${query.includes('nomatcap') ? 'full' : 'matcap'}.png`) });
      return { ...s, after_s: (Date.now() - t0) / 1000 };
    } finally {
      await page.context().close();
    }
  };
  const smallest = 0.3;
  const full = await settle('nomatcap&budget=2', (s) => s.scale <= smallest && s.events_cap > 0 && /events\)/.test(s.text));
  const matcap = await settle('budget=2', (s) => s.tier === 'matcap' && s.scale <= smallest && /quality 30 % · MatCap/.test(s.text));
  note(`full tier only: scale ${full.scale} (${full.width}x${full.height}, events cap ${full.events_cap}, after ${full.frames} frames, ${full.after_s.toFixed(0)} s); ` +
       `with the MatCap tier: scale ${matcap.scale} (${matcap.width}x${matcap.height}, tier ${matcap.tier}, after ${matcap.frames} frames, ${matcap.after_s.toFixed(0)} s); "${matcap.text}"`);
  assert.equal(full.tier, 'full');
  assert.equal(full.scale, smallest);
  assert.equal(full.events_cap, 6);
  assert.match(full.text, /quality 30 % \(6 events\)/);
  assert.doesNotMatch(full.text, /MatCap/);
  assert.equal(matcap.tier, 'matcap');
  assert.equal(matcap.scale, smallest);
  assert.equal(matcap.events_cap, 0);
  assert.match(matcap.text, /MatCap tier: the full tier missed the frame budget at 50 % resolution/);
  // The backing store: CSS width x device pixel ratio x scale.
  for (const s of [full, matcap]) assert.ok(Math.abs(s.width - 390 * 3 * smallest) <= 1, `width ${s.width}`);
});

test('deviceorientation tilts the liquid', async () => {
  const page = await openPage(env);
  try {
    const { before, noise: n } = await noise(page);
    await page.evaluate(async () => {
      // Held upright (beta 90), then rolled 35 degrees to the side about the screen's normal:
      // in W3C angles that ends at alpha 90, beta 55, gamma -90 (gravity along the device's
      // (sin 35, cos 35, 0), the screen still facing the same way).
      for (let i = 0; i < 24; ++i) {
        const u = Math.min(1, Math.max(0, (i - 4) / 12));
        window.dispatchEvent(new DeviceOrientationEvent('deviceorientation',
          { alpha: 90 * u, beta: 90 - 35 * u, gamma: -89.9 * u, absolute: false }));
        await new Promise((r) => setTimeout(r, 20));
      }
    });
    await waitFrames(page, 6);
    assert.equal((await status(page)).input, 'mouse+gyro');
    const d = difference(before, await snapshot(page));
    note(`${d.toFixed(2)}, noise ${n.toFixed(2)}`);
    assert.ok(d > changed(d, n), `difference ${d.toFixed(2)} (noise ${n.toFixed(2)})`);
    await page.screenshot({ path: path.join(artifacts, 'device-orientation.png') });
  } finally {
    await page.context().close();
  }
});

test('touch: one finger tilts, two fingers rotate and move the glass', async () => {
  const page = await openPage(env, { context: { hasTouch: true } });
  try {
    const cdp = await page.context().newCDPSession(page);
    const touch = (type, points) => cdp.send('Input.dispatchTouchEvent', { type, touchPoints: points.map(([x, y], id) => ({ x, y, id })) });
    const c = await canvasCentre(page);
    const { before, noise: n } = await noise(page);
    await touch('touchStart', [[c.x, c.y]]);
    for (let i = 1; i <= 4; ++i) await touch('touchMove', [[c.x + 8 * i, c.y]]);
    await waitFrames(page, 6);
    assert.equal((await status(page)).input, 'touch');
    const d1 = difference(before, await snapshot(page));
    note(`one finger ${d1.toFixed(1)}, noise ${n.toFixed(2)}`);
    await page.screenshot({ path: path.join(artifacts, 'touch-tilt.png') });
    assert.ok(d1 > changed(d1, n), `one finger: difference ${d1.toFixed(2)} (noise ${n.toFixed(2)})`);
    await touch('touchEnd', []);
    await waitFrames(page, 12);  // upright again

    const rest = await snapshot(page);
    const pair = (angle, shift) => {
      const r = 25, s = Math.sin(angle), co = Math.cos(angle);
      return [[c.x + shift - r * co, c.y - r * s], [c.x + shift + r * co, c.y + r * s]];
    };
    await touch('touchStart', pair(0, 0));
    for (let i = 1; i <= 4; ++i) await touch('touchMove', pair((i * Math.PI) / 8, i * 5));
    await waitFrames(page, 6);
    const d2 = difference(rest, await snapshot(page));
    note(`two fingers ${d2.toFixed(1)}`);
    assert.ok(d2 > changed(d2, n), `two fingers: difference ${d2.toFixed(2)} (noise ${n.toFixed(2)})`);
    await touch('touchEnd', []);
  } finally {
    await page.context().close();
  }
});

// ---- droplets following the pointer ----

const droplets = (page) => page.evaluate(() => window.draught.droplets());
// Waits until the trail's pointer has moved more than a centimetre away from `from` (when
// given), its head is within `near` metres of it and the whole trail within `gathered` of
// the head (the springs have settled), and returns the trail.
async function settled(page, from = null, near = 0.002, gathered = 0.004) {
  await page.waitForFunction(({ from, near, gathered }) => {
    const d = window.draught.droplets();
    const dist = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1]);
    return d.droplets && (!from || dist(d.pointer, from) > 0.01) && dist(d.spheres[0], d.pointer) < near &&
      d.spheres.every((s) => dist(s, d.spheres[0]) < gathered);
  }, { from, near, gathered }, { timeout: patience(30000), polling: 50 });
  return droplets(page);
}
// A CSS pixel of the canvas (fractions of its size from the top-left) in page coordinates, and
// the canvas pixel under it (the test pages draw one pixel per CSS pixel).
async function canvasPoint(page, fx, fy) {
  const r = await page.evaluate(() => {
    const b = document.getElementById('canvas').getBoundingClientRect();
    return { left: b.left, top: b.top, w: b.width, h: b.height };
  });
  const px = Math.floor(fx * r.w), py = Math.floor(fy * r.h);
  return { x: r.left + px + 0.5, y: r.top + py + 0.5, px, py };
}
const around = (p, r = 10) => ({ x0: p.px - r, y0: p.py - r, x1: p.px + r, y1: p.py + r });

test('droplets follow the mouse over the picture; a drag tilts the glass, not the pointer', async () => {
  const page = await openPage(env);
  try {
    assert.deepEqual(await droplets(page), { droplets: false });
    await page.selectOption('#drink', 'droplets');
    await page.waitForFunction(() => window.draught.droplets().droplets === true);
    assert.equal(await page.evaluate(() => window.draught.objects().objects.map((o) => o.kind).join()), 'vessel,droplets');
    const start = await settled(page);  // gathered at the plane's origin
    assert.equal(start.spheres.length, 16);
    // The trail reports the new scene before its first frame is on the canvas: let frames pass
    // before the noise is measured, or it measures the switch itself (a CI run saw 3.0).
    await waitFrames(page, 3);
    const { noise: n } = await noise(page);

    // Left of the picture's middle and a little below it: the trail's plane faces the camera
    // (yaw 0), so the pointer lies left of (and below) the droplets' origin, which is near the
    // middle of the picture.
    const left = await canvasPoint(page, 0.2, 0.62);
    await page.mouse.move(left.x, left.y);
    const a = await settled(page, start.pointer);
    assert.ok(a.pointer[0] < -0.04 && a.pointer[1] < 0, `pointer ${a.pointer} for the mouse left of and below the middle`);
    const atLeft = await snapshot(page);
    await page.screenshot({ path: path.join(artifacts, 'droplets-left.png') });
    // What the right's box does on its own while the droplets are away from it.
    await waitFrames(page, 3);
    const right = await canvasPoint(page, 0.78, 0.42);
    const nRight = blockDifference(atLeft, await snapshot(page), around(right));

    // To the right and a little higher: the trail follows, and the picture with it.
    await page.mouse.move(right.x, right.y);
    const b = await settled(page, a.pointer);
    assert.ok(b.pointer[0] > 0.04 && b.pointer[0] - a.pointer[0] > 0.1, `pointer ${b.pointer} after ${a.pointer}`);
    assert.ok(b.pointer[1] > a.pointer[1] + 0.02, `higher on the screen, higher in the plane: ${b.pointer[1]} vs ${a.pointer[1]}`);
    const atRight = await snapshot(page);
    await page.screenshot({ path: path.join(artifacts, 'droplets-right.png') });
    await waitFrames(page, 3);
    const nLeft = blockDifference(atRight, await snapshot(page), around(left));
    // Where the droplets left and where they came the picture changed; a corner did not.
    const dLeft = blockDifference(atLeft, atRight, around(left)), dRight = blockDifference(atLeft, atRight, around(right));
    const dCorner = blockDifference(atLeft, atRight, { x0: 0, y0: 0, x1: 24, y1: 24 });
    note(`pointer ${a.pointer.map((v) => v.toFixed(3))} -> ${b.pointer.map((v) => v.toFixed(3))} m; pictures differ ${dLeft.toFixed(1)} at the left (noise there ${nLeft.toFixed(2)}), ${dRight.toFixed(1)} at the right (noise ${nRight.toFixed(2)}), ${dCorner.toFixed(2)} in a corner (noise ${n.toFixed(2)})`);
    assert.ok(dLeft > 8 && dLeft > changed(dLeft, nLeft), `the droplets left the left: ${dLeft.toFixed(2)} (noise there ${nLeft.toFixed(2)})`);
    assert.ok(dRight > 8 && dRight > changed(dRight, nRight), `the droplets came to the right: ${dRight.toFixed(2)} (noise there ${nRight.toFixed(2)})`);
    assert.ok(dCorner < Math.max(2, 4 * n), `a corner stays: ${dCorner.toFixed(2)} (noise ${n.toFixed(2)})`);

    // A drag tilts the selected glass (the lager) and leaves the pointer where it was.
    await page.mouse.down();
    for (let i = 1; i <= 5; ++i) await page.mouse.move(right.x - 8 * i, right.y);
    await waitFrames(page, 4);
    const dragged = await droplets(page);
    assert.deepEqual(dragged.pointer, b.pointer, 'the pointer stays during a drag');
    assert.ok((await status(page)).tilt > 2, `the glass tilts: ${(await status(page)).tilt} degrees`);
    await page.mouse.up();
  } finally {
    await page.context().close();
  }
});

test('droplets follow a finger on the picture; the glass stays upright', async () => {
  const page = await openPage(env, { context: { hasTouch: true } });
  try {
    await page.selectOption('#drink', 'droplets');
    await page.waitForFunction(() => window.draught.droplets().droplets === true);
    const before = await settled(page);
    const cdp = await page.context().newCDPSession(page);
    const touch = (type, points) => cdp.send('Input.dispatchTouchEvent', { type, touchPoints: points.map(([x, y], id) => ({ x, y, id })) });
    const from = await canvasPoint(page, 0.25, 0.5), to = await canvasPoint(page, 0.75, 0.5);
    await touch('touchStart', [[from.x, from.y]]);
    const a = await settled(page, before.pointer);
    assert.ok(a.pointer[0] < before.pointer[0] - 0.04, `the finger at the left: pointer ${a.pointer}`);
    for (let i = 1; i <= 6; ++i) await touch('touchMove', [[from.x + ((to.x - from.x) * i) / 6, from.y]]);
    const b = await settled(page, a.pointer);
    note(`pointer ${a.pointer.map((v) => v.toFixed(3))} -> ${b.pointer.map((v) => v.toFixed(3))} m`);
    assert.ok(b.pointer[0] > a.pointer[0] + 0.1, `the finger moved right: pointer ${b.pointer} after ${a.pointer}`);
    assert.ok(Math.abs(b.pointer[1] - a.pointer[1]) < 0.005, `along a row: ${b.pointer[1]} vs ${a.pointer[1]}`);
    const st = await status(page);
    assert.equal(st.input, 'touch');
    assert.ok(st.tilt < 0.5, `the glass stays upright: ${st.tilt} degrees`);
    // The MatCap tier (where a slow phone's adaptive quality falls) draws them too: back at
    // the left, the right of the picture changes where they were.
    assert.equal(await page.evaluate(() => window.draught.setParam('render.tier', 'matcap')), '');
    await waitFrames(page, 3);
    const atRight = await snapshot(page);
    for (let i = 5; i >= 0; --i) await touch('touchMove', [[from.x + ((to.x - from.x) * i) / 6, from.y]]);
    await settled(page, b.pointer);
    const dMatCap = blockDifference(atRight, await snapshot(page), around(to));
    note(`MatCap tier: the picture at the right changed ${dMatCap.toFixed(1)} when the droplets left it`);
    assert.ok(dMatCap > 8, `the MatCap tier draws the droplets: ${dMatCap.toFixed(2)}`);
    assert.equal((await status(page)).tier, 'matcap');
    await touch('touchEnd', []);
    // Without droplets a finger tilts the glass again and there is no pointer to take.
    await page.selectOption('#drink', 'lager');
    await page.waitForFunction(() => window.draught.droplets().droplets === false);
    assert.equal(await page.evaluate(() => window.draught.api.pointer(10, 10, 160, 120, 0)), 0);
  } finally {
    await page.context().close();
  }
});

// ---- scenes of several glasses ----

// Where each object lies on the canvas, as the module picks (the reference intersector):
// per object its pixel count, centre (CSS pixels, page coordinates) and bounding box in
// canvas pixels (for snapshots).
// The grid the tests pick on, in CSS pixels: a pick is the reference intersector in wasm,
// and every 2nd pixel was 10 s of a test; a glass still covers hundreds of samples.
const pickStep = 4;
async function objectRegions(page, step = pickStep) {
  const c = await canvasCentre(page);
  const found = await page.evaluate(({ w, h, step }) => {
    const out = [];
    for (let y = step / 2; y < h; y += step)
      for (let x = step / 2; x < w; x += step) {
        const i = window.draught.pick(x, y);
        if (i < 0) continue;
        const o = (out[i] ??= { n: 0, sx: 0, sy: 0, x0: 1e9, y0: 1e9, x1: -1, y1: -1 });
        o.n++, o.sx += x, o.sy += y;
        o.x0 = Math.min(o.x0, x), o.y0 = Math.min(o.y0, y), o.x1 = Math.max(o.x1, x), o.y1 = Math.max(o.y1, y);
      }
    return out;
  }, { w: c.w, h: c.h, step });
  const backing = (await status(page)).width / c.w;  // canvas pixels per CSS pixel
  return found.map((o) => o && {
    n: o.n,
    x: c.x + o.sx / o.n, y: c.y + o.sy / o.n,
    box: { x0: Math.floor((o.x0 - step) * backing), y0: Math.floor((o.y0 - step) * backing),
           x1: Math.ceil((o.x1 + step) * backing), y1: Math.ceil((o.y1 + step) * backing) },
  });
}
const objects = (page) => page.evaluate(() => window.draught.objects());
const waitSelected = (page, i) => page.waitForFunction((i) => window.draught.objects().selected === i, i, { timeout: patience(5000) });

test('several glasses: a click, a tap and the picker select one; the panel edits it alone', async () => {
  // Three copies of the glass (the page's test hook): selection needs no scene preset.
  const page = await openPage(env, { query: 'size=240x120&scale=1&preserve', context: { hasTouch: true } });
  try {
    assert.equal(await page.isHidden('#object-row'), true, 'no picker for a single glass');
    assert.equal(await page.evaluate(() => window.draught.testRow(3)), '');
    await waitFrames(page, 2);
    const o = await objects(page);
    assert.deepEqual(o.objects.map((x) => x.name), ['glass-1', 'glass-2', 'glass-3']);
    assert.equal(o.selected, 0);
    assert.equal(await page.isVisible('#object-row'), true);
    assert.equal(await page.locator('#object option').count(), 3);
    const regions = await objectRegions(page);
    assert.equal(regions.length, 3);
    for (const r of regions) assert.ok(r && r.n > 10, 'every glass covers some of the canvas');
    assert.ok(regions[0].x < regions[1].x && regions[1].x < regions[2].x, 'side by side');
    note(`glasses at x ${regions.map((r) => r.x.toFixed(0)).join(', ')}`);

    // A click on the third glass selects it; one on the floor keeps it.
    await page.mouse.click(regions[2].x, regions[2].y);
    await waitSelected(page, 2);
    assert.equal(await page.inputValue('#object'), '2');
    assert.match((await message(page)).text, /selected glass-3/);
    const c = await canvasCentre(page);
    await page.mouse.click(c.x + 3, c.y + c.h - 3);  // the floor in front
    await waitFrames(page, 1);
    assert.equal((await objects(page)).selected, 2, 'a click on the floor keeps the selection');

    // A drag that starts on another glass tilts the selected one: no selection.
    await page.mouse.move(regions[0].x, regions[0].y);
    await page.mouse.down();
    await page.mouse.move(regions[0].x + 30, regions[0].y, { steps: 4 });
    await page.mouse.up();
    assert.equal((await objects(page)).selected, 2, 'a drag selects nothing');

    // A tap (one finger, down and up in place) selects the second.
    const cdp = await page.context().newCDPSession(page);
    const touch = (type, points) => cdp.send('Input.dispatchTouchEvent', { type, touchPoints: points.map(([x, y], id) => ({ x, y, id })) });
    await touch('touchStart', [[regions[1].x, regions[1].y]]);
    await touch('touchEnd', []);
    await waitSelected(page, 1);

    // The picker and its Next button.
    await page.selectOption('#object', '0');
    await waitSelected(page, 0);
    await page.click('#next-object');
    await waitSelected(page, 1);
    assert.match(await page.textContent('#object-heading'), /glass-2/);

    // The panel edits the selected glass alone, through objects[1].liquid.fill.
    const get = (path) => page.evaluate((p) => JSON.parse(window.draught.api.getParam(p)).value, path);
    const first = await get('objects[0].liquid.fill');
    await page.fill('#p-liquid-fill', '0.3');
    await page.dispatchEvent('#p-liquid-fill', 'change');
    await page.waitForFunction(() => JSON.parse(window.draught.api.getParam('objects[1].liquid.fill')).value === '0.3');
    assert.equal(await get('objects[0].liquid.fill'), first);
    assert.equal(await get('objects[2].liquid.fill'), first);
    assert.equal((await values(page))['liquid.fill'], '0.3', 'the panel shows the selected glass');
    await page.selectOption('#object', '0');
    await page.waitForFunction((f) => document.getElementById('p-liquid-fill').value === f, first);
    // A scene parameter has no object.
    assert.match(await page.evaluate(() => window.draught.setParam('objects[1].env.floor', 'false')), /objects\[1\]\.env\.floor/);
    // Export writes the whole scene: three objects, the second glass's own fill kept.
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#export')]);
    const exported = JSON.parse(fs.readFileSync(await download.path(), 'utf8'));
    assert.equal(exported.kind, 'scene');
    assert.equal(exported.objects.length, 3);
    assert.equal(exported.objects[1].params.liquid.fill, 0.3);
    await page.screenshot({ path: path.join(artifacts, 'three-glasses.png') });

    // Back to one glass: the picker goes.
    await page.selectOption('#drink', 'stout');
    await page.waitForFunction(() => window.draught.objects().objects.length === 1);
    assert.equal(await page.isHidden('#object-row'), true);
  } finally {
    await page.context().close();
  }
});

// Needs presets/scenes/flight.json (four glasses side by side) and the renderer drawing
// every glass (issue 9).
test('flight: a click and the picker select the second glass; a drag tilts it alone', async () => {
  const page = await openPage(env, { query: 'size=160x80&scale=1&preserve' });
  try {
    const drinks = await page.$$eval('#drink option', (o) => o.map((x) => x.value));
    assert.ok(drinks.includes('flight'), 'the flight scene (presets/scenes/flight.json) is among the presets');
    await page.selectOption('#drink', 'flight');
    await page.waitForFunction(() => window.draught.objects().objects.length === 4);
    await waitFrames(page, 3);
    const regions = await objectRegions(page);
    for (let i = 0; i < 4; ++i) assert.ok(regions[i] && regions[i].n > 10, `glass ${i} covers some of the canvas`);
    assert.equal((await objects(page)).selected, 0);

    // Selected by a click on it, and by the picker.
    await page.mouse.click(regions[1].x, regions[1].y);
    await waitSelected(page, 1);
    await page.selectOption('#object', '0');
    await waitSelected(page, 0);
    await page.selectOption('#object', '1');
    await waitSelected(page, 1);

    // A drag tilts the second glass: its liquid moves, the first glass's stays level. (The
    // drag leans it to the right, away from the first glass.)
    const a = await snapshot(page);
    await waitFrames(page, 3);
    const b = await snapshot(page);
    const [box0, box1] = [regions[0].box, regions[1].box];
    const n0 = blockDifference(a, b, box0), n1 = blockDifference(a, b, box1);
    await page.mouse.move(regions[1].x, regions[1].y);
    await page.mouse.down();
    await page.mouse.move(regions[1].x + 30, regions[1].y, { steps: 4 });
    await waitFrames(page, 6);
    const tilted = await snapshot(page);
    await page.mouse.up();
    const d0 = blockDifference(b, tilted, box0), d1 = blockDifference(b, tilted, box1);
    note(`second glass ${d1.toFixed(1)} (noise ${n1.toFixed(2)}), first ${d0.toFixed(1)} (noise ${n0.toFixed(2)})`);
    await page.screenshot({ path: path.join(artifacts, 'flight-tilted.png') });
    assert.equal((await objects(page)).selected, 1, 'the drag kept the selection');
    assert.ok(d1 > changed(d1, n1), `the second glass changed: ${d1.toFixed(2)} (noise ${n1.toFixed(2)})`);
    assert.ok(d1 > 3 * Math.max(d0, n0, 0.5), `the second glass changed much more than the first: ${d1.toFixed(2)} vs ${d0.toFixed(2)}`);

    // Scene reflections in WebGL2 (env.reflections: each glass's panorama drawn into a
    // half-float array texture): the stout's glass mirrors the hefeweizen beside it, so
    // its box changes well above its own motion, and the page keeps drawing, no error.
    const box2 = regions[2].box;
    const r0 = await snapshot(page);
    await waitFrames(page, 3);
    const r1 = await snapshot(page);
    const nr = blockDifference(r0, r1, box2);
    assert.equal(await page.evaluate(() => window.draught.api.setParam('env.reflections', 'true')), '');
    await waitFrames(page, 4);
    const mirrored = await snapshot(page);
    const dr = blockDifference(r1, mirrored, box2);
    note(`reflections: the stout's glass ${dr.toFixed(2)} (noise ${nr.toFixed(2)})`);
    await page.screenshot({ path: path.join(artifacts, 'flight-reflections.png') });
    assert.ok(dr > changed(dr, nr), `the stout's glass mirrors its neighbours: ${dr.toFixed(2)} (noise ${nr.toFixed(2)})`);
    assert.deepEqual(page.draughtLog.filter((l) => l.startsWith('pageerror')), []);
  } finally {
    await page.context().close();
  }
});

// ---- hostile input and a lost context (issue 15, items 2, 3 and 17) ----

// The panel's own path for a value: type it into the row's field and commit it.
async function typeValue(page, path, text) {
  await page.evaluate(({ path, text }) => {
    const el = document.getElementById('p-' + path.replace(/\./g, '-'));
    el.value = text;
    el.dispatchEvent(new Event('change'));
  }, { path, text });
}
const pageErrors = (page) => page.draughtLog.filter((l) => l.startsWith('pageerror'));
const waitMessage = (page, re) => page.waitForFunction((src) => new RegExp(src).test(document.getElementById('message').textContent),
                                                      re.source, { timeout: patience(20000) });
// A normal edit after the hostile input still works: the value is applied and the picture
// changes by more than its own motion.
async function editStillWorks(page, path, text) {
  const { before, noise: n } = await noise(page);
  await typeValue(page, path, text);
  await page.waitForFunction(({ path, text }) => JSON.parse(window.draught.api.values())[path] === text, { path, text });
  await waitFrames(page, 4);
  const d = difference(before, await snapshot(page));
  note(`later edit ${d.toFixed(1)}, noise ${n.toFixed(2)}`);
  assert.ok(d > changed(d, n), `${path}=${text} changed the picture: difference ${d.toFixed(2)} (noise ${n.toFixed(2)})`);
}

// The hostile-input tests share one page, in this order (each asserts that the page keeps
// working, so the next starts from what the last left): the multi-byte echoes first, whose
// drink pickers bring back the default lager it compares with; each test's later edit
// changes a value the one before left. The last closes it.
let inputs;
const inputPage = async () => (inputs ??= await openPage(env));
async function closeInputPage() {
  if (inputs) await inputs.context().close();
  inputs = null;
}

test('multi-byte echoes: errors that shorten a value of UTF-8 characters are shown whole; the page keeps working', async () => {
  const page = await inputPage();
  const v0 = await values(page);
  // 'a' then 3-byte characters: the 60-byte cap of an echo falls inside one.
  const value = 'a' + '€'.repeat(100);
  const bad = JSON.stringify({ draught_preset: 1, kind: 'drink', name: 'euro', params: { liquid: { fill: value } } });
  await page.setInputFiles('#load', { name: 'euro.json', mimeType: 'application/json', buffer: Buffer.from(bad) });
  await waitMessage(page, /euro\.json/);
  let m = await message(page);
  assert.ok(m.error);
  assert.match(m.text, /liquid\.fill/);
  assert.match(m.text, /got "a€+\.\.\.$/, `the echo ends on a whole character: ${m.text}`);
  assert.ok(!m.text.includes('\uFFFD'), 'no broken character');

  // Bytes that are no UTF-8 at all: the browser reads the file as UTF-8 with U+FFFD in their
  // place, so the module only ever sees valid text.
  const broken = Buffer.concat([Buffer.from('{"draught_preset": 1, "kind": "drink", "name": "'), Buffer.from([0xff, 0xfe, 0xe2, 0x82]),
                                Buffer.from('"}')]);
  await page.setInputFiles('#load', { name: 'bytes.json', mimeType: 'application/json', buffer: broken });
  await waitMessage(page, /bytes\.json/);
  assert.match((await message(page)).text, /^loaded drink "\uFFFD+" from bytes\.json$/);
  await page.selectOption('#drink', 'stout');  // then lager again (the picker's own value fires no change): v0's state
  await page.selectOption('#drink', 'lager');

  // The same through a panel field.
  await typeValue(page, 'liquid.haze_color', value);
  await waitMessage(page, /haze_color/);
  m = await message(page);
  assert.ok(m.error);
  assert.match(m.text, /^field 'liquid\.haze_color': expected .*, got "a€{19}\.\.\."$/);
  assert.ok(!m.text.includes('\uFFFD'), 'no broken character');
  assert.deepEqual(await values(page), v0, 'nothing applied');

  await editStillWorks(page, 'liquid.srm', '40');
  assert.deepEqual(pageErrors(page), []);
});

test('large input: a 1.4 MB description loads, a 17 MiB file is refused naming the limit, the page keeps working', async () => {
  const page = await inputPage();
  const big = JSON.stringify({ draught_preset: 1, kind: 'drink', name: 'long-story', description: 'a'.repeat(1_400_000),
                               params: { liquid: { srm: 14 } } });
  await page.setInputFiles('#load', { name: 'long-story.json', mimeType: 'application/json', buffer: Buffer.from(big) });
  await waitMessage(page, /long-story/);
  let m = await message(page);
  assert.ok(!m.error, `loaded, not refused: ${m.text.slice(0, 200)}`);
  assert.match(m.text, /loaded drink "long-story"/);
  assert.equal((await values(page))['liquid.srm'], '14');

  // Over the CLI's limit for a text input: refused before it reaches the module, saying so.
  const huge = Buffer.alloc(17 * 1024 * 1024, 0x20);
  huge.write('{"draught_preset": 1, "kind": "drink", "name": "huge", "params": {}}');
  await page.setInputFiles('#load', { name: 'huge.json', mimeType: 'application/json', buffer: huge });
  await waitMessage(page, /huge\.json/);
  m = await message(page);
  assert.ok(m.error);
  assert.match(m.text, /^huge\.json: 17\.0 MiB, larger than the limit of 16 MiB for a preset file/);

  await editStillWorks(page, 'liquid.fill', '0.3');
  assert.deepEqual(pageErrors(page), []);
});

test('large input: a 3.5 MB paste into a panel field gets a message naming the field; later edits work', async () => {
  const page = await inputPage();
  const v0 = await values(page);
  const pasted = 'x'.repeat(3_500_000);
  await typeValue(page, 'liquid.haze_color', pasted);
  await waitMessage(page, /haze_color/);
  const m = await message(page);
  assert.ok(m.error);
  assert.match(m.text, /^field 'liquid\.haze_color': 3500000 bytes of text, longer than the limit of 4096 bytes for a value/);
  assert.match(await page.textContent('.param[data-path="liquid.haze_color"] .err'), /limit of 4096 bytes/);
  assert.deepEqual(await values(page), v0, 'nothing applied');

  // The module itself takes megabytes through the heap (no stack overrun): a short error,
  // and every later call works.
  const direct = await page.evaluate((n) => window.draught.api.setParam('liquid.fill', '9'.repeat(n)), 3_500_000);
  assert.match(direct, /^field 'liquid\.fill': expected .*, got "9{60}\.\.\."$/);
  assert.deepEqual(await values(page), v0);

  await editStillWorks(page, 'liquid.srm', '2');  // (the large description's drink has 14)
  assert.deepEqual(pageErrors(page), []);
});

test('deep input: a description nested 100,000 levels gets a clear message; the page keeps working', async () => {
  const page = await inputPage();
  try {
    const v0 = await values(page);
    const depth = 100_000;
    const deep = `{"draught_preset": 1, "kind": "drink", "name": "deep", "description": ${'['.repeat(depth)}${']'.repeat(depth)}}`;
    await page.setInputFiles('#load', { name: 'deep.json', mimeType: 'application/json', buffer: Buffer.from(deep) });
    await waitMessage(page, /deep\.json/);
    const m = await message(page);
    assert.ok(m.error);
    assert.match(m.text, /deep\.json/);
    assert.match(m.text, /description/);
    assert.match(m.text, /nested more than 256 levels deep/);
    assert.ok(m.text.length < 400, `a short message (${m.text.length} characters)`);
    assert.deepEqual(await values(page), v0, 'nothing applied');
    await editStillWorks(page, 'liquid.srm', '40');  // (the paste's test left 2)
    assert.deepEqual(pageErrors(page), []);
  } finally {
    await closeInputPage();
  }
});

test('fps readout: right when frames take longer than a second', async () => {
  const page = await openPage(env);
  try {
    // Every animation frame 1.5 s late: the module draws about 0.65 frames a second.
    await page.evaluate(() => {
      const raf = window.requestAnimationFrame.bind(window);
      window.requestAnimationFrame = (cb) => setTimeout(() => raf(cb), 1500);
    });
    await page.waitForTimeout(4500);  // the readout's window holds only slow frames
    const fpsShown = () => page.evaluate(() => +/([\d.]+) fps/.exec(document.getElementById('quality').textContent)[1]);
    const s0 = await status(page);
    const shown = [];
    for (let i = 0; i < 12; ++i) {
      await page.waitForTimeout(500);
      shown.push(await fpsShown());
    }
    const s1 = await status(page);
    const truth = (s1.frames - s0.frames) / (s1.time - s0.time);
    note(`measured ${truth.toFixed(2)} fps, shown ${shown.join(' ')}`);
    assert.ok(truth > 0.3 && truth < 0.9, `frames are slower than one a second (${truth.toFixed(2)} fps)`);
    for (const f of shown) assert.ok(Math.abs(f - truth) <= 0.25 * truth, `shown ${f} fps, measured ${truth.toFixed(2)}`);
  } finally {
    await page.context().close();
  }
});

test('a lost WebGL context is restored: programs and textures rebuilt, drawing again, state kept', async () => {
  const page = await openPage(env, { query: 'size=160x80&scale=1&preserve' });
  try {
    // State to keep: a drink, an edited value, three glasses with the third selected, a tilt.
    await page.selectOption('#drink', 'stout');
    await page.waitForFunction(() => window.draught.status().drink === 'stout');
    assert.equal(await page.evaluate(() => window.draught.testRow(3)), '');
    assert.equal(await page.evaluate(() => window.draught.selectObject(2)), '');
    await typeValue(page, 'liquid.fill', '0.6');
    await page.waitForFunction(() => JSON.parse(window.draught.api.values())['liquid.fill'] === '0.6');
    const c = await canvasCentre(page);
    await page.mouse.move(c.x, c.y);
    await page.mouse.down();  // held through the loss: the glass stays tilted
    await page.mouse.move(c.x + 30, c.y, { steps: 4 });
    await page.waitForFunction(() => window.draught.status().tilt > 10, null, { timeout: patience(10000) });
    await waitFrames(page, 3);
    const before = { values: await values(page), objects: await objects(page), status: await status(page) };
    const picture = await snapshot(page);

    await page.evaluate(() => {
      window.loseContextExt = document.getElementById('canvas').getContext('webgl2').getExtension('WEBGL_lose_context');
      window.loseContextExt.loseContext();
    });
    await page.waitForFunction(() => window.draught.status().context_lost === true, null, { timeout: patience(10000) });
    assert.match((await message(page)).text, /WebGL context was lost/);
    const f0 = (await status(page)).frames;
    await page.waitForTimeout(500);
    assert.ok((await status(page)).frames <= f0 + 1, 'no frames while the context is lost');

    await page.evaluate(() => window.loseContextExt.restoreContext());
    await page.waitForFunction((f) => !window.draught.status().context_lost && window.draught.frames() >= f + 3, f0,
                               { timeout: patience(30000), polling: 50 });
    const after = await status(page);
    assert.equal(after.error, '');
    assert.equal(after.context_restores, 1);
    assert.match((await message(page)).text, /restored/);
    const img = await snapshot(page);
    const st = stats(img);
    assert.ok(st.max - st.min > 60, `a picture again, not a blank canvas (min ${st.min}, max ${st.max})`);
    const d = difference(picture, img);
    note(`after the restore: difference ${d.toFixed(2)} from before the loss, tilt ${before.status.tilt.toFixed(1)} -> ${after.tilt.toFixed(1)} degrees`);
    assert.ok(d < 8, `the same scene drawn again: difference ${d.toFixed(2)}`);
    assert.deepEqual(await values(page), before.values, 'parameter values kept');
    assert.deepEqual(await objects(page), before.objects, 'objects and selection kept');
    assert.equal(after.drink, 'stout');
    assert.ok(Math.abs(after.tilt - before.status.tilt) < 2, `tilt kept: ${before.status.tilt.toFixed(1)} -> ${after.tilt.toFixed(1)} degrees`);
    await page.mouse.up();
    await page.waitForFunction(() => window.draught.status().tilt < 0.5, null, { timeout: patience(10000) });  // upright again

    // And it keeps working: an edit changes the picture.
    await editStillWorks(page, 'env.sweep_color', '0.8,0.2,0.2');  // the whole backdrop, not one glass of three
    assert.deepEqual(pageErrors(page), []);
  } finally {
    await page.context().close();
  }
});

// ---- the screen: the camera and a video file seen through the drink ----

// The canvas pixels (x, y) where the drink is the first thing seen (the module's own picking),
// on the pick grid, a few pixels in from the glass's edges.
async function drinkPixels(page) {
  return page.evaluate((step) => {
    const c = document.getElementById('canvas').getBoundingClientRect();
    const out = [];
    for (let y = 4; y < c.height - 4; y += step)
      for (let x = 4; x < c.width - 4; x += step) {
        let inside = true;
        for (const [dx, dy] of [[0, 0], [-4, 0], [4, 0], [0, -4], [0, 4]]) inside = inside && window.draught.pick(x + dx, y + dy) >= 0;
        if (inside) out.push([x, y]);
      }
    return out;
  }, pickStep);
}
// Mean absolute difference per channel over those pixels.
function differenceAt(a, b, pixels) {
  let sum = 0;
  for (const [x, y] of pixels)
    for (let c = 0; c < 3; ++c) sum += Math.abs(a.data[4 * (y * a.width + x) + c] - b.data[4 * (y * a.width + x) + c]);
  return sum / Math.max(1, 3 * pixels.length);
}
const uploads = (page) => page.evaluate(() => window.draught.screen.uploads());
async function waitUploads(page, n) {
  const u0 = await uploads(page);
  await page.waitForFunction((u) => window.draught.screen.uploads() >= u, u0 + n, { timeout: patience(30000), polling: 50 });
}

test('the camera on the screen: its moving picture is seen through the drink', async () => {
  const page = await openPage(env);
  try {
    await page.evaluate(() => window.draught.setParam('bubbles.max_bubbles', '0'));  // nothing else moves
    await waitFrames(page, 3);
    const plain = await snapshot(page);
    const inDrink = await drinkPixels(page);
    assert.ok(inDrink.length > 100, `the drink covers ${inDrink.length} grid pixels`);
    const still = differenceAt(plain, (await waitFrames(page, 3), await snapshot(page)), inDrink);

    assert.equal(await page.evaluate(() => window.draught.screen.useCamera()), '');
    assert.match((await message(page)).text, /the screen shows the camera \(\d+ x \d+\)/);
    const v = await values(page);
    assert.equal(v['screen.mode'], 'card', 'the screen came on as a card');
    assert.equal(v['screen.source'], '', 'fed by the page');
    assert.equal(await page.evaluate(() => window.draught.setParam('screen.mode', 'background')), '');
    await waitUploads(page, 5);
    await waitFrames(page, 2);
    const a = await snapshot(page);
    // The clip holds some of its frames still, and a loaded machine may see a few camera
    // frames repeated: up to five looks, four uploads apart, for the picture to move.
    let moved = 0;
    for (let look = 0; look < 5 && moved <= Math.max(1.0, 4 * still); ++look) {
      await waitUploads(page, 4);
      await waitFrames(page, 2);
      moved = Math.max(moved, differenceAt(a, await snapshot(page), inDrink));
    }
    const st = await status(page);
    assert.ok(st.screen_frames >= 9, `frames uploaded: ${st.screen_frames}`);
    assert.equal(st.screen_size, '320x180', 'the fake camera plays the test clip');
    const versusPlain = differenceAt(plain, a, inDrink);
    note(`camera ${st.screen_size}: through the drink it moved ${moved.toFixed(2)} between frames (a still scene ${still.toFixed(2)}); differs ${versusPlain.toFixed(1)} from the studio`);
    assert.ok(versusPlain > 10, `the camera's picture is behind the drink: ${versusPlain.toFixed(1)}`);
    assert.ok(moved > Math.max(1.0, 4 * still), `the picture moves through the drink: ${moved.toFixed(2)} (still: ${still.toFixed(2)})`);
    await page.screenshot({ path: path.join(artifacts, 'screen-camera.png') });
    assert.deepEqual(pageErrors(page), []);
  } finally {
    await page.context().close();
  }
});

test('a video file on the screen plays behind the glass; a file that is no video changes nothing', async () => {
  const clip = path.join(artifacts, 'screen-test.webm');
  const made = spawnSync('ffmpeg', ['-nostdin', '-y', '-loglevel', 'error', '-f', 'lavfi', '-i',
    'testsrc2=size=160x90:rate=25:duration=3,hue=H=2*PI*t', '-c:v', 'libvpx', '-b:v', '400k', '-pix_fmt', 'yuv420p', clip]);
  assert.equal(made.status, 0, `ffmpeg made the test clip: ${made.stderr}`);
  const page = await openPage(env);
  try {
    await page.evaluate(() => window.draught.setParam('bubbles.max_bubbles', '0'));
    const inDrink = await drinkPixels(page);
    await page.setInputFiles('#screen-file', clip);
    await page.waitForFunction(() => /the screen plays screen-test\.webm/.test(document.getElementById('message').textContent), null, { timeout: patience(30000) });
    await waitUploads(page, 5);
    await waitFrames(page, 2);
    const a = await snapshot(page);
    await waitUploads(page, 5);
    await waitFrames(page, 2);
    const b = await snapshot(page);
    const moved = differenceAt(a, b, inDrink);
    note(`video through the drink moved ${moved.toFixed(2)}`);
    assert.ok(moved > 1.0, `the video moves behind the glass: ${moved.toFixed(2)}`);
    assert.equal((await status(page)).screen_size, '160x90');

    const before = await uploads(page);
    await page.setInputFiles('#screen-file', { name: 'notes.webm', mimeType: 'video/webm', buffer: Buffer.from('not a video at all') });
    await page.waitForFunction(() => /notes\.webm/.test(document.getElementById('message').textContent), null, { timeout: patience(30000) });
    const m = await message(page);
    assert.ok(m.error, 'shown as an error');
    assert.match(m.text, /notes\.webm: .*the screen keeps what it showed/);
    await waitUploads(page, 3);  // the clip before plays on
    assert.ok((await uploads(page)) > before);
    assert.equal(await page.evaluate(() => window.draught.screen.source()), 'screen-test.webm');
    assert.deepEqual(pageErrors(page), []);
  } finally {
    await page.context().close();
  }
});

test('the shipped screen scene plays its clip through the browser', async () => {
  const page = await openPage(env);
  try {
    await page.selectOption('#drink', 'screen-lager');
    await page.waitForFunction(() => window.draught.status().screen_file === '/presets/videos/draught-loop.mp4', null, { timeout: patience(30000) });
    await page.waitForFunction(() => window.draught.screen.uploads() >= 5, null, { timeout: patience(30000), polling: 50 });
    const st = await status(page);
    assert.equal(st.screen_size, '480x270');
    assert.equal((await values(page))['screen.source'], 'draught-loop', 'the preset keeps its source');
    assert.match((await message(page)).text, /the screen plays draught-loop\.mp4/);
    await waitFrames(page, 2);
    await page.screenshot({ path: path.join(artifacts, 'screen-lager.png') });
    // Back to a drink without a screen: the clip stops.
    await page.selectOption('#drink', 'lager');
    await page.waitForFunction(() => window.draught.status().screen_file === '', null, { timeout: patience(10000) });
    await page.waitForTimeout(600);
    const u = await uploads(page);
    await page.waitForTimeout(600);
    assert.equal(await uploads(page), u, 'no uploads once the screen is gone');
    assert.deepEqual(pageErrors(page), []);
  } finally {
    await page.context().close();
  }
});

// ---- runner ----
const only = process.argv[2];
const t0 = Date.now();
let passed = 0, failed = 0;
const failures = [];  // repeated at the end, where a truncated log's tail still shows them
try {
  env = await start();
  for (const t of tests) {
    if (only && !t.name.includes(only)) continue;
    const t1 = Date.now();
    notes.length = 0;
    try {
      await t.fn();
      ++passed;
      console.log(`ok   ${t.name} (${((Date.now() - t1) / 1000).toFixed(1)} s${notes.length ? '; ' + notes.join(', ') : ''})`);
    } catch (e) {
      ++failed;
      const why = String(e && e.stack || e).split('\n').slice(0, 6).join('\n     ');
      console.log(`FAIL ${t.name} (${((Date.now() - t1) / 1000).toFixed(1)} s)\n     ${why}`);
      failures.push(`${t.name}: ${why.split('\n')[0]}`);
      if (desk && desk.draughtLog.length) console.log('     page log: ' + desk.draughtLog.slice(-5).join(' | '));
    }
  }
} catch (e) {
  ++failed;
  console.log(`FAIL setting up the browser: ${e && e.stack || e}`);
  failures.push(`setting up the browser: ${String(e && e.message || e)}`);
} finally {
  if (env) await env.close();
}
console.log(`${((Date.now() - t0) / 1000).toFixed(1)} s; pictures in ${artifacts}`);
for (const f of failures) console.log(`failed: ${f}`);
console.log(`web tests: ${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
