// Takes docs/view's screenshots: the committed glbs rendered by three.js (render.html) in headless Chromium,
// as a viewer shows them, and reports how much of retail's surface is visible in each (see render.html).
// Usage (from the repository root, after `npm ci` in tools/view-check): node tools/view-check/screenshot.mjs
// Needs chromium (Debian: apt-get install chromium) or CHROMIUM=/path/to/chrome.
import { createServer } from 'node:http';
import { readFileSync, writeFileSync, mkdirSync, existsSync } from 'node:fs';
import { execFile } from 'node:child_process';
import { promisify } from 'node:util';
import { join, extname, dirname } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const root = join(here, '..', '..');
const out = join(root, 'docs', 'view', 'screenshots');
const chromium = process.env.CHROMIUM ?? ['/usr/bin/chromium', '/usr/bin/chromium-browser', '/usr/bin/google-chrome'].find(existsSync);
if (!chromium) { console.error('no chromium: apt-get install chromium, or set CHROMIUM'); process.exit(2); }

const types = { '.html': 'text/html', '.js': 'text/javascript', '.glb': 'model/gltf-binary' };
// /hold answers when the page fetches /done (or after a minute): it keeps the page's load event back until then.
let held = [];
const server = createServer((req, res) => {
  const path = decodeURIComponent(new URL(req.url, 'http://x').pathname);
  if (path === '/hold') { held.push(res); setTimeout(() => res.writableEnded || res.end(), 60000).unref(); return; }
  if (path === '/done') { for (const h of held) h.writableEnded || h.end(); held = []; res.end(); return; }
  const file = path === '/render.html' ? join(here, 'render.html')
    : path.startsWith('/three/') ? join(here, 'node_modules', path)
    : path.startsWith('/view/') ? join(root, 'docs', 'view', path.slice('/view/'.length)) : null;
  if (!file || file.includes('..') || !existsSync(file)) { res.writeHead(404); res.end(); return; }
  res.writeHead(200, { 'content-type': types[extname(file)] ?? 'application/octet-stream' });
  res.end(readFileSync(file));
});
await new Promise(resolve => server.listen(0, '127.0.0.1', resolve));
const port = server.address().port;

// The door from four sides (30 degrees up); the landblock from above-south-west; the house with the door in its opening.
const shots = [
  ...[45, 135, 225, 315].map(az => ({ name: `door-${az}.png`, file: '0x020019FF.glb', az, el: 30 })),
  { name: 'landblock.png', file: '0xA9B4.glb', az: 200, el: 45 },
  // The door at landblock (136, 108, 12): glTF (136, 12, -108); seen from the east, outside the opening.
  { name: 'landblock-door-in-house.png', file: '0xA9B4.glb', az: 70, el: 25, focus: '134,14,-108', r: 7 },
];
mkdirSync(out, { recursive: true });
for (const s of shots) {
  const query = new URLSearchParams({ file: s.file, az: s.az, el: s.el, w: 800, h: 600, ...(s.focus ? { focus: s.focus, r: s.r } : {}) });
  // Asynchronous: this process serves the page while chromium renders it.
  const { stdout: dom } = await promisify(execFile)(chromium, ['--headless', '--no-sandbox', '--disable-gpu-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
    '--hide-scrollbars', '--dump-dom', `http://127.0.0.1:${port}/render.html?${query}`],
    { encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'], maxBuffer: 64 << 20, timeout: 60000 });
  const json = dom.match(/<pre id="result">([^<]*)<\/pre>/)?.[1];
  if (!json) { console.error(`${s.name}: the page gave no result (WebGL unavailable?)`); process.exitCode = 1; continue; }
  const result = JSON.parse(json.replaceAll('&quot;', '"').replaceAll('&amp;', '&'));
  if (result.error) { console.error(`${s.name}: ${result.error}`); process.exitCode = 1; continue; }
  writeFileSync(join(out, s.name), Buffer.from(result.picture.split(',')[1], 'base64'));
  const share = result.retailAlone ? (100 * result.retailVisible / result.retailAlone).toFixed(1) : 'n/a';
  console.log(`${s.name}: retail covers ${result.retailAlone} px alone, ${result.retailVisible} px with every layer drawn (${share} % visible)`);
}
server.close();
