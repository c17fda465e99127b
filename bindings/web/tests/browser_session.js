// A session in a real browser (headless Chromium, driven by cdp.js): keys pressed in the
// platformer move the player, who jumps and lands; the canvas shows every body where the
// module says it is; the package's API on the page runs a game's world and reports its errors.
// Saves screenshots of the page (docs/web.png is one).
//   node browser_session.js <page dir> <screenshot dir>
//
// Expected values come from demo/sample_platformer.cpp: the floor's top is at y 512 (row
// 16 of 32 px tiles), the player is 22 x 40 px, so it stands at y 492; it runs at 260
// px/s and jumps 4 tiles (128 px) high, which takes it above the jump-through platform
// at (160, 400), 112 px wide and 10 high: a jump under it lands on it, at y 375.
"use strict";

const fs = require("node:fs");
const path = require("node:path");
const {Browser, sleep} = require("./cdp.js");
const {serve} = require("./serve.js");

const kStandingY = 512 - 20;
const kRunSpeed = 260;
const kJumpHeight = 128;
const kPlatform = {x: 160, hw: 56, top: 395};
const kPlayerHalf = {hw: 11, hh: 20};

let failures = 0;
function check(ok, what) {
  console.log(`${ok ? "ok  " : "FAIL"} ${what}`);
  if (!ok) failures++;
}

const player = (page) => page.evaluate("jostlePage.state.page.player()");

async function platformer(page) {
  await page.goto(`${page.base}index.html?sample=2`);
  await page.waitUntil("document.title === 'jostle: ready'");
  check(await page.evaluate("jostlePage.state.page.currentName()") === "platformer",
        "?sample=2 opens the platformer");
  // It starts in the air at y 480 and settles on the floor.
  await page.waitUntil(`(p => p.floor && Math.abs(p.y - ${kStandingY}) < 0.5)(jostlePage.state.page.player())`);
  const start = await player(page);
  check(Math.abs(start.y - kStandingY) < 0.5, `the player stands on the floor at y ${start.y.toFixed(2)} (${kStandingY})`);

  // Right arrow held for half a second: about 130 px at 260 px/s (frames come late on a
  // busy machine, so at least a third of that).
  await page.key("ArrowRight", "keyDown");
  const held = Date.now();
  await sleep(500);
  await page.key("ArrowRight", "keyUp");
  const seconds = (Date.now() - held) / 1000;
  await sleep(200);
  const ran = await player(page);
  const moved = ran.x - start.x;
  check(moved > kRunSpeed * seconds / 3 && moved < kRunSpeed * seconds * 1.5,
        `right arrow runs right: ${moved.toFixed(1)} px in ${seconds.toFixed(2)} s at ${kRunSpeed} px/s`);
  check(ran.floor && Math.abs(ran.y - kStandingY) < 0.5, "running stays on the floor");

  // Space jumps: up by about 4 tiles, then down onto the floor again.
  await page.evaluate("window.lowest = 1e9; (function watch() { const p = jostlePage.state.page.player(); if (p === null) return; lowest = Math.min(lowest, p.y); requestAnimationFrame(watch); })(); 0");
  await page.press("Space");
  await page.waitUntil(`jostlePage.state.page.player().y < ${kStandingY - 20}`, 5);
  check(true, "space leaves the floor");
  // Where it lands: on the platform if it jumped from under it, else on the floor.
  const under = Math.abs(ran.x - kPlatform.x) < kPlatform.hw + kPlayerHalf.hw;
  const landingY = under ? kPlatform.top - kPlayerHalf.hh : kStandingY;
  // Landed and still (a busy machine may show a frame of the landing itself first).
  await page.waitUntil(`(p => p.floor && Math.abs(p.y - ${landingY}) < 0.5 && Math.abs(p.vy) < 1)(jostlePage.state.page.player())`, 5);
  const top = await page.evaluate("lowest");
  const rise = kStandingY - top;
  check(rise > kJumpHeight * 0.8 && rise < kJumpHeight * 1.1,
        `the jump rises ${rise.toFixed(1)} px (${kJumpHeight})`);
  const landed = await player(page);
  check(landed.floor && Math.abs(landed.y - landingY) < 0.5 && Math.abs(landed.vy) < 1,
        `the player lands on ${under ? "the jump-through platform" : "the floor again"} (y ${landed.y.toFixed(2)}, ${landingY}; ` +
        `floor ${landed.floor}, vy ${landed.vy.toFixed(2)})`);
  check(Math.abs(landed.x - ran.x) < 1, "a jump in place lands where it left");

  // Pause, so that the canvas and the module agree, then compare them.
  await page.press("KeyP");
  await page.waitUntil("jostlePage.state.paused");
  await sleep(100); // a frame drawn while paused
  await canvasShowsBodies(page);
  const shot = await page.screenshot();
  fs.writeFileSync(path.join(page.shots, "platformer.png"), shot);
}

