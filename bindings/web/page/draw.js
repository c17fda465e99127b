// draw.js: a pane of a sample drawn on a Canvas 2D, as jostle-demo draws it
// (demo/draw_pane.cpp): the world through the library's debug drawing (page.debugDraw,
// canvasDraw below), with debug on its contacts, velocities, touched sides, sleeping
// bodies dimmed and the broadphase's cells; labels, the title and the legend.
"use strict";

/// The page's own colours; the world's are the library's (page.palette()).
const Palette = {
  background: [24, 26, 33],
  text: [230, 230, 230],
  textDim: [120, 124, 135],
  highlight: [255, 210, 90],
  border: [60, 64, 76],
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

/// A debug-draw colour (0xRRGGBBAA) as CSS writes it (the package's cssColour).
const css = (colour) => `#${colour.toString(16).padStart(8, "0")}`;

/// The game's renderer for the library's debug drawing (docs/debug-draw.md): what it
/// calls, in world units, drawn on the canvas through the pane's view.
function canvasDraw(ctx, view) {
  const path = (fill, outline) => {
    if ((fill & 255) !== 0) {
      ctx.fillStyle = css(fill);
      ctx.fill();
    }
    ctx.strokeStyle = css(outline);
    ctx.stroke();
  };
  const rect = (x, y, hw, hh) => {
    const [sx, sy] = view.toScreen(x - hw, y - hh);
    return [sx, sy, Math.max(2 * hw * view.scale, 1), Math.max(2 * hh * view.scale, 1)];
  };
  return {
    line(x1, y1, x2, y2, colour) {
      const [ax, ay] = view.toScreen(x1, y1), [bx, by] = view.toScreen(x2, y2);
      ctx.strokeStyle = css(colour);
      ctx.beginPath();
      ctx.moveTo(ax, ay);
      ctx.lineTo(bx, by);
      ctx.stroke();
    },
    box(x, y, hw, hh, fill, outline) {
      ctx.beginPath();
      ctx.rect(...rect(x, y, hw, hh));
      path(fill, outline);
    },
    roundedBox(x, y, hw, hh, radius, fill, outline) {
      ctx.beginPath();
      ctx.roundRect(...rect(x, y, hw, hh), radius * view.scale);
      path(fill, outline);
    },
    triangle(x1, y1, x2, y2, x3, y3, fill, outline) {
      ctx.beginPath();
      ctx.moveTo(...view.toScreen(x1, y1));
      ctx.lineTo(...view.toScreen(x2, y2));
      ctx.lineTo(...view.toScreen(x3, y3));
      ctx.closePath();
      path(fill, outline);
    },
    point(x, y, size, colour) {
      const [sx, sy] = view.toScreen(x, y);
      ctx.fillStyle = css(colour);
      ctx.fillRect(sx - 1.5, sy - 1.5, 3, 3);
    },
  };
}

/// Marks with no length of their own (a contact's normal, a segment's tick), in pixels.
const kMarkPixels = 14;

/// What the debug marks mean, each word in its mark's colour, and which grid the
/// broadphase picture shows.
function drawLegend(ctx, screen, grid, palette) {
  const dimmed = [24, 16, 8].map((shift) =>
    Math.floor(((palette.dynamicBody >>> shift) & 255) * palette.sleepingPercent / 100));
  const words = [[css(palette.contact), "contacts"], [css(palette.touching), "sides touched"],
                 [css(palette.velocity), "velocity"], [`rgb(${dimmed.join(", ")})`, "asleep"],
                 [css(palette.gridBox), "moving boxes"], [css(palette.gridCell), "grid cells"]];
  ctx.font = "12px ui-monospace, monospace";
  let x = screen.x + 10;
  const y = screen.y + kTitleHeight + 16;
  const plate = (text, at) => {
    ctx.fillStyle = rgb(Palette.background);
    ctx.fillRect(screen.x + 6, at - 12, ctx.measureText(text).width + 8, 17);
  };
  plate(words.map(([, w]) => w).join("  ") + "    ", y);
  for (const [colour, word] of words) {
    ctx.fillStyle = colour;
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
  const [minX, minY] = view.toWorld(s.x, s.y + kTitleHeight);
  const [maxX, maxY] = view.toWorld(s.x + s.w, s.y + s.h);
  page.debugDraw(index, canvasDraw(ctx, view), debug, kMarkPixels / view.scale, {minX, minY, maxX, maxY});
  const grid = debug ? page.grid(index, dt) : null;
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
  ctx.strokeStyle = rgb(Palette.border);
  ctx.beginPath();
  ctx.moveTo(s.x, s.y + kTitleHeight - 0.5);
  ctx.lineTo(s.x + s.w, s.y + kTitleHeight - 0.5);
  ctx.stroke();
  if (debug) drawLegend(ctx, s, grid, page.palette());
  ctx.strokeStyle = rgb(Palette.border);
  ctx.strokeRect(s.x + 0.5, s.y + 0.5, s.w - 1, s.h - 1);
  ctx.restore();
}
