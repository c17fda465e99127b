// cdp.js: a small driver of Debian's Chromium over the DevTools protocol, for the tests,
// with nothing but Node. Chromium is started headless with --remote-debugging-pipe: it
// reads commands from its fd 3 and writes replies and events to its fd 4, each message
// a JSON object ended by a NUL byte (what puppeteer does with pipe: true). A page is a
// target attached in flat mode: its commands carry the session's id.
//
//     const browser = await Browser.launch();
//     const page = await browser.newPage();
//     await page.goto("http://127.0.0.1:8000/");
//     const title = await page.evaluate("document.title");
//     await page.key("ArrowRight", "keyDown");
//     browser.close();
"use strict";

const {spawn} = require("node:child_process");
const fs = require("node:fs");

/// Where Chromium is: $CHROMIUM, or Debian's. Null if neither exists.
function findChromium() {
  for (const path of [process.env.CHROMIUM, "/usr/bin/chromium"])
    if (path && fs.existsSync(path)) return path;
  return null;
}

/// Exits 77, which ctest reads as skipped, where Chromium is missing.
function chromiumOrSkip() {
  const path = findChromium();
  if (path === null) {
    console.log("SKIPPED: chromium is not installed (scripts/setup.sh installs it)");
    process.exit(77);
  }
  return path;
}

/// The headless flags the tests use: no sandbox (root in a container), no GPU, a fixed
/// window, and nothing that reaches the network by itself.
const kHeadless = ["--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
                   "--no-first-run", "--disable-extensions", "--disable-sync",
                   "--mute-audio", "--window-size=1280,760"];

class Browser {
  static async launch(extraArgs = []) {
    const child = spawn(chromiumOrSkip(), [...kHeadless, "--remote-debugging-pipe", ...extraArgs,
                                          "about:blank"],
                        {stdio: ["ignore", "ignore", "ignore", "pipe", "pipe"]});
    const browser = new Browser(child);
    await browser.send("Target.setDiscoverTargets", {discover: true});
    return browser;
  }

  constructor(child) {
    this.child = child;
    this.nextId = 1;
    this.pending = new Map(); // id -> {resolve, reject, method}
    this.listeners = [];      // (message) => void, for events
    let buffer = "";
    child.stdio[4].on("data", (chunk) => {
      buffer += chunk.toString("utf8");
      let end;
      while ((end = buffer.indexOf("\0")) >= 0) {
        this.receive(JSON.parse(buffer.slice(0, end)));
        buffer = buffer.slice(end + 1);
      }
    });
    child.on("exit", () => {
      for (const {reject, method} of this.pending.values())
        reject(new Error(`chromium exited during ${method}`));
      this.pending.clear();
    });
  }

  receive(message) {
    if (message.id === undefined) {
      for (const listener of this.listeners) listener(message);
      return;
    }
    const call = this.pending.get(message.id);
    this.pending.delete(message.id);
    if (message.error) call.reject(new Error(`${call.method}: ${message.error.message}`));
    else call.resolve(message.result);
  }

  /// Sends a command, to the browser or (with sessionId) to a page; resolves to its result.
  send(method, params = {}, sessionId = undefined) {
    const id = this.nextId++;
    const message = {id, method, params};
    if (sessionId !== undefined) message.sessionId = sessionId;
    return new Promise((resolve, reject) => {
      this.pending.set(id, {resolve, reject, method});
      this.child.stdio[3].write(JSON.stringify(message) + "\0");
    });
  }

  /// Resolves to the first event `method` of `sessionId` for which accept(params) holds.
  waitFor(method, sessionId, accept = () => true) {
    return new Promise((resolve) => {
      const listener = (message) => {
        if (message.method === method && message.sessionId === sessionId &&
            accept(message.params)) {
          this.listeners.splice(this.listeners.indexOf(listener), 1);
          resolve(message.params);
        }
      };
      this.listeners.push(listener);
    });
  }

  async newPage() {
    const {targetId} = await this.send("Target.createTarget", {url: "about:blank"});
    const {sessionId} = await this.send("Target.attachToTarget", {targetId, flatten: true});
    const page = new Page(this, sessionId);
    await page.send("Page.enable");
    await page.send("Runtime.enable");
    return page;
  }

  close() {
    this.child.kill();
  }
}

class Page {
  constructor(browser, sessionId) {
    this.browser = browser;
    this.sessionId = sessionId;
    this.errors = []; // uncaught exceptions and console errors of the page
    browser.listeners.push((message) => {
      if (message.sessionId !== sessionId) return;
      if (message.method === "Runtime.exceptionThrown")
        this.errors.push(message.params.exceptionDetails.exception?.description ??
                         message.params.exceptionDetails.text);
      if (message.method === "Runtime.consoleAPICalled" && message.params.type === "error")
        this.errors.push(message.params.args.map((a) => a.value ?? a.description).join(" "));
    });
  }

  send(method, params = {}) {
    return this.browser.send(method, params, this.sessionId);
  }

  /// Navigates and waits for the load event.
  async goto(url) {
    const loaded = this.browser.waitFor("Page.loadEventFired", this.sessionId);
    const {errorText} = await this.send("Page.navigate", {url});
    if (errorText) throw new Error(`${url}: ${errorText}`);
    await loaded;
  }

  /// The value of a JavaScript expression in the page (awaited if it is a promise).
  async evaluate(expression) {
    const {result, exceptionDetails} = await this.send("Runtime.evaluate",
      {expression, returnByValue: true, awaitPromise: true});
    if (exceptionDetails)
      throw new Error(`${expression}: ${exceptionDetails.exception?.description ??
                                        exceptionDetails.text}`);
    return result.value;
  }

  /// Polls `expression` until it is truthy; throws after `seconds`.
  async waitUntil(expression, seconds = 10) {
    const end = Date.now() + seconds * 1000;
    for (;;) {
      const value = await this.evaluate(expression);
      if (value) return value;
      if (Date.now() > end) throw new Error(`timed out waiting for ${expression}`);
      await sleep(50);
    }
  }

  /// A key event, by its KeyboardEvent.code: type is "keyDown" or "keyUp".
  async key(code, type) {
    const keys = {ArrowLeft: [37, "ArrowLeft"], ArrowRight: [39, "ArrowRight"],
                  ArrowUp: [38, "ArrowUp"], ArrowDown: [40, "ArrowDown"], Space: [32, " "],
                  Tab: [9, "Tab"], KeyP: [80, "p"], KeyD: [68, "d"], KeyR: [82, "r"]};
    const [keyCode, key] = keys[code] ?? [code.charCodeAt(code.length - 1), code.slice(-1)];
    await this.send("Input.dispatchKeyEvent", {type, code, key,
                                               windowsVirtualKeyCode: keyCode});
  }

  async press(code) {
    await this.key(code, "keyDown");
    await this.key(code, "keyUp");
  }

  /// A PNG of the page, as a Buffer.
  async screenshot() {
    const {data} = await this.send("Page.captureScreenshot", {format: "png"});
    return Buffer.from(data, "base64");
  }
}

function sleep(ms) {
  return new Promise((resolve) => setTimeout(resolve, ms));
}

module.exports = {Browser, chromiumOrSkip, kHeadless, sleep};
