// page.js: jostle-demo on a web page. The same samples (demo/sample_*.cpp, in the
// module), keys and mouse as the SDL window (docs/demo.md), touch for phones, drawn by
// draw.js. With ?check in the address, the page runs every sample's check instead and
// writes the hashes into its title, for the tests (bindings/web/tests). An ES module: the
// package's API and the samples come from jostle-page.mjs (page_module.js, bundled).
import {loadPage, JostlePage} from "./jostle-page.mjs";

const kStepHz = 60;
const kDt = 1 / kStepHz;
const kSlowMotion = 0.25;   // slow motion plays the world at this fraction of real time
const kLongestFrame = 0.25; // a longer frame (a background tab) counts as this long
const kSpawnHalfPixels = 10; // a right-click box is this many pixels wide, at any scale
const kStatsSmoothing = 1 / 20;
const kPaneGap = 6;

const state = {
  jostle: null,
  page: null,
  names: [],
  current: 0,
  paused: false,
  stepOnce: false,
  slow: false,
  debug: false,
  jumpQueued: false,
  held: new Set(),   // KeyboardEvent.code of the keys held, and the touch pad's buttons
  stepMs: 0,
  accumulator: 0,
  last: null,
  views: [],
  pointer: null,     // {id, pane, grabbed, downAt, x, y} while a pointer is down
};

const canvas = document.getElementById("world");
const ctx = canvas.getContext("2d");

// --- Samples -------------------------------------------------------------------------

function select(index) {
  state.page.release();
  state.current = index;
  state.page.select(index);
  state.accumulator = 0;
  showHeader();
}

function showHeader() {
  const list = document.getElementById("samples");
  list.replaceChildren(...state.names.map((name, i) => {
    const button = document.createElement("button");
    button.textContent = `${i + 1} ${name}`;
    button.className = i === state.current ? "current" : "";
    button.addEventListener("click", () => select(i));
    return button;
  }));
  const letters = state.page.usesLetterKeys();
  const common = "p pause · n step · s slow · r reset";
  document.getElementById("help").textContent = letters
    ? `← → a d run · space jump · ↓ + space drop through · tab debug · ${common} · drag move · right-click box`
    : `tab or d debug · ${common} · drag move · right-click box`;
  document.body.classList.toggle("steered", letters);
  for (const [id, on] of [["debug", state.debug], ["pause", state.paused], ["slow", state.slow]])
    document.getElementById(id).classList.toggle("on", on);
}

function showStats() {
  let bodies = 0;
  const models = [];
  for (let i = 0; i < state.page.paneCount(); i++) {
    bodies += state.page.bodyCount(i);
    models.push(state.page.paneModel(i));
  }
  let text = `bodies ${bodies} · step ${state.stepMs.toFixed(2)} ms · model ${models.join(" | ")} · ${kStepHz} Hz`;
  if (state.paused) text += " · paused";
  if (state.slow) text += " · slow";
  if (state.debug) text += " · debug";
  document.getElementById("stats").textContent = text;
}

// --- Keys ----------------------------------------------------------------------------

function onKey(event) {
  const code = event.code;
  if (/^Digit[1-9]$/.test(code)) {
    const index = Number(code.slice(5)) - 1;
    if (index < state.names.length) select(index);
    return;
  }
  switch (code) {
  case "KeyP": state.paused = !state.paused; break;
  case "KeyN": state.paused = true; state.stepOnce = true; break;
  case "KeyS": state.slow = !state.slow; break;
  case "Tab": state.debug = !state.debug; break;
  // D runs right where a character is steered; elsewhere it is debug, as Tab.
  case "KeyD": if (!state.page.usesLetterKeys()) state.debug = !state.debug; break;
  case "KeyR": select(state.current); break;
  case "Space": case "ArrowUp": case "KeyW": state.jumpQueued = true; break;
  case "Escape": state.page.release(); break;
  default: return;
  }
  showHeader();
}

const kPageKeys = new Set(["Tab", "Space", "ArrowUp", "ArrowDown", "ArrowLeft", "ArrowRight"]);

