// The README's picture of the viewer: the default scene, svbsp beside raytrace, a light
// dragged, compared with raytrace.
//
//   node screenshot.mjs SHADOWKIT_EXE OUT.png
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { startServer, launchBrowser, openViewer, settled } from './viewer_driver.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../../..');
const [exe, out] = process.argv.slice(2);
const server = await startServer(exe, path.join(root, 'examples/default.json'));
const browser = await launchBrowser();
try {
  const page = await openViewer(browser, server.url, { width: 1600, height: 900 });
  await page.select('#layout', 'two');
  await page.select('#method-0', 'svbsp');
  await page.select('#method-1', 'raytrace');
  await settled(page);
  // The point light typed into its fields, low enough to see its handle on the image.
  const fields = await page.$$('#lights .light .xyz input');
  for (const [field, value] of fields.map((f, i) => [f, ['-1.8', '3.0', '3.4'][i]])) {
    await field.click({ clickCount: 3 });
    await field.type(value);
    await field.press('Tab');
  }
  await page.click('#mismatch');
  await settled(page);
  await page.evaluate(() => document.querySelector('#controls').scrollTo(0, 0));
  await page.screenshot({ path: out });
} finally {
  await browser.close();
  await server.stop();
}
