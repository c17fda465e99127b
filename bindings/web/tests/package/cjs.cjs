// The level played through `require` (the package's CommonJS file): node cjs.cjs '<C++ JSON>'
"use strict";
const {load} = require("jostle");
const expect = require("./expect.cjs");

(async () => {
  const {play} = await import("./out/platformer.js");
  const native = JSON.parse(process.argv[2]);
  process.exitCode = expect("require", play(await load()), native) === 0 ? 0 : 1;
})().catch((error) => {
  console.error(error);
  process.exitCode = 1;
});