/// Every body at least 6 px across is its type's colour at its centre on the canvas, and
/// points far from any body are background.
async function canvasShowsBodies(page) {
  const report = await page.evaluate(`(() => {
    const p = jostlePage.state.page;
    const bodies = p.bodies(0);
    const scale = jostlePage.state.views[0].scale;
    const colours = [[150, 150, 150], [70, 130, 230], [240, 150, 60]];
    const near = (a, b) => a.every((c, i) => Math.abs(c - b[i]) <= 2);
    let checked = 0, wrong = [];
    const boxes = [];
    for (let i = 0; i < bodies.length; i += 12) {
      const [x, y, hw, hh, , , type, flags, kind] = bodies.subarray(i, i + 12);
      boxes.push([x, y, hw, hh]);
      if (kind !== 0 || (flags & 4) || Math.min(hw, hh) * scale < 3) continue;
      const pixel = jostlePage.pixel(...jostlePage.toCanvas(0, x, y));
      checked++;
      if (!near(pixel, colours[type])) wrong.push([x, y, type, pixel]);
    }
    // A label's text above its body (draw.js: its baseline 5 px over the body's top), as
    // a box: some 8 px a character wide and 12 px high.
    const taken = boxes.slice();
    for (const l of p.labels(0))
      taken.push([l.x, l.y - l.hh - 11 / scale, (l.text.length * 4 + 2) / scale, 6 / scale]);
    // Empty points: on a grid over the view, 8 px or more from every body and label.
    const v = p.view(0), margin = 8 / scale;
    let empty = 0, notEmpty = [];
    for (let gx = v.minX; gx <= v.maxX; gx += (v.maxX - v.minX) / 23)
      for (let gy = v.minY; gy <= v.maxY; gy += (v.maxY - v.minY) / 17) {
        if (taken.some(([x, y, hw, hh]) => Math.abs(gx - x) < hw + margin && Math.abs(gy - y) < hh + margin)) continue;
        const pixel = jostlePage.pixel(...jostlePage.toCanvas(0, gx, gy));
        empty++;
        if (!near(pixel, [24, 26, 33])) notEmpty.push([gx, gy, pixel]);
      }
    return {count: boxes.length, checked, wrong, empty, notEmpty};
  })()`);
  check(report.checked >= 10 && report.wrong.length === 0,
        `${report.checked} of ${report.count} bodies drawn in their colour where the module has them` +
        (report.wrong.length ? `: wrong ${JSON.stringify(report.wrong.slice(0, 3))}` : ""));
  check(report.empty >= 50 && report.notEmpty.length === 0,
        `${report.empty} points away from every body show the background` +
        (report.notEmpty.length ? `: not ${JSON.stringify(report.notEmpty.slice(0, 3))}` : ""));
}

/// The package's API on the page (docs/javascript.md): the README's crate falls onto the
/// floor and rests at y 280 (floor top 290, crate 10 high); a bad body throws the loader's
/// message, named by the method and the field; a stale body is refused (api.mjs checks the
/// rest in Node).
async function gameApi(page) {
  const result = await page.evaluate(`(() => {
    const world = jostlePage.state.jostle.createWorld({gravity: [0, 800]});
    world.createBody({type: "static", x: 0, y: 300, hw: 400, hh: 10});
    const crate = world.createBody({x: 0, y: 0, hw: 10, hh: 10, bounce: 0.3});
    for (let i = 0; i < 120; i++) world.step(1 / 60);
    const {y} = crate.position, floor = crate.touching.floor;
    let error = "", staleError = "";
    try { world.createBody({x: 0, y: 0, hw: -1, hh: 10}); } catch (e) { error = e.message; }
    const bodies = world.bodies().length;
    crate.destroy();
    try { crate.velocity; } catch (e) { staleError = e.message; }
    world.destroy();
    return {y, floor, error, staleError, bodies};
  })()`);
  check(Math.abs(result.y - 280) < 0.01 && result.floor,
        `the JS API's crate rests on the floor at y ${result.y} (280)`);
  check(result.error === "createBody: hw: must be > 0", `a body with hw -1 throws: "${result.error}"`);
  check(result.staleError === "velocity: stale BodyId (the body was destroyed)",
        `a destroyed crate is refused: "${result.staleError}"`);
  check(result.bodies === 2, "world.bodies() lists the floor and the crate");
}

