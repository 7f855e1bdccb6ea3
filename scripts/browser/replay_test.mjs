// Opens replay.html of real vorrt runs in Debian's Chromium (headless, via
// playwright-core; no browser is downloaded) and checks what the page draws
// against the run's own files: ownship's drawn position at a time against
// trajectory.csv, the findings list against report.json, no console error,
// no page error, no request leaving the file. Writes screenshots.
// Run by scripts/browser/run.sh (which builds target/debug/vorrt first).
import { chromium } from "playwright-core";
import { execFileSync } from "node:child_process";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import { fileURLToPath, pathToFileURL } from "node:url";

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.resolve(here, "..", "..");
const vorrt = process.env.VORRT ?? path.join(root, "target", "debug", "vorrt");
const out = process.env.VORRT_BROWSER_OUT ?? path.join(root, "target", "browser-test");
const fixtures = path.join(root, "crates", "scenarios", "fixtures");
// Positions are written to 0.1 m (data.rs); between two samples the page
// interpolates linearly, as this test does from trajectory.csv.
const TOLERANCE_M = 0.1;

let failures = 0;
function check(ok, message) {
  if (ok) {
    console.log("  ok   " + message);
  } else {
    failures += 1;
    console.log("  FAIL " + message);
  }
}

// Runs vorrt; exit 1 (the run had a finding) is a result, not a failure.
function run(args) {
  try {
    execFileSync(vorrt, args, { stdio: ["ignore", "ignore", "inherit"] });
  } catch (error) {
    if (error.status !== 1) throw error;
  }
}

// trajectory.csv: rows by vessel, in time order.
function readCsv(file) {
  const [header, ...lines] = fs.readFileSync(file, "utf8").trim().split("\n");
  const names = header.split(",");
  const byVessel = new Map();
  let ownship = null;
  for (const line of lines) {
    const cells = line.split(",");
    const row = Object.fromEntries(names.map((n, i) => [n, cells[i]]));
    const vessel = row.vessel;
    ownship ??= vessel;
    if (!byVessel.has(vessel)) byVessel.set(vessel, []);
    byVessel.get(vessel).push({ t: +row.time_s, east: +row.east_m, north: +row.north_m });
  }
  return { ownship, byVessel };
}

function interpolate(rows, t) {
  for (let i = 0; i + 1 < rows.length; i++) {
    if (rows[i].t <= t && t <= rows[i + 1].t) {
      const f = (t - rows[i].t) / (rows[i + 1].t - rows[i].t);
      return { east: rows[i].east + (rows[i + 1].east - rows[i].east) * f,
        north: rows[i].north + (rows[i + 1].north - rows[i].north) * f };
    }
  }
  return null;
}

async function openPage(browser, file) {
  const page = await browser.newPage();
  const problems = [];
  page.on("console", (message) => {
    if (message.type() === "error") problems.push("console error: " + message.text());
  });
  page.on("pageerror", (error) => problems.push("page error: " + error.message));
  // Nothing but the file itself may load: any other request is a failure.
  await page.route("**/*", (route) => {
    const url = route.request().url();
    if (url === pathToFileURL(file).href) return route.continue();
    problems.push("request: " + url);
    return route.abort();
  });
  await page.goto(pathToFileURL(file).href);
  try {
    await page.waitForFunction(() => window.vorrtReplay !== undefined, null, { timeout: 10_000 });
  } catch (error) {
    throw new Error(`${file}: the page did not start (${problems.join("; ") || error.message})`);
  }
  return { page, problems };
}

async function setSlider(page, time_s) {
  await page.locator("#slider").fill(String(time_s));
  return page.evaluate(() => window.vorrtReplay.state());
}

// The drawn positions at a sample time and between two samples against
// trajectory.csv, every vessel.
async function checkPositions(page, csv, times, label) {
  for (const t of times) {
    const state = await setSlider(page, t);
    check(Math.abs(state.time_s - t) < 1e-6, `${label}: slider at ${t} s shows t = ${state.time_s}`);
    const own = state.vessels.find((v) => v.role === "ownship");
    const expected = interpolate(csv.byVessel.get(csv.ownship), t);
    const error = Math.hypot(own.east_m - expected.east, own.north_m - expected.north);
    check(own.name === csv.ownship && error <= TOLERANCE_M,
      `${label}: ownship drawn at (${own.east_m.toFixed(2)}, ${own.north_m.toFixed(2)}) m at ${t} s, trajectory.csv (${expected.east.toFixed(2)}, ${expected.north.toFixed(2)}): ${error.toFixed(3)} m`);
    let worst = 0;
    for (const v of state.vessels) {
      const e = interpolate(csv.byVessel.get(v.name), t);
      if (e) worst = Math.max(worst, Math.hypot(v.east_m - e.east, v.north_m - e.north));
    }
    check(worst <= TOLERANCE_M, `${label}: all ${state.vessels.length} vessels within ${worst.toFixed(3)} m of trajectory.csv at ${t} s`);
  }
}

