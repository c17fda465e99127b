// speed.js: each sample's check (240 steps, sample_check.hpp) timed in headless Chromium
// and natively (jostle-web-sample-hashes --time), on this machine; the best of `runs`
// runs of each, in milliseconds. Not a test: docs/web.md has its figures.
//   node speed.js <page dir> <jostle-web-sample-hashes> [runs]
"use strict";

const {execFileSync} = require("node:child_process");
const path = require("node:path");
const {Browser} = require("./cdp.js");
const {serve} = require("./serve.js");

function best(lines) {
  const best = {};
  for (const line of lines)
    for (const pair of line.trim().split(" ")) {
      const [name, ms] = pair.split("=");
      best[name] = Math.min(best[name] ?? Infinity, Number(ms));
    }
  return best;
}

async function main() {
  const [pageDir, nativeTool, runs = "5"] = process.argv.slice(2);
  const native = best(Array.from({length: Number(runs)},
                                 () => execFileSync(nativeTool, ["--time"], {encoding: "utf8"})));
  const server = await serve(path.resolve(pageDir));
  const browser = await Browser.launch();
  const page = await browser.newPage();
  await page.goto(`${server.url}index.html?check`);
  await page.waitUntil("document.title.startsWith('jostle check')", 60);
  const lines = [];
  for (let run = 0; run < Number(runs); run++)
    lines.push(await page.evaluate(`(() => {
      const p = jostlePage.state.page;
      return p.sampleNames().map((name, i) => {
        const start = performance.now();
        p.check(i);
        return name + "=" + (performance.now() - start).toFixed(1);
      }).join(" ");
    })()`));
  browser.close();
  server.close();
  const web = best(lines);
  console.log("| sample | native (ms) | Chromium (ms) | Chromium / native |");
  console.log("|---|---:|---:|---:|");
  for (const name of Object.keys(native))
    console.log(`| ${name} | ${native[name].toFixed(1)} | ${web[name].toFixed(1)} | ` +
                `${(web[name] / native[name]).toFixed(1)} |`);
}

main().catch((error) => {
  console.log(error.stack);
  process.exit(1);
});
