// The level in headless Chromium, three ways a web game loads the package: a page
// importing it as an ES module (module.html), a page loading an esbuild bundle of it
// (bundle.html), and a web worker (worker.html). Each writes what play() returned into
// its title, checked as in Node (expect.cjs) against the C++ version.
//   node browser.cjs <game dir> '<C++ JSON>'    (the game dir run.sh installed)
"use strict";

const path = require("node:path");
const {Browser} = require("../cdp.js");
const {serve} = require("../serve.js");
const expect = require("./expect.cjs");

async function main() {
  const [gameDir, nativeJson] = process.argv.slice(2);
  const native = JSON.parse(nativeJson);
  const server = await serve(path.resolve(gameDir));
  const browser = await Browser.launch();
  let failures = 0;
  try {
    for (const name of ["module.html", "bundle.html", "worker.html"]) {
      const page = await browser.newPage();
      await page.goto(server.url + name);
      await page.waitUntil("document.title !== 'loading'", 30);
      const title = await page.evaluate("document.title");
      if (!title.startsWith("played ")) {
        console.log(`FAIL ${name}: ${title}`);
        failures++;
        continue;
      }
      failures += expect(name, JSON.parse(title.slice("played ".length)), native);
    }
  } finally {
    browser.close();
    server.close();
  }
  process.exitCode = failures === 0 ? 0 : 1;
}

main().catch((error) => {
  console.log(`FAILED: ${error.stack}`);
  process.exitCode = 1;
});
