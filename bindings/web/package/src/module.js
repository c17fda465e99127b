// The module's loader: instantiates jostle.wasm, a standalone WebAssembly module (its
// functions exported by their C names, WASI's few imports), and gives the package what
// it calls: each C function as `_name`, views of the heap (made anew when the memory
// grows), UTF-8 strings in and out, and the two callbacks the C side calls (the package
// sets `jostlePreSolve` and `jostleMoveFilter` on the object).

const decoder = new TextDecoder();
const encoder = new TextEncoder();

/// The module object of the compiled WebAssembly.Module `wasm`.
export async function instantiate(wasm) {
  const m = {};
  let memory = null, buffer = null;
  let views = {};
  const view = (Type) => {
    if (memory.buffer !== buffer) { // grown: every view is of the old buffer
      buffer = memory.buffer;
      views = {};
    }
    return (views[Type.name] ??= new Type(buffer));
  };
  Object.defineProperties(m, {
    HEAP8: {get: () => view(Int8Array)},
    HEAPU8: {get: () => view(Uint8Array)},
    HEAP32: {get: () => view(Int32Array)},
    HEAPU32: {get: () => view(Uint32Array)},
    HEAPF32: {get: () => view(Float32Array)},
  });
  m.UTF8ToString = (at) => {
    const bytes = m.HEAPU8;
    let end = at;
    while (bytes[end] !== 0) end++;
    return decoder.decode(bytes.subarray(at, end));
  };
  m.lengthBytesUTF8 = (text) => encoder.encode(text).length;
  m.stringToUTF8 = (text, at, size) => {
    const {written} = encoder.encodeInto(text, m.HEAPU8.subarray(at, at + size - 1));
    m.HEAPU8[at + written] = 0;
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
    emscripten_notify_memory_growth: () => {}, // the views are checked at each use
  };
  const instance = await WebAssembly.instantiate(wasm, {env, wasi_snapshot_preview1: wasi});
  const exports = instance.exports;
  memory = exports.memory;
  exports._initialize(); // the C++ library's static constructors
  for (const [name, value] of Object.entries(exports))
    if (typeof value === "function") m[`_${name}`] = value;
  return m;
}
