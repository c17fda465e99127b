// Finding and compiling jostle.wasm, wherever the game runs: given as bytes, a compiled
// module, a URL or a Response, or by default beside the package's own file (read from
// disk in Node, fetched in a page or a worker).

/// The compiled WebAssembly.Module of `source`.
export async function compile(source) {
  source = await source;
  if (source instanceof WebAssembly.Module) return source;
  if (source instanceof ArrayBuffer || ArrayBuffer.isView(source)) return WebAssembly.compile(source);
  if (typeof source === "string") source = new URL(source, globalThis.location?.href);
  if (source instanceof URL && source.protocol === "file:") return WebAssembly.compile(await readFile(source));
  if (source instanceof URL) source = await fetch(source);
  if (typeof Response !== "undefined" && source instanceof Response) {
    if (!source.ok) throw new Error(`${source.url}: ${source.status} ${source.statusText}`);
    // Streaming compilation needs the wasm MIME type, which not every server gives.
    if (typeof WebAssembly.compileStreaming === "function" &&
        source.headers.get("Content-Type") === "application/wasm")
      return WebAssembly.compileStreaming(source);
    return WebAssembly.compile(await source.arrayBuffer());
  }
  throw new TypeError("wasm must be bytes, a WebAssembly.Module, a URL or a Response");
}

/// A file's bytes, in Node (and Deno, Bun). The module's name is not written where a
/// bundler would try to bundle it for a page.
async function readFile(url) {
  const fs = "node:fs/promises";
  const {readFile} = await import(/* webpackIgnore: true */ fs);
  return readFile(url);
}
