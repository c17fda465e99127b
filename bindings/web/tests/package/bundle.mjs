// The level bundled into one file by esbuild (bundle.html loads it): the package resolved
// from node_modules as any dependency, its wasm copied beside the bundle.
import {load} from "jostle";
import {play} from "./out/platformer.js";

load().then((jostle) => { document.title = "played " + JSON.stringify(play(jostle)); },
            (error) => { document.title = "failed " + error.message; });
