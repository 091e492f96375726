// Opens gdnav flight review pages (tools/report/review.py) in headless Chromium (Debian's /usr/bin/chromium through
// playwright-core) and checks them: no JavaScript error (pageerror, console error), no network request (the pages
// are self-contained), every figure drawn with its curves, a screenshot of each page; on the batch page a click on a
// point of the final-error scatter opens that run's page.
// usage: node check_review.mjs RUN_PAGE BATCH_PAGE SCREENSHOT_DIR   -> one JSON line on stdout; exit 1 on a failure
import { chromium } from 'playwright-core';
import { pathToFileURL } from 'node:url';
import path from 'node:path';
import fs from 'node:fs';

const [runPage, batchPage, shotDir] = process.argv.slice(2);
if (!runPage || !batchPage || !shotDir) {
  console.error('usage: node check_review.mjs RUN_PAGE BATCH_PAGE SCREENSHOT_DIR');
  process.exit(2);
}
fs.mkdirSync(shotDir, { recursive: true });

const browser = await chromium.launch({
  executablePath: process.env.GDNAV_CHROMIUM || '/usr/bin/chromium',
  headless: true,
  // playwright-core gives the browser a fresh temporary --user-data-dir of its own.
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
         '--disable-background-networking', '--disable-component-update', '--disable-sync'],
});
const problems = [];
const result = { pages: {} };

function watch(page, label) {
  page.on('pageerror', (e) => problems.push(`${label}: JavaScript error: ${e.message}`));
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`${label}: console error: ${m.text()}`); });
  page.on('request', (r) => {
    const u = r.url();
    if (!/^(file|data|blob):/.test(u)) problems.push(`${label}: network request ${u} (pages must be self-contained)`);
  });
}

// Every plot div: its traces and the drawn curve paths / markers (an empty figure has none).
async function figures(page) {
  return page.evaluate(() => {
    const out = {};
    for (const div of document.querySelectorAll('div.plot')) {
      const lines = [...div.querySelectorAll('.scatterlayer path.js-line')]
        .filter((p) => (p.getAttribute('d') || '').length > 50);
      out[div.id] = {
        traces: (div.data || []).length,
        lines: lines.length,
        points: div.querySelectorAll('.scatterlayer path.point').length,
        fills: div.querySelectorAll('.scatterlayer path.js-fill').length,
        shapes: div.querySelectorAll('.shapelayer path').length,
        height: div.getBoundingClientRect().height,
      };
    }
    return out;
  });
}

// The number of figures the page drew (set by the page once every figure is drawn).
async function ready(page) {
  return Number(await page.evaluate(() => document.body.dataset.plotsReady));
}

async function open(file, label) {
  const page = await browser.newPage({ viewport: { width: 1400, height: 1000 } });
  watch(page, label);
  await page.goto(pathToFileURL(path.resolve(file)).href);
  await page.waitForFunction(() => document.body.dataset.plotsReady !== undefined, null, { timeout: 90000 });
  const info = { ready: await ready(page), figures: await figures(page) };
  info.links = await page.evaluate(() => [...document.querySelectorAll('a[href]')].map((a) => a.getAttribute('href')));
  return { page, info };
}

try {
  {
    const { page, info } = await open(runPage, 'run page');
    await page.screenshot({ path: path.join(shotDir, 'review_run.png'), fullPage: true });
    result.pages.run = info;
    await page.close();
  }
  {
    const { page, info } = await open(batchPage, 'batch page');
    await page.screenshot({ path: path.join(shotDir, 'review_batch.png'), fullPage: true });
    result.pages.batch = info;
    // Click the first point of the final-error scatter: the page of its run opens.
    const point = page.locator('#final .scatterlayer path.point').first();
    await point.scrollIntoViewIfNeeded();
    const box = await point.boundingBox();
    if (!box) throw new Error('no point in the final-error scatter');
    await Promise.all([
      page.waitForURL(/review\/run_\d+\.html$/, { timeout: 30000 }),
      page.mouse.click(box.x + box.width / 2, box.y + box.height / 2),
    ]);
    await page.waitForFunction(() => document.body.dataset.plotsReady !== undefined, null, { timeout: 90000 });
    result.clicked = { url: path.basename(page.url()), ready: await ready(page) };
    await page.close();
  }
} catch (e) {
  problems.push(`check failed: ${e.message}`);
}
await browser.close();
result.problems = problems;
console.log(JSON.stringify(result));
process.exit(problems.length ? 1 : 0);
