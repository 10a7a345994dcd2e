// The viewer's worker: it owns the render (the web edition's Render, a SessionState) and
// steps it when the page asks, so the page never freezes. Each frame carries the picture and
// the overlays the core made for it (shapes of the ray in focus, miss markers, regions,
// frontier, caption). The page starts it from a Blob (a page opened from file:// may not
// start a worker from a file): the sources of renderWorkerParts, after raycache.js's, then a
// call of renderWorkerMain. Its state is one object, `w`, handed to each part.
// `wasmApart`: the source has no WebAssembly (the page took raycache.js's base64 copy out
// of it), whose bytes come in the first message.
function renderWorkerMain(self, RayCache, wasmApart) {
  const w = {
    self, module: null, render: null,
    compare: null,   // a second render beside the first (another cache and order), in lockstep
    running: null,   // 'play' or 'end' while a run goes on
    runStart: 0,     // when the run to the end was asked for (performance.now())
    selected: null,  // the pixel (and path) selected in both renders: {x, y, path}
    canvas: null,    // an OffscreenCanvas the pictures are put together in, a band at a time
    // What the page shows: which overlays, the heatmap, and the image rectangle they are clipped to
    view: { cylinder: false, hull: false, frontier: false, misses: false, heatmap: false, clip: null },
  };
  self.onmessage = (event) => workerMessage(w, event.data);
  if (!wasmApart) workerStart(w, null);
}

// Loads the core: from the bytes the page sent (compiled here, then let go: the worker
// keeps no copy of them, as text or bytes), else from the data URI in raycache.js's source
function workerStart(w, bytes) {
  const options = {};
  if (bytes) {
    options.instantiateWasm = (imports, done) => {
      const wasm = bytes;
      bytes = null;
      WebAssembly.instantiate(wasm, imports).then((r) => done(r.instance, r.module));
      return {};
    };
  }
  RayCache(options).then((m) => workerLoaded(w, m));
}

// What the page draws of one render: its picture at image size, made by the core (the
// image or the heatmap up to `top`, regions, misses), and the shapes and key of the ray
// in focus. The image's bytes once it is complete, for its hash (`hashed`: the page shows the first
// render's only).
function workerPicture(w, r, buffers, top, hashed) {
  const view = w.view;
  const layer = workerBitmap(w, r, view.heatmap, top, view.misses, view.frontier);
  // Once a render: the frames after its end (a click, a toggle) need no second hash
  const image = hashed && r.done() && w.hashedRender !== r ? workerImageBytes(r) : null;
  if (image) w.hashedRender = r;
  buffers.push(layer);
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

// Rows of a band of `width` pixels: the core writes the picture and the image a band at a
// time (a quarter MB of RGBA), so no image-sized buffer is held in its memory or here
function workerBandRows(width) { return Math.max(1, Math.floor(65536 / Math.max(1, width))); }

// The picture as an ImageBitmap, for the page to draw: the core's bands put into the
// worker's canvas straight from its memory, then handed over (the canvas keeps nothing)
function workerBitmap(w, r, heatmap, top, misses, regions) {
  const width = r.width(), height = r.height(), rows = workerBandRows(width);
  if (!w.canvas) w.canvas = new OffscreenCanvas(width, height);
  if (w.canvas.width !== width || w.canvas.height !== height) { w.canvas.width = width; w.canvas.height = height; }
  const g = w.canvas.getContext('2d');
  r.beginPicture(heatmap, top, misses, regions);
  for (let y = 0; y < height; y += rows) {
    const band = r.pictureRows(y, rows);
    const n = band.length / (4 * width);
    g.putImageData(new ImageData(new Uint8ClampedArray(band.buffer, band.byteOffset, band.length), width, n), 0, y);
  }
  r.endPicture();
  return w.canvas.transferToImageBitmap();
}

// The 8-bit RGB image, rows top to bottom, put together from the core's bands (no image
// buffer in the core's memory), for the page to hash with Web Crypto as `raycache render
// --hash` does; handed over, not copied, and dropped once hashed
function workerImageBytes(r) {
  const width = r.width(), height = r.height(), rows = workerBandRows(width);
  const image = new Uint8Array(width * height * 3);
  for (let y = 0; y < height; y += rows) image.set(r.imageRows(y, rows), y * width * 3);
  return image;
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
    generation: w.generation,          // the page's number of the open it answers
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
  w.generation = m.generation;
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
  if (m.type === 'wasm') {
    workerStart(w, m.bytes);
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
const renderWorkerParts = [renderWorkerMain, workerStart, workerPicture, workerBandRows, workerBitmap, workerImageBytes, workerSyncCompare, workerFrame, workerTick, workerGoToStop,
                           workerClaims, workerOpen, workerStep, workerMessage, workerLoaded];
