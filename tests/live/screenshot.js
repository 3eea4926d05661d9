// Takes docs/images/live-monitor.png: the monitor page of
// programs/multitask_plant.st on the real clock, with a trend of the tank
// level, in headless Chromium (as browser_test.js does). Not a test:
//   node tests/live/screenshot.js build/strun build/live-browser/node_modules docs/images/live-monitor.png
"use strict";
const { spawn } = require("child_process");
const fs = require("fs");
const os = require("os");
const path = require("path");

const [strun, modules, out] = process.argv.slice(2);
const puppeteer = require(path.join(modules, "puppeteer-core"));
const program = path.join(__dirname, "..", "..", "programs", "multitask_plant.st");
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

(async () => {
  const child = spawn(strun, ["run", "--serve", "127.0.0.1:0", program], { stdio: ["ignore", "ignore", "pipe"] });
  const url = await new Promise((resolve) => {
    let err = "";
    child.stderr.on("data", (d) => { err += d; const m = /serving (http:\/\/\S+\/)/.exec(err); if (m) resolve(m[1]); });
  });
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), "strun-chromium-"));
  const browser = await puppeteer.launch({
    executablePath: process.env.CHROMIUM || "/usr/bin/chromium", headless: true,
    args: ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-background-networking",
           "--disable-component-update", "--disable-sync", "--user-data-dir=" + profile],
  });
  try {
    const page = await browser.newPage();
    await page.setViewport({ width: 1400, height: 1050 });
    await page.goto(url, { waitUntil: "load" });
    // Rows far down the list are drawn once scrolled to: pick them through the filter.
    for (const path of ["gLevel", "Trend.maxLevel"]) {
      await page.$eval("#filter", (i, p) => { i.value = p; i.dispatchEvent(new Event("input")); }, path);
      await sleep(500);  // the filter applies 150 ms after the last key
      await page.waitForSelector(`.var[data-path="${path}"] .btn-edit`);
      await page.click(`.var[data-path="${path}"] .btn-edit`);
      await page.waitForSelector(`.var[data-path="${path}"] .btn-trend`);
      await page.click(`.var[data-path="${path}"] .btn-trend`);
    }
    await page.$eval("#filter", (i) => { i.value = ""; i.dispatchEvent(new Event("input")); });
    await sleep(7000);
    await page.evaluate(() => { document.activeElement.blur(); window.scrollTo(0, 0); });
    await sleep(300);
    await page.screenshot({ path: out });
  } finally {
    await browser.close();
    child.kill("SIGINT");
    fs.rmSync(profile, { recursive: true, force: true });
  }
})();
