// The viewer's worker: it owns the render (the web edition's Render, a SessionState) and
// steps it when the page asks, so the page never freezes. Each frame carries the picture and
// the overlays the core made for it (shapes of the ray in focus, miss markers, regions,
// frontier, caption). The page starts it from a Blob (a page opened from file:// may not
// start a worker from a file): the sources of renderWorkerParts, after raycache.js's, then a
// call of renderWorkerMain. Its state is one object, `w`, handed to each part.
function renderWorkerMain(self, RayCache) {
  const w = {
    self, module: null, render: null,
    compare: null,   // a second render beside the first (another cache and order), in lockstep
    running: null,   // 'play' or 'end' while a run goes on
    runStart: 0,     // when the run to the end was asked for (performance.now())
    selected: null,  // the pixel (and path) selected in both renders: {x, y, path}
    spares: [],      // picture buffers the page has drawn and given back, to fill again
    // What the page shows: which overlays, the heatmap, and the image rectangle they are clipped to
    view: { cylinder: false, hull: false, frontier: false, misses: false, heatmap: false, clip: null },
  };
  self.onmessage = (event) => workerMessage(w, event.data);
  RayCache().then((m) => workerLoaded(w, m));
}

// What the page draws of one render: its picture at image size, made by the core (the
// image or the heatmap up to `top`, regions, misses), and the shapes and key of the ray
// in focus. The image's bytes only once it is complete, for its hash (`hashed`: the page
// hashes the first render's only).
function workerPicture(w, r, buffers, top, hashed) {
  const view = w.view;
  const picture = r.picture(view.heatmap, top, view.misses, view.frontier);
  const layer = workerSpare(w, picture.length);
  layer.set(picture);
  const image = hashed && r.done() ? r.image().slice() : null;
  buffers.push(layer.buffer);
  if (image) buffers.push(image.buffer);
  const width = r.width(), height = r.height();
  const c = view.clip || [0, 0, width, height];
  // The margin keeps cut edges off the picture (as the Qt GUI's)
  const mx = (c[2] - c[0]) * 0.05 + 1, my = (c[3] - c[1]) * 0.05 + 1;
  const shapes = view.cylinder || view.hull
    ? r.shapes(view.cylinder, view.hull, c[0] - mx, c[1] - my, c[2] + mx, c[3] + my) : [];
  return {
    width, height, layer, image, heatTop: top, shapes,
    frontier: view.frontier ? r.frontier() : null, legend: r.legend(),
    keys: JSON.parse(r.keys(view.cylinder, view.hull, view.frontier, view.misses)),
    statistics: JSON.parse(r.statistics()), caption: r.caption(),
    focusPixel: r.focusPixel(), selectedPixel: r.selectedPixel(), done: r.done(),
  };
}

// A buffer of `n` bytes for a picture: one the page gave back, else a new one. A run sends
// a picture every frame: filling the same two buffers again leaves the page no garbage
function workerSpare(w, n) {
  const i = w.spares.findIndex((b) => b.byteLength === n);
  return new Uint8ClampedArray(i < 0 ? new ArrayBuffer(n) : w.spares.splice(i, 1)[0]);
}

// The compared render goes to the first's step: every render has the same rays, so
// when the first is done, so is the second
function workerSyncCompare(w) {
  if (!w.compare) return;
  w.compare.runToStep(w.render.steps());
  if (w.render.done() && !w.compare.done()) w.compare.run(1 << 30);
  // Stepping clears a render's selection: the pixel selected in the first stays selected in both
  if (w.selected) w.compare.select(w.selected.x, w.selected.y, w.selected.path);
}

function workerFrame(w, extra) {
  const buffers = [];
  workerSyncCompare(w);
  // One heatmap scale for both renders side by side
  const top = w.view.heatmap ? Math.max(w.render.heatTop(), w.compare ? w.compare.heatTop() : 1) : 1;
  const first = workerPicture(w, w.render, buffers, top, true);
  // The page lists the ray tree of the first render only
  first.rayTree = JSON.parse(w.render.rayTree());
  const second = w.compare ? workerPicture(w, w.compare, buffers, top, false) : null;
  if (second) second.compareCaption = w.render.compareCaption(w.compare);
  w.self.postMessage(Object.assign({ type: 'frame' }, first, {
    compare: second, progress: w.render.progress(), running: w.running,
    heapBytes: w.module.HEAP8.length,  // the WebAssembly memory, for tests/web/page_memory.py
  }, extra || {}), buffers);
}

function workerTick(w) {
  if (!w.running || !w.render) return;
  const t0 = performance.now();
  // Play: a few rays a frame, to watch; to the end: as many as fit in a quarter second
  if (w.running === 'play') w.render.run(50);
  else {
    let more = true;
    while (more && performance.now() - t0 < 250) more = w.render.run(20000);
  }
  if (w.render.done()) {
    // Wall time, from the click to the last ray (frames and pauses between slices included)
    const ms = w.running === 'end' ? performance.now() - w.runStart : null;
    w.running = null;
    workerFrame(w, { runMs: ms });
    return;
  }
  workerFrame(w);
  setTimeout(() => workerTick(w), w.running === 'play' ? 16 : 0);
}

