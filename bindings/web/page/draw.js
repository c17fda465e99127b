// draw.js: a pane of a sample drawn on a Canvas 2D, as jostle-demo draws it
// (demo/draw_pane.cpp): bodies in `jostle render`'s colours, labels, the title, and with
// debug on, sleeping bodies dimmed, the sides each body touched, velocities, contacts and
// the picture of the broadphase grid (demo/grid_picture.hpp) under the bodies.
"use strict";

const Palette = {
  background: [24, 26, 33],
  // Indexed by body type: static grey, kinematic blue, dynamic orange.
  types: [[150, 150, 150], [70, 130, 230], [240, 150, 60]],
  outlinePercent: 60,
  sleepingPercent: 55,
  text: [230, 230, 230],
  textDim: [120, 124, 135],
  highlight: [255, 210, 90],
  border: [60, 64, 76],
  touching: [230, 60, 60],
  velocity: [90, 220, 120],
  contact: [250, 250, 120],
  bullet: [255, 255, 255],
  // The broadphase picture, under the bodies: cell lines just off the background, the
  // main level's cells that hold boxes tinted, other levels' cells outlined, grown boxes.
  gridLine: [40, 44, 58],
  gridTint: "rgba(80, 190, 230, 0.16)",
  gridOutline: [50, 110, 140],
  grownBox: [110, 220, 250],
};

function rgb([r, g, b], percent = 100) {
  const s = (c) => Math.floor((c * percent) / 100);
  return `rgb(${s(r)}, ${s(g)}, ${s(b)})`;
}

/// How a pane shows its box of the world: the rule of demo/view.cpp, the box plus a
/// margin of 1/20 of its longer side, fitted at one scale along both axes, centred.
class PaneView {
  constructor(box, screen) {
    const margin = Math.max(box.maxX - box.minX, box.maxY - box.minY) / 20;
    const w = box.maxX - box.minX + 2 * margin;
    const h = box.maxY - box.minY + 2 * margin;
    this.screen = screen; // {x, y, w, h} in CSS pixels
    this.scale = Math.min(screen.w / w, screen.h / h);
    const cx = (box.minX + box.maxX) / 2;
    const cy = (box.minY + box.maxY) / 2;
    this.offsetX = screen.x + screen.w / 2 - cx * this.scale;
    this.offsetY = screen.y + screen.h / 2 - cy * this.scale;
  }
  toScreen(x, y) { return [x * this.scale + this.offsetX, y * this.scale + this.offsetY]; }
  toWorld(sx, sy) { return [(sx - this.offsetX) / this.scale, (sy - this.offsetY) / this.scale]; }
  contains(sx, sy) {
    const s = this.screen;
    return sx >= s.x && sx < s.x + s.w && sy >= s.y && sy < s.y + s.h;
  }
}

/// The band at the top of a pane that holds its title; the world is drawn below it.
const kTitleHeight = 30;
/// Velocity lines show this many seconds of motion.
const kVelocitySeconds = 0.1;

/// The outline of a body's shape as a path: a box, a rounded box, a ramp's triangle or
/// a segment's sloped face (shared/drawn_shape.hpp).
function shapePath(ctx, view, b) {
  const [x, y, hw, hh, , , , , kind, radius, dx, dy] = b;
  const [sx, sy] = view.toScreen(x - hw, y - hh);
  const w = Math.max(2 * hw * view.scale, 1);
  const h = Math.max(2 * hh * view.scale, 1);
  ctx.beginPath();
  if (kind === 1) {
    ctx.roundRect(sx, sy, w, h, radius * view.scale);
  } else if (kind === 2 || kind === 3) {
    // The corner the slope names is cut off: the face runs between its two neighbours.
    const a = view.toScreen(x + dx * hw, y - dy * hh);
    const c = view.toScreen(x - dx * hw, y + dy * hh);
    ctx.moveTo(a[0], a[1]);
    ctx.lineTo(c[0], c[1]);
    if (kind === 2) {
      const right = view.toScreen(x - dx * hw, y - dy * hh);
      ctx.lineTo(right[0], right[1]);
      ctx.closePath();
    }
  } else {
    ctx.rect(sx, sy, w, h);
  }
}