// The findings list holds exactly the report's findings, and a click on
// one moves the slider to its moment.
async function checkFindings(page, report, label) {
  const listed = await page.$$eval("#findings li.finding", (items) =>
    items.map((li) => ({ vessel: li.dataset.vessel, name: li.dataset.name, time: li.dataset.time })));
  const expected = [];
  for (const target of report.targets) for (const name of target.findings) expected.push(target.name + "/" + name);
  for (const text of report.path_quality.findings) expected.push("/track");
  const got = listed.map((f) => f.vessel + "/" + f.name);
  check(JSON.stringify([...got].sort()) === JSON.stringify([...expected].sort()),
    `${label}: the ${got.length} findings listed are the report's ${expected.length}` +
    (got.length <= 6 ? ` [${got.join(", ")}]` : ` (${got.slice(0, 4).join(", ")}, ...)`));
  const onTimeline = (await page.evaluate(() => window.vorrtReplay.state())).timeline_findings;
  const timedCount = listed.filter((f) => f.time !== "").length;
  check(onTimeline === timedCount, `${label}: ${onTimeline} findings marked on the timeline for ${timedCount} with a moment`);
  const timed = listed.find((f) => f.time !== "");
  if (timed) {
    await page.locator(`#findings li.finding[data-name="${timed.name}"]`).first().click();
    const state = await page.evaluate(() => window.vorrtReplay.state());
    const slider = Number(await page.locator("#slider").inputValue());
    check(Math.abs(state.time_s - Number(timed.time)) < 1e-6 && Math.abs(slider - Number(timed.time)) <= 0.05,
      `${label}: clicking finding ${timed.vessel}/${timed.name} moves to ${Number(timed.time)} s (now ${state.time_s} s, slider ${slider})`);
  }
}

async function screenshots(page, times, stem) {
  fs.mkdirSync(path.join(out, "screenshots"), { recursive: true });
  for (const t of times) {
    await setSlider(page, t);
    const file = path.join(out, "screenshots", `${stem}-t${String(Math.round(t)).padStart(4, "0")}.png`);
    await page.screenshot({ path: file, fullPage: true });
    console.log("  wrote " + path.relative(root, file));
  }
}

async function checkRun(browser, label, dir, reportFile, csvFile = path.join(dir, "trajectory.csv")) {
  console.log(label);
  const html = path.join(dir, "replay.html");
  const report = JSON.parse(fs.readFileSync(path.join(dir, reportFile), "utf8"));
  const { page, problems } = await openPage(browser, html);
  const data = await page.evaluate(() => window.vorrtReplay.data());
  const times = data.times_s;
  const end = times[times.length - 1];
  const at = (f) => times[Math.round((times.length - 1) * f)];
  const mid = (at(0.5) + times[Math.round((times.length - 1) * 0.5) + 1]) / 2;
  await checkPositions(page, readCsv(csvFile), [at(0.3), mid, end], label);
  await checkFindings(page, report, label);
  const legendRows = await page.$$eval("#legend tr.vessel", (rows) => rows.length);
  check(legendRows === 1 + report.targets.length, `${label}: the vessel list has ${legendRows} rows for ${1 + report.targets.length} vessels`);
  check(problems.length === 0, `${label}: no console error, page error or outside request${problems.length ? ": " + problems.join("; ") : ""}`);
  return { page, data, times, at };
}

