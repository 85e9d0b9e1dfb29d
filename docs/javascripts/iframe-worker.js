// A Worker for pages read from disk. Chromium refuses `new Worker(url)` on a file:// page, and
// Material's search runs its index in a worker; Material's offline plugin would load a shim for
// this from the web, which a site read offline cannot reach. So on file:// pages the worker's
// script runs in a hidden iframe of the page instead, and messages pass between the two as
// events. The offline plugin adds no shim of its own when a polyfill named like this one is
// listed (mkdocs.yml, extra.polyfills).
(function () {
  "use strict";
  if (location.protocol !== "file:") return;

  class IFrameWorker extends EventTarget {
    constructor(url) {
      super();
      this.onmessage = null;
      this.onerror = null;
      this._pending = [];
      this._frame = document.createElement("iframe");
      this._frame.hidden = true;
      (document.body || document.documentElement).appendChild(this._frame);
      const scope = this._frame.contentWindow;
      // the worker's replies (its global postMessage) come back here, after the current task
      // as a real worker's would
      scope.postMessage = (data) => setTimeout(() => this._emit("message", { data }));
      const script = scope.document.createElement("script");
      script.src = new URL(url, location.href).href;
      script.onload = () => {
        const pending = this._pending;
        this._pending = null;
        pending.forEach((data) => this.postMessage(data));
      };
      script.onerror = () => this._emit("error", { message: `cannot load ${script.src}` });
      scope.document.body.appendChild(script);
    }

    postMessage(data) {
      if (this._pending) {
        this._pending.push(data);
        return;
      }
      const scope = this._frame.contentWindow;
      setTimeout(() => scope.dispatchEvent(new scope.MessageEvent("message", { data })));
    }

    terminate() {
      this._frame.remove();
    }

    _emit(type, init) {
      const event = type === "message" ? new MessageEvent(type, init) : new ErrorEvent(type, init);
      const handler = type === "message" ? this.onmessage : this.onerror;
      if (handler) handler.call(this, event);
      this.dispatchEvent(event);
    }
  }

  window.Worker = IFrameWorker;
  // Material's search worker looks for this name to find its language files beside its script
  window.IFrameWorker = IFrameWorker;
})();
