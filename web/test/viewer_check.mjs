// Opens a viewer page that `shadowgen view` wrote in headless Chromium, from its file://
// URL, and reports what a test needs to judge it, as one JSON object on standard output:
//
//   node web/test/viewer_check.mjs PAGE_DIR [--hash camera=top] [--points POINTS.json]
//                                  [--switch-off light:ID|group:NAME ...] [--hover X,Y,Z]
//                                  [--screenshot OUT.png] [--width W] [--height H]
//
//   {"console_errors": [...], "page_errors": [...], "failed_requests": [...],
//    "network_requests": [URLs the page asked for beyond file:, data: and blob:],
//    "ready": true, "groups": [{"name": "sun", "colour": 16777215}, ...],
//    "north": the north arrow's angle, degrees clockwise from the screen's up,
//    "points": [{"name": ..., "x": ..., "y": ..., "rgb": [r, g, b]}, ...],
//    "hover": ["face ground", "area 400 m²", ...]}
//
// POINTS.json is a list of {"name", "at": [x, y, z]} in the scene's coordinates; each is
// projected by the page (window.shadowgenViewer.project) and its pixel read from a
// screenshot of the page, decoded by the browser. --switch-off unchecks a legend box (a
// light's, or a light set's or band's) first; --hover moves the pointer onto a point of
// the scene last and gives the lines of the hover box. The browser is Debian's chromium
// (/usr/bin/chromium, or $CHROMIUM), driven by playwright-core, WebGL drawn on the CPU
// (SwiftShader). Exit 0 when the page could be judged, 1 otherwise (the reason on stderr).
import { chromium } from 'playwright-core';
import { readFileSync, writeFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

function parseArgs(argv) {
  const args = { hash: '', points: null, screenshot: null, width: 800, height: 600, off: [], hover: null };
  const rest = [];
  for (let i = 0; i < argv.length; ++i) {
    const option = argv[i];
    if (option === '--hash') args.hash = argv[++i];
    else if (option === '--points') args.points = argv[++i];
    else if (option === '--screenshot') args.screenshot = argv[++i];
    else if (option === '--switch-off') args.off.push(argv[++i]);
    else if (option === '--hover') args.hover = argv[++i].split(',').map(Number);
    else if (option === '--width') args.width = Number(argv[++i]);
    else if (option === '--height') args.height = Number(argv[++i]);
    else rest.push(option);
  }
  if (rest.length !== 1) {
    throw new Error('usage: viewer_check.mjs PAGE_DIR [--hash H] [--points P.json] [--screenshot OUT.png]');
  }
  args.page = rest[0];
  return args;
}

async function main() {
  const args = parseArgs(process.argv.slice(2));
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox'],
  });
  const result = {
    console_errors: [], page_errors: [], failed_requests: [], network_requests: [], ready: false,
  };
  try {
    const page = await browser.newPage({ viewport: { width: args.width, height: args.height } });
    page.on('console', (message) => {
      if (message.type() === 'error') result.console_errors.push(message.text());
    });
    page.on('pageerror', (error) => result.page_errors.push(String(error)));
    page.on('request', (request) => {
      if (!/^(file|data|blob):/.test(request.url())) result.network_requests.push(request.url());
    });
    page.on('requestfailed', (request) =>
      result.failed_requests.push(`${request.url()}: ${request.failure()?.errorText}`));
    page.on('response', (response) => {
      if (response.status() >= 400) result.failed_requests.push(`${response.url()}: ${response.status()}`);
    });
    const url = pathToFileURL(resolve(args.page, 'index.html')).href + (args.hash ? '#' + args.hash : '');
    await page.goto(url, { waitUntil: 'load' });
    try {
      await page.waitForFunction(() => window.shadowgenViewer && window.shadowgenViewer.ready,
                                 null, { timeout: 30000 });
      result.ready = true;
    } catch (error) {
      result.ready = false;
    }
    if (result.ready) {
      for (const what of args.off) {
        const [kind, ...rest] = what.split(':');
        const found = await page.evaluate(({ kind, name }) => {
          const box = [...document.querySelectorAll(`input[data-${kind}]`)].find(
            (b) => b.dataset[kind] === name);
          if (!box) return false;
          box.checked = false;
          box.dispatchEvent(new Event('change'));
          return true;
        }, { kind, name: rest.join(':') });
        if (!found) throw new Error(`no legend box ${what}`);
      }
      result.groups = await page.evaluate(() => window.shadowgenViewer.groups());
      result.north = await page.evaluate(() => window.shadowgenViewer.north());
      const shot = await page.screenshot({ type: 'png' });
      if (args.screenshot) writeFileSync(args.screenshot, shot);
      if (args.points) {
        const points = JSON.parse(readFileSync(args.points, 'utf8'));
        result.points = await page.evaluate(async ({ points, png }) => {
          const bytes = Uint8Array.from(atob(png), (c) => c.charCodeAt(0));
          const image = await createImageBitmap(new Blob([bytes], { type: 'image/png' }));
          const canvas = new OffscreenCanvas(image.width, image.height);
          const context = canvas.getContext('2d');
          context.drawImage(image, 0, 0);
          return points.map((point) => {
            const at = window.shadowgenViewer.project(...point.at);
            const x = Math.floor(at.x);
            const y = Math.floor(at.y);
            const inside = x >= 0 && y >= 0 && x < image.width && y < image.height;
            const rgb = inside ? Array.from(context.getImageData(x, y, 1, 1).data.slice(0, 3)) : null;
            return { name: point.name, x, y, rgb };
          });
        }, { points, png: shot.toString('base64') });
      }
      if (args.hover) {
        const at = await page.evaluate((p) => window.shadowgenViewer.project(...p), args.hover);
        await page.mouse.move(at.x, at.y);
        result.hover = await page.evaluate(
          () => [...document.getElementById('info').children].map((line) => line.textContent));
      }
    }
  } finally {
    await browser.close();
  }
  process.stdout.write(JSON.stringify(result) + '\n');
}

main().catch((error) => {
  process.stderr.write(`viewer_check.mjs: ${error.message}\n`);
  process.exit(1);
});
