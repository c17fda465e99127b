// draw.js: a pane of a sample drawn on a Canvas 2D, as jostle-demo draws it
// (demo/draw_pane.cpp): bodies in `jostle render`'s colours, labels, the title, and with
// debug on, sleeping bodies dimmed, the sides each body touched, velocities and contacts.
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

function drawLegend(ctx, screen) {
  const words = [[Palette.contact, "contacts"], [Palette.touching, "sides touched"],
                 [Palette.velocity, "velocity"],
                 [Palette.types[2].map((c) => c * Palette.sleepingPercent / 100), "asleep"]];
  ctx.font = "12px ui-monospace, monospace";
  let x = screen.x + 10;
  const y = screen.y + kTitleHeight + 16;
  const width = words.reduce((sum, [, w]) => sum + ctx.measureText(w).width + 14, 0);
  ctx.fillStyle = rgb(Palette.background);
  ctx.fillRect(x - 4, y - 12, width + 4, 17);
  for (const [colour, word] of words) {
    ctx.fillStyle = rgb(colour);
    ctx.fillText(word, x, y);
    x += ctx.measureText(word).width + 14;
  }
}

/// Draws pane `index` of `page` (a JostlePage) through `view`.
function drawPane(ctx, page, index, view, debug) {
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
  if (debug) drawLegend(ctx, s);
  ctx.strokeStyle = rgb(Palette.border);
  ctx.strokeRect(s.x + 0.5, s.y + 0.5, s.w - 1, s.h - 1);
  ctx.restore();
}
