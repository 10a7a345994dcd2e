// The viewer's worker: it owns the render (the web edition's Render, a RenderSession) and
// steps it when the page asks, so the page never freezes. The page starts it from a Blob
// (a page opened from file:// may not start a worker from a file): renderWorkerMain's
// source, after raycache.js's.
function renderWorkerMain(self, RayCache) {
  let module = null;
  let render = null;
  let running = null;  // 'play' or 'end' while a run goes on
  let runStart = 0;    // performance.now() when the run to the end started
  let runMs = 0;       // milliseconds spent tracing in the run to the end

  function frame(extra) {
    const image = render.image().slice();
    const heat = render.heat().slice();
    const misses = render.missReasons().slice();
    self.postMessage(Object.assign({
      type: 'frame', width: render.width(), height: render.height(), image, heat, misses,
      statistics: JSON.parse(render.statistics()), caption: render.caption(),
      focusPixel: render.focusPixel(), done: render.done(), progress: render.progress(), running,
    }, extra || {}), [image.buffer, heat.buffer, misses.buffer]);
  }

  function tick() {
    if (!running || !render) return;
    const t0 = performance.now();
    // Play: a few rays a frame, to watch; to the end: as many as fit in a quarter second
    if (running === 'play') render.run(50);
    else {
      let more = true;
      while (more && performance.now() - t0 < 250) more = render.run(20000);
    }
    if (running === 'end') runMs += performance.now() - t0;
    if (render.done()) {
      const ms = running === 'end' ? runMs : null;
      running = null;
      frame({ runMs: ms });
      return;
    }
    frame();
    setTimeout(tick, running === 'play' ? 16 : 0);
  }

  self.onmessage = (event) => {
    const m = event.data;
    if (m.type === 'open') {
      running = null;
      if (render) { render.delete(); render = null; }
      let spec = m.scene;
      if (m.nff !== undefined) spec = module.storeSceneFile(m.name || 'dropped.nff', m.nff);
      const error = module.checkScene(spec);
      if (error) { self.postMessage({ type: 'error', message: error }); return; }
      try {
        render = new module.Render(spec, m.width | 0, m.height | 0, m.cache, m.order, m.accel);
      } catch (e) {
        self.postMessage({ type: 'error', message: String(e) });
        return;
      }
      frame({ opened: true });
    } else if (!render) {
      return;
    } else if (m.type === 'ray') {
      running = null; render.run(1); frame();
    } else if (m.type === 'pixel' || m.type === 'miss') {
      running = null; render.runUntil(m.type, 1 << 30); frame();
    } else if (m.type === 'play' || m.type === 'end') {
      const wasRunning = running;
      running = m.type;
      runStart = performance.now();
      runMs = 0;
      if (!wasRunning) tick();
    } else if (m.type === 'pause') {
      running = null; frame();
    }
  };

  RayCache().then((m) => {
    module = m;
    self.postMessage({ type: 'loaded', scenes: module.builtinSceneList(),
                      missReasons: module.missReasonNames().trim().split('\n') });
  });
}
