// The viewer's worker: it owns the render (the web edition's Render, a SessionState) and
// steps it when the page asks, so the page never freezes. Each frame carries the image and
// the overlays the core made for it (shapes of the ray in focus, miss markers, regions,
// frontier, caption). The page starts it from a Blob (a page opened from file:// may not
// start a worker from a file): renderWorkerMain's source, after raycache.js's.
function renderWorkerMain(self, RayCache) {
  let module = null;
  let render = null;
  let running = null;  // 'play' or 'end' while a run goes on
  let runStart = 0;    // when the run to the end was asked for (performance.now())
  let selected = null; // the pixel (and path) selected in both renders: {x, y, path}
  // What the page shows: which overlays, the heatmap, and the image rectangle they are clipped to
  let view = { cylinder: false, hull: false, frontier: false, misses: false, heatmap: false, clip: null };

  let compare = null;   // a second render beside the first (another cache and order), in lockstep

  // What the page draws of one render: its picture at image size, made by the core (the
  // image or the heatmap up to `top`, regions, misses), and the shapes and key of the ray
  // in focus. The image's bytes only once it is complete, for its hash.
  function picture(r, buffers, top) {
    const layer = new Uint8ClampedArray(r.picture(view.heatmap, top, view.misses, view.frontier));
    const image = r.done() ? r.image().slice() : null;
    buffers.push(layer.buffer);
    if (image) buffers.push(image.buffer);
    const w = r.width(), h = r.height();
    const c = view.clip || [0, 0, w, h];
    // The margin keeps cut edges off the picture (as the Qt GUI's)
    const mx = (c[2] - c[0]) * 0.05 + 1, my = (c[3] - c[1]) * 0.05 + 1;
    const shapes = view.cylinder || view.hull
      ? r.shapes(view.cylinder, view.hull, c[0] - mx, c[1] - my, c[2] + mx, c[3] + my) : [];
    return {
      width: w, height: h, layer, image, heatTop: top, shapes,
      frontier: view.frontier ? r.frontier() : null, legend: r.legend(),
      keys: JSON.parse(r.keys(view.cylinder, view.hull, view.frontier, view.misses)),
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
    // Stepping clears a render's selection: the pixel selected in the first stays selected in both
    if (selected) compare.select(selected.x, selected.y, selected.path);
  }

  function frame(extra) {
    const buffers = [];
    syncCompare();
    // One heatmap scale for both renders side by side
    const top = view.heatmap ? Math.max(render.heatTop(), compare ? compare.heatTop() : 1) : 1;
    const first = picture(render, buffers, top);
    const second = compare ? picture(compare, buffers, top) : null;
    if (second) second.compareCaption = render.compareCaption(compare);
    self.postMessage(Object.assign({ type: 'frame' }, first, {
      compare: second, progress: render.progress(), running,
      heapBytes: module.HEAP8.length,  // the WebAssembly memory, for tests/web/page_memory.py
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
    if (render.done()) {
      // Wall time, from the click to the last ray (frames and pauses between slices included)
      const ms = running === 'end' ? performance.now() - runStart : null;
      running = null;
      frame({ runMs: ms });
      return;
    }
    frame();
    setTimeout(tick, running === 'play' ? 16 : 0);
  }

  // A tour stop's rays (rc::applyStopRays): its steps, its run to a miss, its selection
  function goToStop(m) {
    const applied = JSON.parse(render.applyStop(m.tour, m.stop));
    selected = applied.selected;
    syncCompare();
    return applied.notes;
  }

  // The stop's claims, checked by the core on what the page draws (rc::checkClaim)
  function claims(m) {
    if (!render) return { error: 'no picture' };
    const given = JSON.stringify(m.claims || []);
    return JSON.parse(compare ? render.claimsCompared(m.tour, m.stop, given, compare)
                              : render.claims(m.tour, m.stop, given));
  }

  // A new render (and the compared one) of the scene, size and choices the page asks for,
  // on to the tour stop's rays when it shows one
  function openRender(m) {
    running = null;
    selected = null;
    if (m.view) view = m.view;
    if (render) { render.delete(); render = null; }
    if (compare) { compare.delete(); compare = null; }
    let spec = m.scene;
    if (m.nff !== undefined) spec = module.storeSceneFile(m.name || 'dropped.nff', m.nff);
    const error = module.checkScene(spec);
    if (error) { self.postMessage({ type: 'error', message: error }); return; }
    let notes = [];
    // A render that cannot be made says why in its error() (the bindings catch C++'s
    // exceptions, which would reach here as bare numbers)
    const make = (cache, order) => {
      const r = new module.Render(spec, m.width | 0, m.height | 0, cache, order, m.accel,
                                 m.band === undefined ? -1 : m.band | 0);
      const why = r.error();
      if (!why) return r;
      r.delete();
      throw new Error(why);
    };
    try {
      render = make(m.cache, m.order);
      if (m.compare) compare = make(m.compare.cache, m.compare.order);
      // The reader's warnings (a polygon of zero area, skipped), named as the CLI names them
      notes = render.warnings().split('\n').filter(Boolean).map((w) => 'warning: ' + w);
      if (m.stop) notes = notes.concat(goToStop(m.stop));
    } catch (e) {
      if (render) { render.delete(); render = null; }
      self.postMessage({ type: 'error', message: e instanceof Error ? e.message : 'the render failed (' + e + ')' });
      return;
    }
    frame({ opened: true, notes });
  }

  self.onmessage = (event) => {
    const m = event.data;
    if (m.type === 'view') {
      view = m.view;
      if (render) frame();
    } else if (m.type === 'claims') {
      self.postMessage(Object.assign({ type: 'claims' }, claims(m)));
    } else if (m.type === 'tour') {
      self.postMessage({ type: 'tour', stop: JSON.parse(module.tourStop(m.tour, m.stop | 0)) });
    } else if (m.type === 'open') {
      openRender(m);
    } else if (!render) {
      // A bad file left no picture: say so rather than do nothing
      if (['ray', 'pixel', 'miss', 'select', 'play', 'end'].includes(m.type))
        self.postMessage({ type: 'error', message: 'There is no picture to trace: open a scene that reads ' +
                           'without errors (the Scene menu, Open file, or drop an NFF file on the picture).' });
      return;
    } else if (m.type === 'ray') {
      running = null; selected = null; render.run(1); frame();
    } else if (m.type === 'pixel' || m.type === 'miss') {
      running = null; selected = null; render.runUntil(m.type, ''); frame();
    } else if (m.type === 'select') {
      const why = render.select(m.x, m.y, '');
      selected = why ? null : { x: m.x, y: m.y, path: '' };
      frame(why ? { notes: [why] } : {});
    } else if (m.type === 'play' || m.type === 'end') {
      const wasRunning = running;
      running = m.type;
      runStart = performance.now();
      selected = null;
      render.clearSelection();
      if (compare) compare.clearSelection();
      if (!wasRunning) tick();
    } else if (m.type === 'pause') {
      running = null; frame();
    }
  };

  RayCache().then((m) => {
    module = m;
    // The menus' choices come from the core's registries (rc::registryListing)
    const registry = {};
    for (const what of ['caches', 'orders', 'searches', 'overlays']) registry[what] = JSON.parse(module.registry(what));
    self.postMessage({ type: 'loaded', scenes: JSON.parse(module.sceneList()), registry, maxSize: module.maxSize,
                       palette: JSON.parse(module.palette()),
                      missReasons: module.missReasonNames().trim().split('\n') });
  });
}
