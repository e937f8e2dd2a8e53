// SPDX-License-Identifier: MIT
// The racer's page (make web's out/web) in a real browser: Debian's chromium-headless-shell, driven
// by puppeteer-core, WebGL2 on SwiftShader through ANGLE. For each technique the page runs, a few
// frames of the chase camera at a fixed step are read back (the page's hook: the engine's frame)
// and compared with the native GLES driver's frame of the same technique, size, step and content
// (`racer --headless --backend gles`, EGL on Mesa llvmpipe), under the thresholds of
// engine/render/docs/gles.md "In a browser"; the canvas must show exactly that frame; so must
// SSAM's frame of the pan camera, into the forest, with its light shafts. Then the
// technique switch is clicked while paused and the frame must change, and a2c, which the GLES
// driver refuses where the page asks for the closest-sample depth, must be named in the switch. Any console error, WebGL error or uncaught page
// exception fails the test. out/web missing fails it too, saying to run `make web`.
//   node racer_page_test.mjs --out OUT_WEB --racer RACER --work DIR
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { launchChromium, parseArgs } from './browser.mjs';
import { serve } from './serve.mjs';

const args = parseArgs(process.argv.slice(2));
const fail = (message) => { console.error(`racer_page_test: FAIL: ${message}`); process.exit(1); };

for (const file of ['index.html', 'racer.js', 'racer.wasm', 'racer.data', 'content/models/car.glb'])
  if (!existsSync(join(args.out, file)))
    fail(`${join(args.out, file)} is missing: build the page first with \`make web\` ` +
         '(or configure with -DSSAM_WEB_TESTS=OFF to leave the browser suite out)');
const chromium = await launchChromium(fail);

// The frame the test renders: small, a few fixed steps of the chase camera.
const frame = { width: 320, height: 180, frames: 3, dt: 0.0333333 };
// Compared techniques, and their thresholds (engine/render/docs/gles.md "In a browser": measured
// with this Chromium and Mesa, then given headroom): the mean absolute difference over every
// channel in 8-bit codes, and the share of pixels with any channel more than `bound` apart.
const bound = 48;
// a2c's 4x depth keeps any one sample on both sides (`--msaa-depth any`, the page's default).
const techniques = {
  'ssam': { mean: 3.4, over: 0.0065 },
  'ssam-plus': { mean: 0.6, over: 0.0008 },
  'alpha-test': { mean: 0.55, over: 0.0016 },
  'hashed': { mean: 0.65, over: 0.0024 },
  'hashed+taa': { mean: 3.4, over: 0.02 },
  'a2c': { mean: 2.9, over: 0.01, native: ['--msaa-depth', 'any'] },
};
// What the GLES driver refuses when the page asks for the closest-sample depth (?msaa-depth=closest).
const refused = 'a2c';
// The pan frame is mostly foliage, where the two rasterizers differ most.
const panLimit = { mean: 6.5, over: 0.0026 };
// How much farther the pan frame must be from the native frame without light shafts than from
// the one with them (8-bit codes, mean over RGB).
const shaftsShow = 1.0;

mkdirSync(args.work, { recursive: true });
const started = Date.now();
const server = await serve(args.out, 0);
const base = `http://127.0.0.1:${server.address().port}/`;
const problems = [];
let failed = false;
const check = (ok, message) => {
  console.log(`racer_page_test: ${ok ? 'ok' : 'FAIL'}: ${message}`);
  if (!ok) failed = true;
};

async function openPage(query) {
  const page = await chromium.newPage();
  page.on('console', (m) => {
    if (m.type() === 'error' || /INVALID_|GL error/.test(m.text())) problems.push(`console: ${m.text()}`);
  });
  page.on('pageerror', (e) => problems.push(`uncaught: ${e.message}`));
  await page.goto(base + '?' + new URLSearchParams(query), { waitUntil: 'load' });
  await page.waitForFunction('racerPage.ready || racerPage.error', { timeout: 120000 });
  return page;
}

