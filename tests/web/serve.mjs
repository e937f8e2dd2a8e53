// SPDX-License-Identifier: MIT
// make serve-web, and the browser test's server: out/web (or the folder given) on 127.0.0.1 only,
// with the cross-origin isolation headers (COOP/COEP) a threaded WebAssembly build needs for
// SharedArrayBuffer (the page is single-threaded today; the headers cost nothing). Node alone.
//   node tests/web/serve.mjs [DIR] [PORT]   PORT 0 (the test's): any free port, printed
import { createServer } from 'node:http';
import { readFile } from 'node:fs/promises';
import { extname, join, normalize, resolve, sep } from 'node:path';

const types = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.mjs': 'text/javascript',
  '.wasm': 'application/wasm', '.data': 'application/octet-stream', '.png': 'image/png',
  '.json': 'application/json',
};

export function serve(dir, port) {
  const root = resolve(dir);
  const server = createServer(async (request, response) => {
    const path = decodeURIComponent(new URL(request.url, 'http://localhost').pathname);
    const file = normalize(join(root, path.endsWith('/') ? path + 'index.html' : path));
    const headers = { 'Cross-Origin-Opener-Policy': 'same-origin', 'Cross-Origin-Embedder-Policy': 'require-corp',
                      'Cache-Control': 'no-store' };
    if (!file.startsWith(root + sep)) {
      response.writeHead(403, headers).end('outside the served folder');
      return;
    }
    try {
      const body = await readFile(file);
      response.writeHead(200, { ...headers, 'Content-Type': types[extname(file)] ?? 'application/octet-stream' });
      response.end(body);
    } catch {
      response.writeHead(404, headers).end('not found: ' + path);
    }
  });
  return new Promise((done, fail) => {
    server.once('error', fail);
    server.listen(port, '127.0.0.1', () => done(server));
  });
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const dir = process.argv[2] ?? 'out/web';
  const server = await serve(dir, Number(process.argv[3] ?? 8080));
  console.log(`serve-web: ${resolve(dir)} at http://127.0.0.1:${server.address().port}/ (Ctrl+C stops)`);
}