/// Keys 1 to 8 switch sample; a scene file loads into a pane of its own, and a bad one
/// is refused with the loader's message, the current sample left as it was.
async function samplesAndScenes(page) {
  const name = "jostlePage.state.page.currentName()";
  await page.press("Digit3");
  check(await page.evaluate(name) === "pyramid", "key 3 opens the pyramid");
  await page.press("Digit7");
  check(await page.evaluate(name) === "slopes", "key 7 opens the slopes");
  const result = await page.evaluate(`(() => {
    const p = jostlePage.state.page;
    let error = "";
    try { p.loadScene('{"bodies": [{"x": 0, "y": 0, "hw": 0, "hh": 1}]}'); } catch (e) { error = e.message; }
    const kept = p.currentName();
    p.loadScene('{"solver": "classic", "bodies": [{"type": "static", "x": 0, "y": 10, "hw": 50, "hh": 5}, {"x": 0, "y": 0, "hw": 2, "hh": 2}]}');
    return {error, kept, name: p.currentName(), panes: p.paneCount(), bodies: p.bodyCount(0),
            model: p.paneModel(0)};
  })()`);
  check(/bodies\[0\]\.hw/.test(result.error) && result.kept === "slopes",
        `a bad scene is refused: "${result.error}"`);
  check(result.name === "scene" && result.panes === 1 && result.bodies === 2 &&
        result.model === "classic", "a scene file loads: one pane, its two bodies, its model");
}

/// A finger: in the tutorial, a short tap on empty space in the physical pane drops a
/// box there (a finger has no right button).
async function touch(page) {
  await page.send("Emulation.setTouchEmulationEnabled", {enabled: true, maxTouchPoints: 1});
  await page.goto(`${page.base}index.html?sample=1`);
  await page.waitUntil("document.title === 'jostle: ready'");
  const count = "jostlePage.state.page.bodies(1).length / 12";
  const before = await page.evaluate(count);
  // Above the scene, where nothing is: the point (400, 0) of the world.
  const [x, y] = await page.evaluate(`(() => {
    const [sx, sy] = jostlePage.state.views[1].toScreen(400, 0);
    const r = document.getElementById("world").getBoundingClientRect();
    return [r.left + sx, r.top + sy];
  })()`);
  await page.send("Input.dispatchTouchEvent", {type: "touchStart", touchPoints: [{x, y}]});
  await page.send("Input.dispatchTouchEvent", {type: "touchEnd", touchPoints: []});
  await page.waitUntil(`${count} === ${before + 1}`, 5);
  const box = await page.evaluate(`(b => Array.from(b.subarray(b.length - 12, b.length - 8)))(jostlePage.state.page.bodies(1))`);
  check(Math.abs(box[0] - 400) < 2 && box[1] < 60,
        `a tap drops a box where the finger is: (${box[0].toFixed(1)}, ${box[1].toFixed(1)}), tapped at (400, 0)`);
  await page.send("Emulation.setTouchEmulationEnabled", {enabled: false});
}

/// The tutorial's two models side by side with the debug view, for docs/web.png.
async function tutorialPicture(page) {
  await page.goto(`${page.base}index.html?sample=1`);
  await page.waitUntil("document.title === 'jostle: ready'");
  await page.press("Tab");
  await page.waitUntil("jostlePage.state.debug");
  await sleep(1500);
  const panes = await page.evaluate("[0, 1].map(i => jostlePage.state.page.paneTitle(i))");
  check(panes.join(" ") === "classic physical", `the tutorial shows both models: ${panes.join(", ")}`);
  fs.writeFileSync(path.join(page.shots, "tutorial.png"), await page.screenshot());
}

async function main() {
  const [pageDir, shots] = process.argv.slice(2);
  fs.mkdirSync(shots, {recursive: true});
  const server = await serve(path.resolve(pageDir));
  const browser = await Browser.launch();
  try {
    const page = await browser.newPage();
    page.base = server.url;
    page.shots = shots;
    await platformer(page);
    await gameApi(page);
    await samplesAndScenes(page);
    await touch(page);
    await tutorialPicture(page);
    check(page.errors.length === 0, `no errors in the page${page.errors.length ? ": " + page.errors.join("; ") : ""}`);
  } finally {
    browser.close();
    server.close();
  }
  console.log(failures === 0 ? "all passed" : `${failures} failed`);
  process.exit(failures === 0 ? 0 : 1);
}

main().catch((error) => {
  console.log(`FAILED: ${error.stack}`);
  process.exit(1);
});