// The engine's frame (the hook) and what the canvas shows, as RGBA8 arrays, rows from the top.
async function readFrame(page) {
  return page.evaluate(() => {
    const canvas = document.getElementById('canvas');
    const { width, height } = canvas;
    const at = Module.ccall('racer_page_read_frame', 'number', [], []);
    const engine = Array.from(Module.HEAPU8.subarray(at, at + width * height * 4));
    const copy = new OffscreenCanvas(width, height).getContext('2d');
    copy.drawImage(canvas, 0, 0);
    const shown = Array.from(copy.getImageData(0, 0, width, height).data);
    return { width, height, engine, shown };
  });
}

// The native PNG's RGBA8, decoded by the browser without any colour conversion.
async function decodePng(page, path) {
  const bytes = Array.from(readFileSync(path));
  return page.evaluate(async (data) => {
    const bitmap = await createImageBitmap(new Blob([new Uint8Array(data)], { type: 'image/png' }),
                                           { colorSpaceConversion: 'none', premultiplyAlpha: 'none' });
    const context = new OffscreenCanvas(bitmap.width, bitmap.height).getContext('2d');
    context.drawImage(bitmap, 0, 0);
    return Array.from(context.getImageData(0, 0, bitmap.width, bitmap.height).data);
  }, bytes);
}

// The browser's frame as a PNG beside the native one in the work folder (what a failure shows).
async function writePng(page, rgba, width, height, path) {
  const base64 = await page.evaluate(async (data, w, h) => {
    const canvas = new OffscreenCanvas(w, h);
    canvas.getContext('2d').putImageData(new ImageData(new Uint8ClampedArray(data), w, h), 0, 0);
    const bytes = new Uint8Array(await (await canvas.convertToBlob({ type: 'image/png' })).arrayBuffer());
    let text = '';
    for (const b of bytes) text += String.fromCharCode(b);
    return btoa(text);
  }, rgba, width, height);
  writeFileSync(path, Buffer.from(base64, 'base64'));
}

function difference(a, b) {
  let sum = 0, over = 0;
  for (let p = 0; p < a.length; p += 4) {
    let worst = 0;
    for (let c = 0; c < 3; ++c) {
      const d = Math.abs(a[p + c] - b[p + c]);
      sum += d;
      worst = Math.max(worst, d);
    }
    if (worst > bound) ++over;
  }
  return { mean: sum / (a.length / 4 * 3), over: over / (a.length / 4) };
}

// The native GLES driver's frame of `technique` (the test's size, steps and content) into `path`.
function nativeFrame(technique, path, extra = []) {
  execFileSync(args.racer, ['--headless', '--backend', 'gles', '--technique', technique, '--size',
                            `${frame.width}x${frame.height}`, '--frames', String(frame.frames), '--fixed-dt',
                            String(frame.dt), '--content', join(args.out, 'content'), ...extra, '--capture', path],
               { stdio: ['ignore', 'ignore', 'inherit'] });
}

