// Starting `shadowkit serve` and Chromium, and driving the page as a user would: what the
// browser test and the latency measurement share.
import { spawn } from 'node:child_process';
import puppeteer from 'puppeteer-core';

const CHROMIUM = process.env.SHADOWKIT_CHROMIUM || '/usr/bin/chromium';

// `shadowkit serve SCENE --port 0` on loopback; resolves with its URL once it prints it.
export function startServer(exe, scene, extra = []) {
  const child = spawn(exe, ['serve', scene, '--port', '0', ...extra],
    { stdio: ['ignore', 'pipe', 'inherit'] });
  const exited = new Promise((resolve) => child.on('exit', (code) => resolve(code)));
  return new Promise((resolve, reject) => {
    let output = '';
    child.stdout.on('data', (chunk) => {
      output += chunk;
      const url = output.match(/http:\/\/\S+\//);
      if (url) {
        resolve({
          url: url[0],
          stop: async () => { child.kill('SIGTERM'); return exited; },
        });
      }
    });
    exited.then((code) => reject(new Error(`shadowkit serve exited with ${code}: ${output}`)));
  });
}

export function launchBrowser() {
  return puppeteer.launch({
    executablePath: CHROMIUM,
    headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage'],
  });
}

// Opens the viewer at \p url and waits for its first frame.
export async function openViewer(browser, url, viewport) {
  const page = await browser.newPage();
  await page.setViewport({ ...viewport, deviceScaleFactor: 1 });
  await page.goto(url);
  await page.waitForFunction(() => window.shadowkitViewer && window.shadowkitViewer.stats.drawn > 0,
    { timeout: 60000 });
  await settled(page);
  return page;
}

// Waits until every pane shows the frame of the newest state: nothing waits to be sent, and the
// last request sent is the one drawn.
export async function settled(page) {
  try {
    await page.waitForFunction(() => window.shadowkitViewer.panes.every((p) =>
      p.pendingSince === null && p.inFlight === null && p.socket.readyState === WebSocket.OPEN &&
      p.drawnId === p.nextId - 1), { timeout: 120000, polling: 50 });
  } catch (error) {
    const panes = await page.evaluate(() => window.shadowkitViewer.panes.map((p) =>
      ({ pending: p.pendingSince, inFlight: p.inFlight, socket: p.socket.readyState,
        drawn: p.drawnId, next: p.nextId,
        caption: p.caption.textContent })));
    throw new Error(`the page did not settle: ${JSON.stringify(panes)}`);
  }
}

// Where light \p index's handle is, in the page's CSS pixels.
export function handleOf(page, index) {
  return page.evaluate((index) => {
    const v = window.shadowkitViewer;
    const pane = v.panes[0];
    const at = v.project(v.state.camera, v.state.lights[index].light.position);
    const rect = pane.overlay.getBoundingClientRect();
    const s = rect.width / pane.canvas.width;
    return [rect.left + at[0] * s, rect.top + at[1] * s];
  }, index);
}

// Zooms out with the mouse wheel, as a user would, until light \p index's handle is on the
// image with a margin.
export async function bringIntoView(page, index) {
  for (let tries = 0; tries < 20; tries++) {
    const [x, y] = await handleOf(page, index);
    const rect = await page.evaluate(() => {
      const r = window.shadowkitViewer.panes[0].overlay.getBoundingClientRect();
      return [r.left, r.top, r.right, r.bottom];
    });
    const margin = 0.15 * (rect[2] - rect[0]);
    if (x > rect[0] + margin && x < rect[2] - margin && y > rect[1] + margin &&
        y < rect[3] - margin) return;
    await page.mouse.move((rect[0] + rect[2]) / 2, (rect[1] + rect[3]) / 2);
    await page.mouse.wheel({ deltaY: 400 });
    await settled(page);
  }
  throw new Error(`light ${index} stays outside the image`);
}

// Drags light \p index's handle by \p offset CSS pixels with the mouse, in \p steps moves
// \p interval milliseconds apart, then waits for the last frame.
export async function dragLight(page, index, offset, steps = 10, interval = 16) {
  const [x, y] = await handleOf(page, index);
  await page.mouse.move(x, y);
  await page.mouse.down();
  for (let i = 1; i <= steps; i++) {
    await page.mouse.move(x + offset[0] * i / steps, y + offset[1] * i / steps);
    await new Promise((resolve) => setTimeout(resolve, interval));
  }
  await page.mouse.up();
  await settled(page);
}