// A tour stop's rays (rc::applyStopRays): its steps, its run to a miss, its selection
function workerGoToStop(w, m) {
  const applied = JSON.parse(w.render.applyStop(m.tour, m.stop));
  w.selected = applied.selected;
  workerSyncCompare(w);
  return applied.notes;
}

// The stop's claims, checked by the core on what the page draws (rc::checkClaim)
function workerClaims(w, m) {
  if (!w.render) return { error: 'no picture' };
  const given = JSON.stringify(m.claims || []);
  return JSON.parse(w.compare ? w.render.claimsCompared(m.tour, m.stop, given, w.compare)
                              : w.render.claims(m.tour, m.stop, given));
}

// A new render (and the compared one) of the scene, size and choices the page asks for,
// on to the tour stop's rays when it shows one
function workerOpen(w, m) {
  w.running = null;
  w.selected = null;
  if (m.view) w.view = m.view;
  if (w.render) { w.render.delete(); w.render = null; }
  if (w.compare) { w.compare.delete(); w.compare = null; }
  let spec = m.scene;
  if (m.nff !== undefined) spec = w.module.storeSceneFile(m.name || 'dropped.nff', m.nff);
  const error = w.module.checkScene(spec);
  if (error) { w.self.postMessage({ type: 'error', message: error }); return; }
  let notes = [];
  // A render that cannot be made says why in its error() (the bindings catch C++'s
  // exceptions, which would reach here as bare numbers)
  const make = (cache, order) => {
    const r = new w.module.Render(spec, m.width | 0, m.height | 0, cache, order, m.accel,
                                  m.band === undefined ? -1 : m.band | 0);
    const why = r.error();
    if (!why) return r;
    r.delete();
    throw new Error(why);
  };
  try {
    w.render = make(m.cache, m.order);
    if (m.compare) w.compare = make(m.compare.cache, m.compare.order);
    // The reader's warnings (a polygon of zero area, skipped), named as the CLI names them
    notes = w.render.warnings().split('\n').filter(Boolean).map((line) => 'warning: ' + line);
    if (m.stop) notes = notes.concat(workerGoToStop(w, m.stop));
  } catch (e) {
    if (w.render) { w.render.delete(); w.render = null; }
    w.self.postMessage({ type: 'error', message: e instanceof Error ? e.message : 'the render failed (' + e + ')' });
    return;
  }
  workerFrame(w, { opened: true, notes });
}

// What the page asks of the render once one is open
function workerStep(w, m) {
  const render = w.render;
  if (m.type === 'ray') {
    w.running = null; w.selected = null; render.run(1); workerFrame(w);
  } else if (m.type === 'pixel' || m.type === 'miss') {
    w.running = null; w.selected = null; render.runUntil(m.type, ''); workerFrame(w);
  } else if (m.type === 'select') {
    const why = render.select(m.x, m.y, '');
    w.selected = why ? null : { x: m.x, y: m.y, path: '' };
    workerFrame(w, why ? { notes: [why] } : {});
  } else if (m.type === 'play' || m.type === 'end') {
    const wasRunning = w.running;
    w.running = m.type;
    w.runStart = performance.now();
    w.selected = null;
    render.clearSelection();
    if (w.compare) w.compare.clearSelection();
    if (!wasRunning) workerTick(w);
  } else if (m.type === 'pause') {
    w.running = null; workerFrame(w);
  }
}

function workerMessage(w, m) {
  if (m.type === 'spare') {
    w.spares = w.spares.concat(m.buffers).slice(-2);  // two: the first render's and the compared one's
  } else if (m.type === 'view') {
    w.view = m.view;
    if (w.render) workerFrame(w);
  } else if (m.type === 'claims') {
    w.self.postMessage(Object.assign({ type: 'claims' }, workerClaims(w, m)));
  } else if (m.type === 'tour') {
    w.self.postMessage({ type: 'tour', stop: JSON.parse(w.module.tourStop(m.tour, m.stop | 0)) });
  } else if (m.type === 'open') {
    workerOpen(w, m);
  } else if (w.render) {
    workerStep(w, m);
  } else if (['ray', 'pixel', 'miss', 'select', 'play', 'end'].includes(m.type)) {
    // A bad file left no picture: say so rather than do nothing
    w.self.postMessage({ type: 'error', message: 'There is no picture to trace: open a scene that reads ' +
                         'without errors (the Scene menu, Open file, or drop an NFF file on the picture).' });
  }
}

function workerLoaded(w, module) {
  w.module = module;
  // The menus' choices come from the core's registries (rc::registryListing)
  const registry = {};
  for (const what of ['caches', 'orders', 'searches', 'overlays']) registry[what] = JSON.parse(module.registry(what));
  w.self.postMessage({ type: 'loaded', scenes: JSON.parse(module.sceneList()), registry, maxSize: module.maxSize,
                       palette: JSON.parse(module.palette()),
                       missReasons: module.missReasonNames().trim().split('\n') });
}

// What the page puts in the worker's source, besides raycache.js's factory
const renderWorkerParts = [renderWorkerMain, workerPicture, workerSpare, workerSyncCompare, workerFrame, workerTick, workerGoToStop,
                           workerClaims, workerOpen, workerStep, workerMessage, workerLoaded];
