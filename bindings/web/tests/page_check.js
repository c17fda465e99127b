// The page in headless Chromium, read as a document (--dump-dom): with ?check it runs
// every sample's check and writes the hashes into its title, which must equal what the
// same samples give natively (jostle-web-sample-hashes). A sample is then the same scene
// in the browser as in jostle-demo: same bodies, same random numbers, same steps.
//   node page_check.js <page dir> <jostle-web-sample-hashes>
"use strict";

const {execFile, execFileSync} = require("node:child_process");
const {promisify} = require("node:util");
const path = require("node:path");
const {chromiumOrSkip, kHeadless} = require("./cdp.js");
const {serve} = require("./serve.js");

async function main() {
  const [pageDir, nativeTool] = process.argv.slice(2);
  const chromium = chromiumOrSkip();
  const native = execFileSync(nativeTool, {encoding: "utf8"}).trim();
  const server = await serve(path.resolve(pageDir));
  let dom;
  try {
    // Virtual time: the page's work runs as fast as it can, then the DOM is written.
    // (Asynchronously: the server answers from this process's event loop.)
    ({stdout: dom} = await promisify(execFile)(
      chromium, [...kHeadless, "--virtual-time-budget=60000", "--dump-dom",
                 `${server.url}index.html?check`],
      {encoding: "utf8", timeout: 90000}));
  } finally {
    server.close();
  }
  const title = (dom.match(/<title>([^<]*)<\/title>/) ?? [, "(no title)"])[1];
  console.log(`native:   ${native}`);
  console.log(`chromium: ${title}`);
  const expected = `jostle check ${native}`;
  if (title !== expected) {
    console.log("FAILED: the page's hashes differ from the native ones");
    process.exit(1);
  }
  // Eight samples, each hashed: a page that ran none would not get here.
  if (native.split(" ").length !== 9) {
    console.log("FAILED: expected the nine samples of jostle-demo");
    process.exit(1);
  }
  console.log("the page's samples give the native hashes");
}

main().catch((error) => {
  console.log(`FAILED: ${error.stack}`);
  process.exit(1);
});