window.addEventListener("keydown", (event) => {
  if (event.ctrlKey || event.metaKey || event.altKey) return;
  if (kPageKeys.has(event.code)) event.preventDefault(); // no scrolling, no focus moves
  state.held.add(event.code);
  if (!event.repeat) onKey(event);
});
window.addEventListener("keyup", (event) => state.held.delete(event.code));
window.addEventListener("blur", () => state.held.clear());

/// The keys held for this step, as jostle_page_step's bits; a jump once per press.
function keysForStep() {
  const h = state.held;
  const letters = state.page.usesLetterKeys();
  const K = JostlePage.KEYS;
  let keys = 0;
  if (h.has("ArrowLeft") || (letters && h.has("KeyA")) || h.has("pad-left")) keys |= K.left;
  if (h.has("ArrowRight") || (letters && h.has("KeyD")) || h.has("pad-right")) keys |= K.right;
  if (h.has("ArrowUp")) keys |= K.up;
  if (h.has("ArrowDown") || h.has("pad-down")) keys |= K.down;
  if (state.jumpQueued) keys |= K.jump;
  state.jumpQueued = false;
  return keys;
}

// --- Mouse and touch -------------------------------------------------------------------

function paneAt(x, y) {
  return state.views.findIndex((view) => view.contains(x, y));
}

function canvasPoint(event) {
  const r = canvas.getBoundingClientRect();
  return [event.clientX - r.left, event.clientY - r.top];
}

canvas.addEventListener("contextmenu", (event) => event.preventDefault());
canvas.addEventListener("pointerdown", (event) => {
  const [x, y] = canvasPoint(event);
  const pane = paneAt(x, y);
  if (pane < 0) return;
  const view = state.views[pane];
  const [wx, wy] = view.toWorld(x, y);
  if (event.button === 2) {
    state.page.dropBox(pane, wx, wy, kSpawnHalfPixels / view.scale);
    return;
  }
  canvas.setPointerCapture(event.pointerId);
  const grabbed = state.page.grab(pane, wx, wy);
  state.pointer = {id: event.pointerId, pane, grabbed, touch: event.pointerType !== "mouse",
                   downAt: performance.now(), x, y};
});
canvas.addEventListener("pointermove", (event) => {
  if (state.pointer === null || state.pointer.id !== event.pointerId) return;
  const [x, y] = canvasPoint(event);
  const view = state.views[state.pointer.pane];
  if (view) state.page.dragTo(...view.toWorld(x, y));
});
function pointerUp(event) {
  const p = state.pointer;
  if (p === null || p.id !== event.pointerId) return;
  state.pointer = null;
  state.page.release();
  // A finger has no right button: a short tap on empty space drops a box.
  const [x, y] = canvasPoint(event);
  const view = state.views[p.pane];
  if (p.touch && !p.grabbed && view && performance.now() - p.downAt < 300 &&
      Math.hypot(x - p.x, y - p.y) < 10)
    state.page.dropBox(p.pane, ...view.toWorld(x, y), kSpawnHalfPixels / view.scale);
}
canvas.addEventListener("pointerup", pointerUp);
canvas.addEventListener("pointercancel", pointerUp);

/// The touch pad and the toolbar: buttons that hold a key while pressed, or press one.
function wireButtons() {
  for (const button of document.querySelectorAll("[data-hold]")) {
    const name = button.dataset.hold;
    const down = (event) => {
      event.preventDefault();
      state.held.add(name);
      if (name === "pad-jump") state.jumpQueued = true;
    };
    const up = () => state.held.delete(name);
    button.addEventListener("pointerdown", down);
    button.addEventListener("pointerup", up);
    button.addEventListener("pointerleave", up);
    button.addEventListener("pointercancel", up);
  }
  const toolbar = {debug: "Tab", pause: "KeyP", step: "KeyN", slow: "KeyS", reset: "KeyR"};
  for (const [id, code] of Object.entries(toolbar))
    document.getElementById(id).addEventListener("click", () => onKey({code}));
  document.getElementById("scene").addEventListener("change", async (event) => {
    const file = event.target.files[0];
    if (!file) return;
    try {
      state.page.release();
      state.page.loadScene(await file.text());
      state.current = -1;
      showHeader();
      showError("");
    } catch (error) {
      showError(`${file.name}: ${error.message}`);
    }
  });
}

