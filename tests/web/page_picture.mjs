// SPDX-License-Identifier: MIT
// make web-picture: README's picture of the racer's page (game/web/page.png), taken the way the
// browser test runs it: make web's out/web served on a loopback port, Debian's
// chromium-headless-shell through puppeteer-core, WebGL2 on SwiftShader. The page runs SSAM with
// its HUD (every pass's time, the light shafts' among them), the chase camera into a bend at
// 480x270, 200 fixed steps of 1/30 s; the picture is the page's header, canvas and key line
// after the last step (its times are this machine's, so no two pictures are the same).
//   node page_picture.mjs --out OUT_WEB --png PATH [--frames N] [--camera chase|pan|free|sky]
import { existsSync } from 'node:fs';
import { join } from 'node:path';
import { launchChromium, parseArgs } from './browser.mjs';
import { serve } from './serve.mjs';

const args = parseArgs(process.argv.slice(2));
const fail = (message) => { console.error(`page_picture: ${message}`); process.exit(1); };
if (!args.out || !args.png) fail('usage: node page_picture.mjs --out OUT_WEB --png PATH [--frames N] [--camera C]');
if (!existsSync(join(args.out, 'racer.wasm'))) fail(`${args.out} has no page: run \`make web\` first`);
const frames = Number(args.frames ?? 200);
if (!Number.isInteger(frames) || frames < 1) fail(`--frames ${args.frames}: a whole number of at least 1`);

const chromium = await launchChromium(fail);
const server = await serve(args.out, 0);
try {
  const page = await chromium.newPage();
  await page.setViewport({ width: 520, height: 400 });
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  const query = new URLSearchParams({ technique: 'ssam', camera: args.camera ?? 'chase', size: '480x270',
                                      frames, dt: 0.0333333, hud: 1 });
  await page.goto(`http://127.0.0.1:${server.address().port}/?${query}`, { waitUntil: 'load' });
  await page.waitForFunction('racerPage.framesDone || racerPage.error', { timeout: 300000 });
  const error = await page.evaluate('racerPage.error');
  if (error || errors.length) fail(`the page failed: ${error ?? errors.join('; ')}`);
  const box = await page.evaluate(() => {
    const bottom = document.getElementById('keys').getBoundingClientRect().bottom;
    return { x: 0, y: 0, width: document.documentElement.clientWidth, height: Math.ceil(bottom) + 8 };
  });
  await page.screenshot({ path: args.png, clip: box });
  console.log(`page_picture: wrote ${args.png} (${box.width}x${box.height}, ${frames} frames)`);
} finally {
  await chromium.close();
  server.close();
}