try {
  for (const [technique, limit] of Object.entries(techniques)) {
    const native = join(args.work, `native_${technique.replace('+', '_')}.png`);
    nativeFrame(technique, native, limit.native);
    const page = await openPage({ technique, frames: frame.frames, dt: frame.dt,
                                  size: `${frame.width}x${frame.height}`, hud: 0 });
    await page.waitForFunction('racerPage.framesDone || racerPage.error', { timeout: 120000 });
    const error = await page.evaluate('racerPage.error');
    if (error) {
      check(false, `${technique}: the page failed: ${error}`);
      await page.close();
      continue;
    }
    const web = await readFrame(page);
    await writePng(page, web.engine, web.width, web.height, native.replace('native_', 'web_'));
    const d = difference(web.engine, await decodePng(page, native));
    check(d.mean <= limit.mean && d.over <= limit.over,
          `${technique}: against the native GLES frame mean |diff| ${d.mean.toFixed(3)} (<= ${limit.mean}), ` +
          `${(100 * d.over).toFixed(3)}% of pixels over ${bound} (<= ${100 * limit.over}%)`);
    const shown = difference(web.engine, web.shown);
    check(shown.mean === 0, `${technique}: the canvas shows the engine's frame (mean |diff| ${shown.mean})`);
    await page.close();
  }

  // The pan camera (?camera=pan), into the forest toward the sun, where the light shafts show:
  // the page's frame against the native one under `panLimit`, and farther from the native frame
  // without shafts by `shaftsShow` (the shafts' own light, which WebGL2 once left out).
  {
    const native = join(args.work, 'native_pan.png');
    const shaftless = join(args.work, 'native_pan_no_shafts.png');
    nativeFrame('ssam', native, ['--camera', 'pan']);
    nativeFrame('ssam', shaftless, ['--camera', 'pan', '--no-lightshafts']);
    const page = await openPage({ technique: 'ssam', frames: frame.frames, dt: frame.dt,
                                  size: `${frame.width}x${frame.height}`, hud: 0, camera: 'pan' });
    await page.waitForFunction('racerPage.framesDone || racerPage.error', { timeout: 120000 });
    const web = await readFrame(page);
    await writePng(page, web.engine, web.width, web.height, join(args.work, 'web_pan.png'));
    const d = difference(web.engine, await decodePng(page, native));
    check(d.mean <= panLimit.mean && d.over <= panLimit.over,
          `ssam, pan camera: against the native GLES frame mean |diff| ${d.mean.toFixed(3)} (<= ${panLimit.mean}), ` +
          `${(100 * d.over).toFixed(3)}% of pixels over ${bound} (<= ${100 * panLimit.over}%)`);
    const without = difference(web.engine, await decodePng(page, shaftless));
    check(without.mean >= d.mean + shaftsShow,
          `ssam, pan camera: the light shafts show (mean |diff| ${without.mean.toFixed(3)} against the native ` +
          `frame without them, >= ${d.mean.toFixed(3)} + ${shaftsShow})`);
    await page.close();
  }

  // The switch: alpha test running, paused (P), then SSAM chosen; the frame must change and then
  // hold still (paused: only the technique differs). Then a2c, which the GLES driver refuses
  // when the page asks for the closest-sample depth resolve ([Hathaway 2010] §3.5.1).
  const page = await openPage({ technique: 'alpha-test', dt: frame.dt, size: `${frame.width}x${frame.height}`,
                                hud: 0, 'msaa-depth': 'closest' });
  const framesAfter = async (n) => {
    const now = await page.evaluate(() => Module.ccall('racer_page_frames', 'number', [], []));
    await page.waitForFunction((until) => Module.ccall('racer_page_frames', 'number', [], []) >= until,
                               { timeout: 60000 }, now + n);
  };
  await framesAfter(3);
  await page.focus('#canvas');
  await page.keyboard.press('KeyP');
  await framesAfter(2);
  const before = (await readFrame(page)).engine;
  await page.select('#technique', 'ssam');
  await framesAfter(2);
  const after = (await readFrame(page)).engine;
  await framesAfter(2);
  const again = (await readFrame(page)).engine;
  const changed = difference(before, after), held = difference(after, again);
  check(changed.mean > 0.5 && held.mean === 0,
        `switch alpha-test -> ssam while paused changes the frame (mean |diff| ${changed.mean.toFixed(3)}) ` +
        `and it then holds (${held.mean})`);
  await page.select('#technique', refused);
  await page.waitForFunction((name) => document.querySelector(`#technique option[value="${name}"]`).disabled,
                             { timeout: 30000 }, refused);
  const option = await page.$eval(`#technique option[value="${refused}"]`,
                                  (o) => ({ disabled: o.disabled, text: o.textContent, why: o.title }));
  const status = await page.$eval('#status', (s) => s.textContent);
  const current = await page.$eval('#technique', (s) => s.value);
  check(option.disabled && /unavailable/.test(option.text) && option.why.length > 0 && status.includes(option.why) &&
          current === 'ssam',
        `${refused} is refused by name in the switch ("${option.why}") and ssam kept`);
  await page.close();
} finally {
  await chromium.close();
  server.close();
}
for (const p of problems) check(false, p);
console.log(`racer_page_test: ${((Date.now() - started) / 1000).toFixed(1)} s`);
if (failed) process.exit(1);
