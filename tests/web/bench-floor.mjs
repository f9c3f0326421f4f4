// A benchmark, not a test (nothing is asserted, CTest does not run it): the floor under the
// web page's frame rate in headless chromium on SwiftShader (the tests' browser, lib.mjs).
// A bare WebGL2 canvas of W x H CSS pixels at devicePixelRatio 1 (as bench.mjs pins the
// page) draws `passes` full-screen triangles a frame with a shader that does almost
// nothing (one texture read, one write), for passes 0 (a clear only), 1, 3, 8, 16 and 32, each frame
// requested by requestAnimationFrame as the page does. What is left of a frame's time for
// draught's own work is the difference. `node bench-floor.mjs [runs] [seconds] [WxH]`
// after scripts/build-web.sh (lib.mjs serves its folder; the page is written in place).
import { benchArgs, framesPerSecond, median, start } from './lib.mjs';

const { runs, seconds, size } = benchArgs('bench-floor.mjs', { runs: 3, seconds: 4 });
const [w, h] = size.split('x').map(Number);

const page_html = (passes) => `<!doctype html><html><body style="margin:0">
<canvas id="c" width="${w}" height="${h}" style="width:${w}px;height:${h}px"></canvas>
<script>
const gl = document.getElementById('c').getContext('webgl2', { antialias: false });
const sh = (type, src) => { const s = gl.createShader(type); gl.shaderSource(s, src); gl.compileShader(s); return s; };
const prog = gl.createProgram();
gl.attachShader(prog, sh(gl.VERTEX_SHADER, '#version 300 es\\nvoid main() { vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2); gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0); }'));
gl.attachShader(prog, sh(gl.FRAGMENT_SHADER, '#version 300 es\\nprecision highp float; uniform sampler2D t; out vec4 o; void main() { o = texelFetch(t, ivec2(gl_FragCoord.xy) & 7, 0) * 0.5 + 0.25; }'));
gl.linkProgram(prog);
const tex = gl.createTexture();
gl.bindTexture(gl.TEXTURE_2D, tex);
gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, 8, 8, 0, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(256).fill(128));
gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
gl.useProgram(prog);
gl.bindVertexArray(gl.createVertexArray());
let frames = 0;
window.draught = { frames: () => frames };
const frame = () => {
  gl.clearColor(0.1, 0.2, 0.3, 1.0);
  gl.clear(gl.COLOR_BUFFER_BIT);
  for (let i = 0; i < ${passes}; ++i) gl.drawArrays(gl.TRIANGLES, 0, 3);
  ++frames;
  requestAnimationFrame(frame);
};
requestAnimationFrame(frame);
</script></body></html>`;

const env = await start();
try {
  console.log(`chromium ${env.browser.version()}, SwiftShader (lib.mjs flags); ${size} at devicePixelRatio 1; ${runs} runs of ${seconds} s after 2 s`);
  for (const passes of [0, 1, 3, 8, 16, 32]) {
    const context = await env.browser.newContext({ viewport: { width: w + 40, height: h + 40 }, deviceScaleFactor: 1 });
    const page = await context.newPage();
    try {
      await page.goto(env.base);  // (a page of the server's origin, then written over)
      await page.setContent(page_html(passes));
      await page.waitForTimeout(2000);
      const fps = await framesPerSecond(page, runs, seconds);  // (the page counts window.draught.frames)
      console.log(`${passes} full-screen pass${passes === 1 ? '' : 'es'}: fps ${fps.map((f) => f.toFixed(1)).join(' ')}; median ${median(fps).toFixed(1)} (${(1000 / median(fps)).toFixed(1)} ms a frame)`);
    } finally {
      await context.close();
    }
  }
} finally {
  await env.close();
}
