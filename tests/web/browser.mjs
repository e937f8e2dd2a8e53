// SPDX-License-Identifier: MIT
// What the browser test and make web-picture share: their `--name value` arguments, and Debian's
// chromium-headless-shell started through puppeteer-core with WebGL2 on SwiftShader (ANGLE), the
// browser and the flags every run of the page uses. `fail` reports a missing piece by name.
import { existsSync } from 'node:fs';

// `--out DIR --png PATH` as { out: 'DIR', png: 'PATH' }.
export function parseArgs(argv) {
  return Object.fromEntries(argv.reduce((pairs, value, i, all) =>
    (i % 2 === 0 ? [...pairs, [all[i].replace(/^--/, ''), all[i + 1]]] : pairs), []));
}

export async function launchChromium(fail) {
  const browser = '/usr/bin/chromium-headless-shell';
  if (!existsSync(browser)) fail(`${browser} is missing (Debian: chromium-headless-shell; make deps installs it)`);
  let puppeteer;
  try {
    puppeteer = (await import('puppeteer-core')).default;
  } catch {
    fail('puppeteer-core is not installed in tests/web/node_modules: run `make web-tools` (npm ci)');
  }
  return puppeteer.launch({
    executablePath: browser, headless: 'shell',
    args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox', '--disable-gpu-sandbox'],
  });
}