// The page draws land, no-go areas and separation zones when its data has
// them (the scenario does not carry them yet): a copy of a page with a
// square of land around a square hole, checked by the colour of pixels
// inside the land, inside the hole, and in a no-go square.
async function checkPolygons(browser, dir) {
  const label = "polygons (tss page with land, a hole and a no-go area)";
  console.log(label);
  const html = fs.readFileSync(path.join(dir, "replay.html"), "utf8");
  const ring = (x0, y0, x1, y1) => [[x0, y0], [x1, y0], [x1, y1], [x0, y1]];
  const land = [[ring(-9000, -5000, -5000, -2000), ring(-8000, -4000, -7000, -3000)]];
  const noGo = [[ring(-3600, 2600, -2600, 3600)]];
  const patched = html
    .replace('"land":[]', '"land":' + JSON.stringify(land))
    .replace('"no_go":[]', '"no_go":' + JSON.stringify(noGo));
  check(patched !== html, `${label}: the data has the optional polygon fields`);
  const file = path.join(dir, "replay-polygons.html");
  fs.writeFileSync(file, patched);
  const { page, problems } = await openPage(browser, file);
  await setSlider(page, 0);
  const colours = await page.evaluate((points) => {
    const chart = document.getElementById("chart");
    const view = window.vorrtReplay.state().view;
    const dpr = window.devicePixelRatio || 1;
    const ctx = chart.getContext("2d");
    return points.map(([x, y]) => {
      const px = chart.clientWidth / 2 + (x - view.cx) * view.px_per_m;
      const py = chart.clientHeight / 2 - (y - view.cy) * view.px_per_m;
      return Array.from(ctx.getImageData(Math.round(px * dpr), Math.round(py * dpr), 1, 1).data);
    });
  }, [[-6000, -2500], [-7500, -3500], [-3100, 3100]]);
  const near = (c, rgb) => rgb.every((v, i) => Math.abs(c[i] - v) <= 12);
  check(near(colours[0], [0xe9, 0xdc, 0xb5]), `${label}: land is drawn (pixel ${colours[0]})`);
  check(!near(colours[1], [0xe9, 0xdc, 0xb5]), `${label}: its hole is not (pixel ${colours[1]})`);
  check(colours[2][0] > colours[2][1] + 20, `${label}: the no-go area is drawn red (pixel ${colours[2]})`);
  check(problems.length === 0, `${label}: no console error, page error or outside request${problems.length ? ": " + problems.join("; ") : ""}`);
}

// Play runs the clock and pause stops it; the wheel zooms and a drag pans.
async function checkControls(page, label) {
  await setSlider(page, 0);
  await page.locator("#speed").selectOption("300");
  await page.locator("#play").click();
  await page.waitForFunction(() => window.vorrtReplay.state().time_s > 0, null, { timeout: 10_000 });
  await page.locator("#play").click();
  const paused = await page.evaluate(() => window.vorrtReplay.state());
  check(!paused.playing && paused.time_s > 0, `${label}: play ran the clock to ${paused.time_s.toFixed(1)} s, pause stopped it`);
  const box = await page.locator("#chart").boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.wheel(0, -300);
  const zoomed = await page.evaluate(() => window.vorrtReplay.state());
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 120, box.y + box.height / 2, { steps: 4 });
  await page.mouse.up();
  await setSlider(page, paused.time_s);
  const panned = await page.evaluate(() => window.vorrtReplay.state());
  check(zoomed.view.px_per_m > paused.view.px_per_m * 1.2, `${label}: the wheel zoomed in (${paused.view.px_per_m.toFixed(4)} -> ${zoomed.view.px_per_m.toFixed(4)} px/m)`);
  check(panned.view.cx < zoomed.view.cx, `${label}: dragging right moved the view west (${zoomed.view.cx.toFixed(0)} -> ${panned.view.cx.toFixed(0)} m east)`);
  await page.locator("#fit").click();
}

// Ownship and `count` targets on straight tracks, as trajectory.csv: a
// judge run with many vessels (no planner, so it is quick in debug builds).
function manyTargetsCsv(file, count) {
  const rows = ["time_s,vessel,east_m,north_m,course_deg,speed_kn,length_m"];
  const knots = 1852 / 3600;
  for (let t = 0; t <= 1800; t += 5) {
    rows.push(`${t},ownship,0,${-5556 + 12 * knots * t},0,12,100`);
    for (let k = 0; k < count; k++) {
      const angle = (2 * Math.PI * k) / count;
      const r = 9000 + 40 * k;
      const speed = 6 + (k % 9);
      const course = (angle * 180 / Math.PI + 180) % 360;
      const x = r * Math.sin(angle) - Math.sin(angle) * speed * knots * t;
      const y = r * Math.cos(angle) - Math.cos(angle) * speed * knots * t;
      rows.push(`${t},T${k + 1},${x.toFixed(2)},${y.toFixed(2)},${course.toFixed(2)},${speed},${60 + (k % 5) * 40}`);
    }
  }
  fs.writeFileSync(file, rows.join("\n") + "\n");
}

