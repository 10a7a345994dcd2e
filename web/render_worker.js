// The viewer's worker: it owns the render (the web edition's Render, a SessionState) and
// steps it when the page asks, so the page never freezes. Each frame carries the image and
// the overlays the core made for it (shapes of the ray in focus, miss markers, regions,
// frontier, caption). The page starts it from a Blob (a page opened from file:// may not
// start a worker from a file): renderWorkerMain's source, after raycache.js's.
function renderWorkerMain(self, RayCache) {
  let module = null;
  let render = null;
  let running = null;  // 'play' or 'end' while a run goes on
  let runMs = 0;       // milliseconds spent tracing in the run to the end
  // What the page shows: which overlays, and the image rectangle they are clipped to
  let view = { cylinder: false, hull: false, frontier: false, misses: false, clip: null };

  let compare = null;   // a second render beside the first (another cache and order), in lockstep

  // What the page draws of one render
  function picture(r, buffers) {
    const image = r.image().slice();
    const heat = r.heat().slice();
    const misses = view.misses ? r.missReasons().slice() : new Uint8Array(0);
    const regions = view.frontier ? r.regions().slice() : new Uint8Array(0);
    buffers.push(image.buffer, heat.buffer, misses.buffer, regions.buffer);
    const w = r.width(), h = r.height();
    const c = view.clip || [0, 0, w, h];
    // The margin keeps cut edges off the picture (as the Qt GUI's)
    const mx = (c[2] - c[0]) * 0.05 + 1, my = (c[3] - c[1]) * 0.05 + 1;
    const shapes = view.cylinder || view.hull
      ? r.shapes(view.cylinder, view.hull, c[0] - mx, c[1] - my, c[2] + mx, c[3] + my) : [];
    return {
      width: w, height: h, image, heat, misses, regions, shapes,
      frontier: view.frontier ? r.frontier() : null, legend: r.legend(),
      statistics: JSON.parse(r.statistics()), caption: r.caption(),
      focusPixel: r.focusPixel(), selectedPixel: r.selectedPixel(), done: r.done(),
    };
  }

  // The compared render goes to the first's step: every render has the same rays, so
  // when the first is done, so is the second
  function syncCompare() {
    if (!compare) return;
    compare.runToStep(render.steps());
    if (render.done() && !compare.done()) compare.run(1 << 30);
  }

  function frame(extra) {
    const buffers = [];
    syncCompare();
    const first = picture(render, buffers);
    const second = compare ? picture(compare, buffers) : null;
    self.postMessage(Object.assign({ type: 'frame' }, first, {
      compare: second, progress: render.progress(), running,
    }, extra || {}), buffers);
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

  // A tour stop's rays: its steps, then on to the miss it shows, then its selection
  function goToStop(m) {
    const notes = [];
    if (m.steps > 0) render.runToStep(m.steps);
    if (m.run === 'next-miss') {
      if (!render.runUntil('miss', m.missReason || '')) notes.push('no such miss before the end');
    } else if (m.run) {
      notes.push('run ' + m.run + ': not in the web viewer');
    }
    if (m.showcase) render.showcase();
    if (m.select) {
      const [xy, path] = m.select.split(':');
      const [x, y] = xy.split(',').map(Number);
      const why = render.select(x, y, path || '');
      if (why) notes.push('select: ' + why);
      syncCompare();
      if (compare) compare.select(x, y, path || '');
    }
    return notes;
  }

  self.onmessage = (event) => {
    const m = event.data;
    if (m.type === 'view') {
      view = m.view;
      if (render) frame();
    } else if (m.type === 'tour') {
      self.postMessage({ type: 'tour', stop: JSON.parse(module.tourStop(m.tour, m.stop | 0)) });
    } else if (m.type === 'open') {
      running = null;
      if (m.view) view = m.view;
      if (render) { render.delete(); render = null; }
      if (compare) { compare.delete(); compare = null; }
      let spec = m.scene;
      if (m.nff !== undefined) spec = module.storeSceneFile(m.name || 'dropped.nff', m.nff);
      const error = module.checkScene(spec);
      if (error) { self.postMessage({ type: 'error', message: error }); return; }
      let notes = [];
      try {
        render = new module.Render(spec, m.width | 0, m.height | 0, m.cache, m.order, m.accel);
        if (m.compare) compare = new module.Render(spec, m.width | 0, m.height | 0, m.compare.cache, m.compare.order, m.accel);
        if (m.stop) notes = goToStop(m.stop);
      } catch (e) {
        self.postMessage({ type: 'error', message: String(e) });
        return;
      }
      frame({ opened: true, notes });
    } else if (!render) {
      return;
    } else if (m.type === 'ray') {
      running = null; render.run(1); frame();
    } else if (m.type === 'pixel' || m.type === 'miss') {
      running = null; render.runUntil(m.type, ''); frame();
    } else if (m.type === 'select') {
      const why = render.select(m.x, m.y, '');
      if (compare) compare.select(m.x, m.y, '');
      frame(why ? { notes: [why] } : {});
    } else if (m.type === 'play' || m.type === 'end') {
      const wasRunning = running;
      running = m.type;
      runMs = 0;
      render.clearSelection();
      if (compare) compare.clearSelection();
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
