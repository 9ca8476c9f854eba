// The viewer in a real browser: starts `shadowkit serve` on a free loopback port, drives
// Debian's headless Chromium through puppeteer-core, and checks that what the page shows is
// what `shadowkit render` writes for the same camera and lights.
//
//   node viewer_browser_test.mjs SHADOWKIT_EXE SCENE.json OUT_DIR
//
// Exit status 0 when every check holds; each failed check prints one line.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import {
  startServer, launchBrowser, openViewer, settled, bringIntoView, dragLight,
} from './viewer_driver.mjs';

const [exe, scenePath, outDir] = process.argv.slice(2);
if (!outDir) {
  console.error('usage: node viewer_browser_test.mjs SHADOWKIT_EXE SCENE.json OUT_DIR');
  process.exit(2);
}
fs.mkdirSync(outDir, { recursive: true });
const work = fs.mkdtempSync(path.join(os.tmpdir(), 'shadowkit-viewer-'));
let failures = 0;
function check(condition, what) {
  console.log(`${condition ? 'ok  ' : 'FAIL'} ${what}`);
  if (!condition) failures++;
}

// A scene file with the page's camera and lights in place of the scene's own; mesh paths are
// made absolute, since the file is written elsewhere.
function sceneWithView(view) {
  const scene = JSON.parse(fs.readFileSync(scenePath, 'utf8'));
  for (const object of scene.objects || []) {
    if (object.mesh) object.mesh = path.resolve(path.dirname(scenePath), object.mesh);
  }
  scene.camera = view.camera;
  scene.lights = view.lights;
  const file = path.join(work, `view-${Date.now()}.json`);
  fs.writeFileSync(file, JSON.stringify(scene));
  return file;
}

// `shadowkit render` of the page's view with \p method: the image and light 0's mask.
function render(view, method) {
  const file = sceneWithView(view);
  const prefix = path.join(work, `${method}-mask`);
  const image = path.join(work, `${method}.png`);
  execFileSync(exe, ['render', file, '--method', method, '--mask', prefix, '--image', image]);
  return { image, mask: `${prefix}.L0.png` };
}

// Pixels of pane \p index's canvas that differ from the PNG \p file, both decoded by the
// browser the same way (no colour conversion).
async function differingPixels(page, index, file) {
  const png = fs.readFileSync(file).toString('base64');
  return page.evaluate(async (index, png) => {
    const canvas = window.shadowkitViewer.panes[index].canvas;
    const shown = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
    const bytes = Uint8Array.from(atob(png), (c) => c.charCodeAt(0));
    const bitmap = await createImageBitmap(new Blob([bytes], { type: 'image/png' }),
      { colorSpaceConversion: 'none', premultiplyAlpha: 'none' });
    if (bitmap.width !== canvas.width || bitmap.height !== canvas.height) return -1;
    const reference = new OffscreenCanvas(bitmap.width, bitmap.height).getContext('2d');
    reference.drawImage(bitmap, 0, 0);
    const expected = reference.getImageData(0, 0, bitmap.width, bitmap.height).data;
    let differing = 0;
    for (let i = 0; i < shown.length; i += 4) {
      if (shown[i] !== expected[i] || shown[i + 1] !== expected[i + 1] ||
          shown[i + 2] !== expected[i + 2]) differing++;
    }
    return differing;
  }, index, png);
}

const pageView = (page) => page.evaluate(() => {
  const s = window.shadowkitViewer.state;
  return { camera: s.camera, lights: s.lights.filter((l) => l.enabled).map((l) => l.light) };
});
const paneInfo = (page, index) => page.evaluate((i) => window.shadowkitViewer.panes[i].info, index);

async function choose(page, selector, value) {
  await page.select(selector, value);
  await settled(page);
}

const server = await startServer(exe, scenePath);
const browser = await launchBrowser();
try {
  const page = await openViewer(browser, server.url, { width: 1600, height: 900 });
  const errors = [];
  page.on('pageerror', (error) => errors.push(error.message));
  const first = await pageView(page);
  check((await paneInfo(page, 0)).method === 'volume', 'the page shows volume first');

  await bringIntoView(page, 0);
  const zoomed = await pageView(page);
  check(zoomed.camera.position[2] !== first.camera.position[2], 'the wheel zooms the camera out');
  await dragLight(page, 0, [160, 60]);
  const dragged = await pageView(page);
  const moved = dragged.lights[0].position;
  check(moved[0] !== first.lights[0].position[0] && moved[1] === first.lights[0].position[1],
    `dragging light 0 moves it across its plane: ${first.lights[0].position} -> ${moved}`);
  const frames = await page.evaluate(() => window.shadowkitViewer.stats.drawn);
  check(frames >= 3, `the drag drew ${frames} frames`);

  let expected = render(dragged, 'volume');
  check(await differingPixels(page, 0, expected.image) === 0,
    'the shaded image on the page is pixel-identical to `render --image` (volume)');

  await choose(page, '#method-0', 'svbsp');
  check((await paneInfo(page, 0)).method === 'svbsp', 'switching the method to svbsp');
  expected = render(dragged, 'svbsp');
  check(await differingPixels(page, 0, expected.image) === 0,
    'the page is pixel-identical to `render --image` (svbsp)');

  await choose(page, '#view', 'mask');
  check((await paneInfo(page, 0)).view === 'mask', 'switching the view to the mask');
  check(await differingPixels(page, 0, expected.mask) === 0,
    'the mask on the page is pixel-identical to `render --mask` (svbsp, light 0)');

  await choose(page, '#view', 'difference');
  const difference = await paneInfo(page, 0);
  check(difference.view === 'difference' && difference.reference_ms !== undefined,
    'the difference view compares with raytrace');
  await page.screenshot({ path: path.join(outDir, 'viewer-difference.png') });

  await choose(page, '#view', 'shaded');
  await choose(page, '#layout', 'two');
  await choose(page, '#method-1', 'raytrace');
  const panes = await page.evaluate(() => window.shadowkitViewer.panes.length);
  check(panes === 2 && (await paneInfo(page, 1)).method === 'raytrace',
    'two panes side by side, the right one raytrace');
  await page.click('#mismatch');
  await settled(page);
  const compared = await paneInfo(page, 0);
  check(compared.lights.every((l) => l.mismatch_interior_pct <= 0.05),
    `svbsp against raytrace on demand: ${compared.lights.map((l) => l.mismatch_interior_pct)} %`);
  await page.screenshot({ path: path.join(outDir, 'viewer.png') });
  check(errors.length === 0, `no script errors on the page ${errors.join('; ')}`);
} finally {
  await browser.close();
  const status = await server.stop();
  check(status === 0, `the server stops on SIGTERM with status 0 (got ${status})`);
  fs.rmSync(work, { recursive: true, force: true });
}
process.exit(failures ? 1 : 0);