function showError(text) {
  document.getElementById("error").textContent = text;
}

// --- The frame -----------------------------------------------------------------------

function layout() {
  const dpr = window.devicePixelRatio || 1;
  const w = canvas.clientWidth, h = canvas.clientHeight;
  if (canvas.width !== Math.round(w * dpr) || canvas.height !== Math.round(h * dpr)) {
    canvas.width = Math.round(w * dpr);
    canvas.height = Math.round(h * dpr);
  }
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  const count = state.page.paneCount();
  // Side by side; on a narrow screen (a phone held upright), one above the other.
  const across = w >= h || count === 1;
  const views = [];
  for (let i = 0; i < count; i++) {
    const screen = across
      ? {x: kPaneGap + i * ((w - kPaneGap) / count), y: 0, w: (w - kPaneGap) / count - kPaneGap, h}
      : {x: 0, y: kPaneGap + i * ((h - kPaneGap) / count), w, h: (h - kPaneGap) / count - kPaneGap};
    // The world below the pane's title band.
    const below = {x: screen.x, y: screen.y + kTitleHeight, w: screen.w, h: screen.h - kTitleHeight};
    const view = new PaneView(state.page.view(i), below);
    view.screen = screen;
    views.push(view);
  }
  state.views = views;
}

function frame(now) {
  const seconds = state.last === null ? 0 : Math.min((now - state.last) / 1000, kLongestFrame);
  state.last = now;
  state.accumulator += seconds * (state.slow ? kSlowMotion : 1);
  let steps = Math.floor(state.accumulator / kDt);
  state.accumulator -= steps * kDt;
  if (state.paused) steps = state.stepOnce ? 1 : 0;
  state.stepOnce = false;
  for (let i = 0; i < steps; i++) {
    const ms = state.page.step(keysForStep(), kDt);
    state.stepMs += (ms - state.stepMs) * kStatsSmoothing;
  }
  layout();
  ctx.fillStyle = "rgb(17, 18, 23)";
  ctx.fillRect(0, 0, canvas.clientWidth, canvas.clientHeight);
  for (let i = 0; i < state.views.length; i++)
    drawPane(ctx, state.page, i, state.views[i], state.debug, kDt);
  showStats();
  requestAnimationFrame(frame);
}

// --- The check (?check): every sample's hash in the title ------------------------------

function runCheck() {
  const times = [];
  const results = state.names.map((name, i) => {
    const start = performance.now();
    const hash = state.page.check(i);
    times.push(`${name}=${(performance.now() - start).toFixed(1)}`);
    return `${name}=${hash}`;
  });
  const text = `jostle check ${results.join(" ")}`;
  // The milliseconds of each check, beside jostle-web-sample-hashes --time's (docs/web.md).
  document.getElementById("help").textContent = `ms ${times.join(" ")}`;
  document.getElementById("error").textContent = text;
  document.title = text;
}

async function main() {
  try {
    ({jostle: state.jostle, page: state.page} = await loadPage());
  } catch (error) {
    showError(`The module did not load: ${error.message}`);
    document.title = "jostle: failed";
    return;
  }
  state.names = state.page.sampleNames();
  if (new URLSearchParams(location.search).has("check")) {
    runCheck();
    return;
  }
  const first = Number(new URLSearchParams(location.search).get("sample") || 1) - 1;
  select(first >= 0 && first < state.names.length ? first : 0);
  wireButtons();
  document.title = "jostle: ready";
  requestAnimationFrame(frame);
}

// For the tests and the curious: the page's state, the views, and a way to map a point
// of a pane's world onto the canvas's pixels.
window.jostlePage = {
  state,
  toCanvas(pane, x, y) {
    const dpr = window.devicePixelRatio || 1;
    const [sx, sy] = state.views[pane].toScreen(x, y);
    return [Math.floor(sx * dpr), Math.floor(sy * dpr)];
  },
  pixel(px, py) { return Array.from(ctx.getImageData(px, py, 1, 1).data.slice(0, 3)); },
};

main();
