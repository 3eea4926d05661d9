// The monitor page in a real browser (headless Chromium, driven by
// puppeteer-core, which tests/live/browser_setup.sh installs into the build
// directory): it opens the page of a running program, sees a value change,
// forces a variable through the page and checks through the API that the
// force holds, steps one cycle and sees the cycle counter advance.
// Usage: node browser_test.js STRUN PROGRAM NODE_MODULES_DIR [SCREENSHOT.png]
"use strict";
const { spawn } = require("child_process");
const fs = require("fs");
const os = require("os");
const path = require("path");

const [strun, program, modules, screenshot] = process.argv.slice(2);
const puppeteer = require(path.join(modules, "puppeteer-core"));

// The step in progress, named in the failure message: a failure in CI leaves only this test's output.
let step = "start";
function fail(message) { throw new Error(message); }
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

async function startStrun(args) {
  const child = spawn(strun, ["run", ...args, program], { stdio: ["ignore", "pipe", "pipe"] });
  let err = "";
  const url = await new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error("no 'serving' line: " + err)), 30000);
    child.stderr.on("data", (d) => {
      err += d;
      const m = /strun: serving (http:\/\/\S+\/)/.exec(err);
      if (m) { clearTimeout(timer); resolve(m[1]); }
    });
    child.on("exit", (code) => reject(new Error("strun exited " + code + ": " + err)));
  });
  return { child, url };
}

async function api(url, p, body) {
  const res = await fetch(url + p.slice(1), body === undefined ? {} : { method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(body) });
  if (!res.ok) fail(p + ": " + res.status + " " + (await res.text()));
  return res.json();
}

async function waitFor(what, predicate, timeout = 30000) {
  const end = Date.now() + timeout;
  let last;
  while (Date.now() < end) {
    last = await what();
    if (predicate(last)) return last;
    await sleep(50);
  }
  fail("timed out; last " + JSON.stringify(last));
}

(async () => {
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), "strun-chromium-"));
  const { child, url } = await startStrun(["--serve", "127.0.0.1:0"]);
  let browser;
  try {
    step = "launching Chromium";
    // Generous limits: Chromium's first start on a fresh machine builds its font caches.
    browser = await puppeteer.launch({
      timeout: 120000,
      executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
      headless: true,
      args: ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-background-networking",
             "--disable-component-update", "--disable-sync", "--user-data-dir=" + profile],
    });
    const page = await browser.newPage();
    page.setDefaultTimeout(60000);
    await page.setViewport({ width: 1400, height: 900 });
    const outside = [];
    page.on("request", (r) => { if (!r.url().startsWith(url) && !r.url().startsWith("data:")) outside.push(r.url()); });
    const errors = [];
    page.on("pageerror", (e) => errors.push(String(e)));
    step = "loading the page";
    await page.goto(url, { waitUntil: "load" });

    // The instances are expanded: elementary values are in the page without a click.
    const cell = '.var[data-path="Main.counter"] .value';
    step = "the counter's value changing";
    await page.waitForSelector(cell);
    const first = await waitFor(() => page.$eval(cell, (td) => td.textContent), (t) => t !== "");
    await waitFor(() => page.$eval(cell, (td) => td.textContent), (t) => t !== "" && Number(t) > Number(first));
    const state = await waitFor(() => page.$eval("#plc-state", (e) => e.textContent), (t) => t === "RUN");
    if (state !== "RUN") fail("state " + state);

    // Force Main.x through the page: the editor of its row, value 42, F.
    step = "forcing Main.x through the page";
    await page.click('.var[data-path="Main.x"] .btn-edit');
    await page.waitForSelector('.var[data-path="Main.x"] .edit-value');
    await page.$eval('.var[data-path="Main.x"] .edit-value', (i) => { i.value = ""; });
    await page.type('.var[data-path="Main.x"] .edit-value', "42");
    await page.click('.var[data-path="Main.x"] .btn-force');
    const st = await waitFor(() => api(url, "/api/state"), (s) => s.forces["Main.x"] === 42);
    const before = st.tasks[0].cycles;
    await waitFor(() => api(url, "/api/state"), (s) => s.tasks[0].cycles > before + 5);
    const held = await api(url, "/api/vars?watch=Main.x&watch=Main.mirror");
    if (held.values["Main.x"] !== 42 || held.values["Main.mirror"] !== 43) fail("the force did not hold: " + JSON.stringify(held));
    await page.waitForSelector('.var[data-path="Main.x"].forced');
    await waitFor(() => page.$eval('.var[data-path="Main.x"] .value', (td) => td.textContent), (t) => t === "42");

    // Pause, then step one cycle from the page: the cycle counter advances by one.
    step = "pausing and stepping one cycle";
    await page.click("#btn-pause");
    await waitFor(() => api(url, "/api/state"), (s) => s.paused);
    await waitFor(() => page.$eval("#plc-paused", (e) => !e.hidden), (v) => v);
    const paused = (await api(url, "/api/state")).tasks[0].cycles;
    await sleep(200);
    if ((await api(url, "/api/state")).tasks[0].cycles !== paused) fail("cycles went on while paused");
    const counterBefore = Number(await page.$eval(cell, (td) => td.textContent));
    await page.click("#btn-step");
    const after = await waitFor(() => api(url, "/api/state"), (s) => s.tasks[0].cycles !== paused);
    if (after.tasks[0].cycles !== paused + 1 || !after.paused) fail("one step: " + paused + " -> " + after.tasks[0].cycles);
    await waitFor(() => page.$eval("#tasks tbody tr td:nth-child(4)", (td) => Number(td.textContent)), (c) => c === paused + 1);
    await waitFor(() => page.$eval(cell, (td) => Number(td.textContent)), (v) => v === counterBefore + 1);

    // The filter box.
    step = "the filter box";
    await page.type("#filter", "valve");
    await waitFor(() => page.$('.var[data-path="Main.counter"]'), (e) => e === null);
    if (!(await page.$('.var[data-path="Main.valve.cmd"]'))) fail("the filter hid a match");
    await page.$eval("#filter", (i) => { i.value = ""; i.dispatchEvent(new Event("input")); });
    await waitFor(() => page.$('.var[data-path="Main.counter"]'), (e) => e !== null);

    if (screenshot) {
      await api(url, "/api/resume", {});
      await page.click('.var[data-path="Main.counter"] .btn-edit');
      await page.click('.var[data-path="Main.counter"] .btn-trend');
      await page.click('.var[data-path="Main.word"] .btn-edit');
      await page.click('.var[data-path="Main.word"] .btn-trend');
      await sleep(2500);
      await page.screenshot({ path: screenshot });
    }
    if (outside.length) fail("the page loaded from elsewhere: " + outside.join(", "));
    if (errors.length) fail("errors in the page: " + errors.join("; "));
    console.log("ok   browser: value changes, force through the page holds, one step advances one cycle");
  } finally {
    if (browser) await browser.close();
    child.kill("SIGINT");
    fs.rmSync(profile, { recursive: true, force: true });
  }
})().catch((e) => { console.error("FAIL browser (" + step + "): " + e.message); process.exit(1); });
