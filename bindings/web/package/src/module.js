// The module's loader: instantiates jostle.wasm, a standalone WebAssembly module (its
// functions exported by their C names, WASI's few imports), and gives the package what
// it calls: each C function as `_name`, views of the heap (made anew when the memory
// grows), UTF-8 strings in and out, and the two callbacks the C side calls (the package
// sets `jostlePreSolve` and `jostleMoveFilter` on the object).

const decoder = new TextDecoder();
const encoder = new TextEncoder();

/// The module object of the compiled WebAssembly.Module `wasm`.
export async function instantiate(wasm) {
  let m = null, memory = null;
  // The heap's views, made anew when the module's memory grows (it says so: growing
  // detaches the old buffer). Plain properties: a getter checking the buffer at each use
  // tripled the cost of a body's getter.
  const renewViews = () => {
    const buffer = memory.buffer;
    m.HEAP8 = new Int8Array(buffer);
    m.HEAPU8 = new Uint8Array(buffer);
    m.HEAP32 = new Int32Array(buffer);
    m.HEAPU32 = new Uint32Array(buffer);
    m.HEAPF32 = new Float32Array(buffer);
  };
  const helpers = {
    UTF8ToString(at) {
      const bytes = m.HEAPU8;
      let end = at;
      while (bytes[end] !== 0) end++;
      return decoder.decode(bytes.subarray(at, end));
    },
    lengthBytesUTF8: (text) => encoder.encode(text).length,
    stringToUTF8(text, at, size) {
      const {written} = encoder.encodeInto(text, m.HEAPU8.subarray(at, at + size - 1));
      m.HEAPU8[at + written] = 0;
    },
  };

  // What the module writes to stdout and stderr (nothing in normal use), by lines.
  const lines = {1: "", 2: ""};
  const wasi = {
    fd_write(fd, iovs, count, writtenAt) {
      const words = m.HEAPU32;
      let written = 0;
      for (let i = 0; i < count; i++) {
        const at = words[(iovs >> 2) + 2 * i], length = words[(iovs >> 2) + 2 * i + 1];
        lines[fd] = (lines[fd] ?? "") + decoder.decode(m.HEAPU8.subarray(at, at + length));
        written += length;
      }
      const parts = lines[fd].split("\n");
      lines[fd] = parts.pop();
      for (const line of parts) (fd === 2 ? console.error : console.log)(line);
      words[writtenAt >> 2] = written;
      return 0;
    },
    fd_close: () => 0,
    fd_seek: () => 0,
    // Nanoseconds, as a 64-bit integer: the step's profile times its stages by it.
    clock_time_get(clock, precision, at) {
      const ms = clock === 0 ? Date.now() : performance.now();
      new DataView(memory.buffer).setBigUint64(at, BigInt(Math.round(ms * 1e6)), true);
      return 0;
    },
    proc_exit(code) {
      throw new Error(`jostle.wasm stopped (exit code ${code})`);
    },
  };
  const env = {
    jostle_js_pre_solve: (collision, context) => (m.jostlePreSolve(collision, context) ? 1 : 0),
    jostle_js_move_filter: (other, context) => m.jostleMoveFilter(other, context),
    emscripten_notify_memory_growth: () => renewViews(),
  };
  const instance = await WebAssembly.instantiate(wasm, {env, wasi_snapshot_preview1: wasi});
  const exports = instance.exports;
  // Made at once, every property there from the start (the views and callbacks are set
  // later): an object given 170 properties one computed name at a time is kept as a
  // dictionary by V8, and every call looking its function up paid for it (a body's
  // getter 32 ns against 21).
  const functions = Object.entries(exports).filter(([, value]) => typeof value === "function")
    .map(([name, value]) => [`_${name}`, value]);
  const views = ["HEAP8", "HEAPU8", "HEAP32", "HEAPU32", "HEAPF32"].map((name) => [name, null]);
  m = Object.fromEntries([...functions, ...Object.entries(helpers), ...views,
    ["jostlePreSolve", null], ["jostleMoveFilter", null]]);
  memory = exports.memory;
  renewViews();
  exports._initialize(); // the C++ library's static constructors
  return m;
}
