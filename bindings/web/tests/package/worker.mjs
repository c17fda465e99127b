// The level played in a web worker: the package finds its wasm from its own URL there too.
import {load} from "./node_modules/jostle/jostle.mjs";
import {play} from "./out/platformer.js";

load().then((jostle) => postMessage("played " + JSON.stringify(play(jostle))),
            (error) => postMessage("failed " + error.message));