function drawBody(ctx, view, b, debug) {
  const [x, y, hw, hh, vx, vy, type, flags, kind, , dx, dy] = b;
  const awake = (flags & 1) !== 0;
  const sensor = (flags & 4) !== 0;
  const base = Palette.types[type];
  const dimmed = debug && type !== 0 && !awake;
  const fill = rgb(base, dimmed ? Palette.sleepingPercent : 100);
  const outline = (flags & 2) !== 0 ? rgb(Palette.bullet)
    : rgb(base, (dimmed ? Palette.sleepingPercent : 100) * Palette.outlinePercent / 100);
  shapePath(ctx, view, b);
  if (kind === 3) {
    ctx.strokeStyle = fill;
    ctx.stroke();
  } else if (sensor) {
    ctx.strokeStyle = fill;
    ctx.stroke();
  } else {
    ctx.fillStyle = fill;
    ctx.fill();
    ctx.strokeStyle = outline;
    ctx.stroke();
  }
  // A one-way platform: its blocking face bright.
  if (kind === 0 && (dx !== 0 || dy !== 0)) {
    const fx = x + dx * hw, fy = y + dy * hh;
    const ax = dy !== 0 ? hw : 0, ay = dy !== 0 ? 0 : hh;
    line(ctx, view.toScreen(fx - ax, fy - ay), view.toScreen(fx + ax, fy + ay), Palette.text);
  }
  if (!debug || type !== 2 || sensor) return;
  if (kind === 0) {
    const [l, t] = view.toScreen(x - hw, y - hh);
    const [r, bt] = view.toScreen(x + hw, y + hh);
    if (flags & 8) line(ctx, [l, bt], [r, bt], Palette.touching);
    if (flags & 16) line(ctx, [l, t], [r, t], Palette.touching);
    if (flags & 32) line(ctx, [l, t], [l, bt], Palette.touching);
    if (flags & 64) line(ctx, [r, t], [r, bt], Palette.touching);
  }
  if (awake)
    line(ctx, view.toScreen(x, y),
         view.toScreen(x + vx * kVelocitySeconds, y + vy * kVelocitySeconds), Palette.velocity);
}

function line(ctx, [ax, ay], [bx, by], colour) {
  ctx.strokeStyle = rgb(colour);
  ctx.beginPath();
  ctx.moveTo(ax, ay);
  ctx.lineTo(bx, by);
  ctx.stroke();
}

/// Each touching pair: a dot where they meet, a short line along the normal into the
/// body it pushes (at most 14 pixels, or that body's extent).
function drawContacts(ctx, view, contacts) {
  ctx.fillStyle = rgb(Palette.contact);
  for (let i = 0; i < contacts.length; i += 5) {
    const [px, py, nx, ny, along] = contacts.subarray(i, i + 5);
    const [sx, sy] = view.toScreen(px, py);
    ctx.fillRect(sx - 1.5, sy - 1.5, 3, 3);
    const pixels = Math.min(Math.max(along * view.scale, 3), 14);
    line(ctx, [sx, sy], [sx + nx * pixels, sy + ny * pixels], Palette.contact);
  }
}

const kMinCellPixels = 6;   // closer lines would fill the pane rather than show cells
const kMinGrowthPixels = 2; // a grown box is outlined only where its growth shows

/// The broadphase picture, as demo/draw_grid_picture.cpp draws it: each box is filed in
/// the cell of its level that holds its min corner, each cell drawn once.
function drawGrid(ctx, view, grid) {
  const cellSize = (level) => level >= 63 ? Infinity : grid.levelZero * 2 ** level;
  const cells = new Map();
  for (const box of grid.boxes) {
    const cell = cellSize(box.level);
    if (!isFinite(cell)) continue;
    const x = Math.floor(box.minX / cell), y = Math.floor(box.minY / cell);
    cells.set(`${box.level} ${x} ${y}`, [box.level, x, y, cell]);
  }
  const cellPath = ([, x, y, cell]) => {
    const [sx, sy] = view.toScreen(x * cell, y * cell);
    ctx.rect(sx, sy, cell * view.scale, cell * view.scale);
  };
  ctx.fillStyle = Palette.gridTint;
  ctx.beginPath();
  for (const cell of cells.values()) if (cell[0] === grid.mainLevel) cellPath(cell);
  ctx.fill();
  const main = cellSize(grid.mainLevel);
  if (isFinite(main) && main * view.scale >= kMinCellPixels) {
    const s = view.screen;
    const [fromX, fromY] = view.toWorld(s.x, s.y);
    const [toX, toY] = view.toWorld(s.x + s.w, s.y + s.h);
    ctx.strokeStyle = rgb(Palette.gridLine);
    ctx.beginPath();
    for (let i = Math.floor(fromX / main); i <= Math.floor(toX / main) + 1; i++) {
      const x = Math.round(view.toScreen(i * main, 0)[0]) + 0.5;
      ctx.moveTo(x, s.y);
      ctx.lineTo(x, s.y + s.h);
    }
    for (let i = Math.floor(fromY / main); i <= Math.floor(toY / main) + 1; i++) {
      const y = Math.round(view.toScreen(0, i * main)[1]) + 0.5;
      ctx.moveTo(s.x, y);
      ctx.lineTo(s.x + s.w, y);
    }
    ctx.stroke();
  }
  ctx.strokeStyle = rgb(Palette.gridOutline);
  ctx.beginPath();
  for (const cell of cells.values()) if (cell[0] !== grid.mainLevel) cellPath(cell);
  ctx.stroke();
  ctx.strokeStyle = rgb(Palette.grownBox);
  ctx.beginPath();
  for (const box of grid.boxes) {
    if (Math.max(box.growX, box.growY) * view.scale < kMinGrowthPixels) continue;
    const [sx, sy] = view.toScreen(box.minX, box.minY);
    ctx.rect(sx, sy, (box.maxX - box.minX) * view.scale, (box.maxY - box.minY) * view.scale);
  }
  ctx.stroke();
}

