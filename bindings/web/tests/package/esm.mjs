// The level played through `import` (the package's ES module): node esm.mjs '<C++ JSON>'
import {load} from "jostle";
import {play} from "./out/platformer.js";
import expect from "./expect.cjs";

const native = JSON.parse(process.argv[2]);
process.exitCode = expect("import", play(await load()), native) === 0 ? 0 : 1;