async function main() {
  fs.rmSync(out, { recursive: true, force: true });
  fs.mkdirSync(out, { recursive: true });
  run(["simulate", path.join(fixtures, "paper", "tss.ron"), "--out", path.join(out, "tss")]);
  run(["simulate", path.join(fixtures, "imazu", "imazu_13.ron"), "--out", path.join(out, "imazu_13")]);
  run(["simulate", path.join(fixtures, "geo", "channel_ais.ron"), "--out", path.join(out, "channel_ais")]);
  run(["judge", path.join(out, "imazu_13", "trajectory.csv"), "--scenario", path.join(fixtures, "imazu", "imazu_13.ron"), "--out", path.join(out, "judge_imazu_13")]);
  manyTargetsCsv(path.join(out, "many.csv"), 100);
  run(["judge", path.join(out, "many.csv"), "--out", path.join(out, "judge_many")]);

  const userData = fs.mkdtempSync(path.join(os.tmpdir(), "vorrt-chromium-"));
  // A fresh profile (playwright passes it as --user-data-dir); without the
  // networking flags Chromium's own connections are refused on CI machines.
  const browser = await chromium.launchPersistentContext(userData, {
    executablePath: process.env.CHROMIUM ?? "/usr/bin/chromium",
    headless: true,
    viewport: { width: 1400, height: 1050 },
    args: ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
      "--disable-background-networking", "--disable-component-update", "--disable-sync"],
  });
  try {
    const tss = await checkRun(browser, "paper/tss (simulate)", path.join(out, "tss"), "report.json");
    check(tss.data.lanes.length === 1, "paper/tss: the westbound lane is in the data");
    await screenshots(tss.page, [tss.at(0.25), tss.at(0.5), tss.at(0.75)], "tss");
    await checkPolygons(browser, path.join(out, "tss"));
    const imazu = await checkRun(browser, "imazu_13 (simulate)", path.join(out, "imazu_13"), "report.json");
    await screenshots(imazu.page, [imazu.at(0.2), imazu.at(0.45), imazu.at(0.7)], "imazu_13");
    await checkControls(imazu.page, "imazu_13 (simulate)");
    const geo = await checkRun(browser, "geo/channel_ais (simulate)", path.join(out, "channel_ais"), "report.json");
    check(geo.data.geo !== null && geo.data.geo.graticule.length >= 4,
      `geo/channel_ais: a latitude/longitude grid of ${geo.data.geo ? geo.data.geo.graticule.length : 0} lines`);
    await screenshots(geo.page, [geo.at(0.5)], "channel_ais");
    await checkRun(browser, "imazu_13 (judge)", path.join(out, "judge_imazu_13"), "judgement.json",
      path.join(out, "imazu_13", "trajectory.csv"));
    const many = await checkRun(browser, "100 targets (judge)", path.join(out, "judge_many"), "judgement.json",
      path.join(out, "many.csv"));
    const size = fs.statSync(path.join(out, "judge_many", "replay.html")).size;
    check(size < 1_000_000, `100 targets: replay.html is ${(size / 1024).toFixed(0)} KiB`);
    await screenshots(many.page, [many.at(0.5)], "many");
    // A figure, not a check (no timed assertion): the time to draw one
    // frame (chart, timeline, charts) with 101 vessels, over 200 slider moves.
    const frameMs = await many.page.evaluate(() => {
      const slider = document.getElementById("slider");
      const start = performance.now();
      for (let k = 0; k < 200; k++) {
        slider.value = (k * 7.3) % Number(slider.max);
        slider.dispatchEvent(new Event("input"));
      }
      return (performance.now() - start) / 200;
    });
    console.log(`  100 targets: ${frameMs.toFixed(1)} ms per frame`);
  } finally {
    await browser.close();
    fs.rmSync(userData, { recursive: true, force: true });
  }
  console.log(failures === 0 ? "browser test: all checks passed" : `browser test: ${failures} checks FAILED`);
  process.exit(failures === 0 ? 0 : 1);
}

main().catch((error) => {
  console.error(error);
  process.exit(1);
});