/// What the debug marks mean, each word in its mark's colour, and which grid the
/// broadphase picture shows.
function drawLegend(ctx, screen, grid) {
  const words = [[Palette.contact, "contacts"], [Palette.touching, "sides touched"],
                 [Palette.velocity, "velocity"],
                 [Palette.types[2].map((c) => c * Palette.sleepingPercent / 100), "asleep"],
                 [Palette.grownBox, "grown boxes"], [Palette.gridOutline, "grid cells"]];
  ctx.font = "12px ui-monospace, monospace";
  let x = screen.x + 10;
  const y = screen.y + kTitleHeight + 16;
  const plate = (text, at) => {
    ctx.fillStyle = rgb(Palette.background);
    ctx.fillRect(screen.x + 6, at - 12, ctx.measureText(text).width + 8, 17);
  };
  plate(words.map(([, w]) => w).join("  ") + "    ", y);
  for (const [colour, word] of words) {
    ctx.fillStyle = rgb(colour);
    ctx.fillText(word, x, y);
    x += ctx.measureText(word).width + 14;
  }
  const main = grid.levelZero * 2 ** grid.mainLevel;
  const caption = grid.boxes.length === 0 ? "broadphase: no boxes"
    : `${grid.name} grid: ${grid.boxes.length} ${grid.boxes.length === 1 ? "box" : "boxes"}, ` +
      `${grid.inMainLevel} in cells of ${Number(main.toPrecision(3))} (level ${grid.mainLevel})`;
  plate(caption, y + 17);
  ctx.fillStyle = rgb(Palette.textDim);
  ctx.fillText(caption, screen.x + 10, y + 17);
}

/// Draws pane `index` of `page` (a JostlePage) through `view`; steps are `dt` long.
function drawPane(ctx, page, index, view, debug, dt) {
  const s = view.screen;
  ctx.save();
  ctx.beginPath();
  ctx.rect(s.x, s.y, s.w, s.h);
  ctx.clip();
  ctx.fillStyle = rgb(Palette.background);
  ctx.fillRect(s.x, s.y, s.w, s.h);
  ctx.save();
  ctx.beginPath();
  ctx.rect(s.x, s.y + kTitleHeight, s.w, s.h - kTitleHeight);
  ctx.clip();
  ctx.lineWidth = 1;
  const grid = debug ? page.grid(index, dt) : null;
  if (debug) drawGrid(ctx, view, grid);
  const bodies = page.bodies(index);
  for (let i = 0; i < bodies.length; i += 12)
    drawBody(ctx, view, bodies.subarray(i, i + 12), debug);
  if (debug) drawContacts(ctx, view, page.contacts(index));
  ctx.font = "11px ui-monospace, monospace";
  ctx.textAlign = "center";
  ctx.fillStyle = rgb(Palette.text);
  for (const label of page.labels(index)) {
    const [sx, sy] = view.toScreen(label.x, label.y - label.hh);
    ctx.fillText(label.text, sx, sy - 5);
  }
  ctx.restore();
  ctx.textAlign = "left";
  ctx.font = "600 15px ui-sans-serif, system-ui, sans-serif";
  ctx.fillStyle = rgb(Palette.textDim);
  ctx.fillText(page.paneTitle(index).toUpperCase(), s.x + 10, s.y + 20);
  line(ctx, [s.x, s.y + kTitleHeight - 0.5], [s.x + s.w, s.y + kTitleHeight - 0.5], Palette.border);
  if (debug) drawLegend(ctx, s, grid);
  ctx.strokeStyle = rgb(Palette.border);
  ctx.strokeRect(s.x + 0.5, s.y + 0.5, s.w - 1, s.h - 1);
  ctx.restore();
}
