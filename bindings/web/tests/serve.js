// serve.js: the page's directory over HTTP on 127.0.0.1, on a free port, for the tests
// (the page loads its .wasm by fetch, which file:// does not allow). scripts/web.sh
// serves it with python3 -m http.server instead.
"use strict";

const http = require("node:http");
const fs = require("node:fs");
const path = require("node:path");

const kTypes = {".html": "text/html", ".js": "text/javascript", ".mjs": "text/javascript", ".css": "text/css",
                ".wasm": "application/wasm", ".json": "application/json"};

/// Resolves to {url, close()}: the server of `directory`, its address ending in "/".
function serve(directory) {
  const server = http.createServer((request, response) => {
    const name = decodeURIComponent(new URL(request.url, "http://x").pathname);
    const file = path.join(directory, name === "/" ? "index.html" : path.normalize(name));
    if (!file.startsWith(directory)) {
      response.writeHead(403).end();
      return;
    }
    fs.readFile(file, (error, data) => {
      if (error) {
        response.writeHead(404).end();
        return;
      }
      response.writeHead(200, {"Content-Type": kTypes[path.extname(file)] ?? "text/plain"});
      response.end(data);
    });
  });
  return new Promise((resolve) => {
    server.listen(0, "127.0.0.1", () => resolve({
      url: `http://127.0.0.1:${server.address().port}/`,
      close: () => server.close(),
    }));
  });
}

module.exports = {serve};
