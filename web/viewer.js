// The viewer page: controls, the canvas, the statistics. The render itself runs in a
// worker (render_worker.js) that owns the web edition's Render; every overlay comes from
// the core through it (the shapes of the ray in focus, the miss markers, the regions and
// frontier of the fill, the caption): this file only styles them, by role.
// Its declarations are the page's own, at the top level of this script (a classic script:
// raycache.js and render_worker.js declare only RayCache, renderWorkerMain, worker* and
// renderWorkerParts).
const $ = (id) => document.getElementById(id);
const params = new URLSearchParams(location.search);
const canvas = $('canvas');
const context = canvas.getContext('2d');
// The pictures at image size, the first render's and the compared one's: the ImageBitmaps the
// worker made of the last frame's (each closed when the next comes, so only one is held)
const layers = [null, null];
let last = null;        // the last frame the worker sent
let dropped = null;     // {name, text} of a dropped NFF file
let worker = null;
let generation = 0;     // renders opened so far: a hash written late for an earlier one is dropped
let pendingRun = null;  // ?run=end: run to the end once the render is open
let stop = null;        // the tour stop shown (?tour=NAME&stop=K), as the core read it
let viewRect = null;    // the image rectangle shown [x0, y0, x1, y1] (null: the whole image)
let zoomAbout = 0;      // a stop's zoom, about the pixel in focus, once the render is open
if (params.get('embed') === '1') document.body.classList.add('embed');

// The colours, role styles and heatmap ramp are the core's (view/palette.h, which the Qt
// GUI draws with too), sent by the worker when the web edition has loaded (usePalette); the
// picture's own colours (heatmap, regions, misses) the core sets in it
let kRay, kQueued, kDeferred, kSelection, kMissText, kDeferredText;
let kRoleStyles = {}, kRamp = [[0, 0, 0]];
function usePalette(p) {
  const c = p.colours;
  [kRay, kQueued, kDeferred, kSelection] = [c.ray, c.queued, c.deferred, c.selection];
  [kMissText, kDeferredText] = [c.missText, c.deferredText];
  kRoleStyles = p.roles;
  kRamp = p.ramp;
}
const rgba = (c, a) => 'rgba(' + c[0] + ',' + c[1] + ',' + c[2] + ',' + (a === undefined ? 1 : a / 255) + ')';

// The worker, from a Blob: raycache.js's factory and the worker's parts (render_worker.js),
// as source text, then a call of renderWorkerMain. The factory carries the WebAssembly as a
// base64 data URI (-sSINGLE_FILE): the worker gets its bytes in a message instead, so that
// it holds no text copy of them (its source, and the string the factory would make of it)
function startWorker() {
  let factory = RayCache.toString(), wasm = null;
  const prefix = 'wasmBinaryFile="data:application/octet-stream;base64,';
  const begin = factory.indexOf(prefix) + prefix.length, end = factory.indexOf('"', begin);
  if (begin >= prefix.length && end > begin) {
    const text = atob(factory.slice(begin, end));
    wasm = new Uint8Array(text.length);
    for (let i = 0; i < text.length; ++i) wasm[i] = text.charCodeAt(i);
    factory = factory.slice(0, begin) + factory.slice(end);
  }
  const source = 'var _scriptDir = undefined;\nvar RayCache = ' + factory + ';\n' +
    renderWorkerParts.map(String).join('\n') + '\nrenderWorkerMain(self, RayCache, ' + !!wasm + ');\n';
  const url = URL.createObjectURL(new Blob([source], { type: 'text/javascript' }));
  worker = new Worker(url);
  worker.onmessage = (e) => onMessage(e.data);
  worker.onerror = (e) => showError('worker: ' + e.message);
  if (wasm) worker.postMessage({ type: 'wasm', bytes: wasm.buffer }, [wasm.buffer]);
}

// An error is a sentence in the caption; the picture, key and statistics of what was open
// before go, so that nothing of the old scene shows under the new name
function showError(message) {
  $('caption').textContent = message;
  $('caption').className = 'error';
  last = null;
  layers.forEach((b, k) => { if (b) b.close(); layers[k] = null; });
  context.setTransform(1, 0, 0, 1, 0, 0);
  context.clearRect(0, 0, canvas.width, canvas.height);
  for (const id of ['key', 'stats', 'left-out']) $(id).innerHTML = '';
  for (const id of ['image-hash', 'timing', 'overlay-count', 'overlay-roles']) $(id).textContent = '';
}
let maxSize = 2048;  // the largest width or height the page traces (the bindings' maxSize)

// Scene names: a built-in name (cube:5), an SPD scene of scenes/ (scenes/balls2.nff)
function sceneSpec(name) { return name.startsWith('scenes/') ? '/' + name : name; }

function overlayChoice() {
  return { cylinder: $('ov-cylinder').checked, hull: $('ov-hull').checked, frontier: $('ov-frontier').checked,
           misses: $('ov-misses').checked, heatmap: $('heatmap').checked, clip: viewRect };
}

// `atStop`: the tour stop whose rays the render goes on to ({tour, stop}; its settings are in
// the controls), else nothing
function openScene(atStop) {
  const width = +$('width').value, height = +$('height').value;
  // The size limit, said before anything is traced (the bindings check it too)
  for (const [name, v] of [['width', width], ['height', height]])
    if (!(Number.isInteger(v) && v >= 0 && v <= maxSize)) {
      showError('The ' + name + ' must be a whole number from 1 to ' + maxSize + ' (0: the scene\'s own), not ' +
                $(name).value + ': a larger image needs more memory than a browser tab has.');
      return;
    }
  const m = { type: 'open', width, height, cache: $('cache').value, order: $('order').value,
              accel: $('accel').value, band: atStop ? stop.plan.band : -1, view: overlayChoice(),
              stop: atStop || null, compare: null };
  const [compareCache, compareOrder] = $('compare').value.split(':');
  if (compareCache && compareOrder) m.compare = { cache: compareCache, order: compareOrder };
  if ($('scene').value === 'dropped' && dropped) { m.nff = dropped.text; m.name = dropped.name; }
  else m.scene = sceneSpec($('scene').value);
  m.generation = ++generation;
  $('image-hash').textContent = '';
  $('timing').textContent = '';
  $('caption').className = '';
  $('caption').textContent = 'tracing…';
  if (!atStop) { viewRect = null; zoomAbout = 0; }
  worker.postMessage(m);
}

function onMessage(m) {
  if (m.type === 'loaded') {
    maxSize = m.maxSize;
    for (const id of ['width', 'height']) $(id).max = maxSize;
    usePalette(m.palette);
    fillChoices(m.registry);
    fillScenes(m.scenes);
    // The first view teaches: with nothing asked for, the lecture's first stop, its caption
    // and its ray in focus with overlays on
    if (![...params.keys()].some((k) => k !== 'embed')) {
      params.set('tour', 'hanrahan86');
      params.set('stop', '1');
      history.replaceState(null, '', '?' + params.toString());
    }
    if (params.has('tour')) {
      worker.postMessage({ type: 'tour', tour: params.get('tour'), stop: +(params.get('stop') || 1) });
      return;
    }
    openScene();
    if (params.get('run') === 'end') pendingRun = 'end';
  } else if (m.type === 'tour') {
    if (m.stop.error) { showError(m.stop.error); return; }
    stop = m.stop;
    applyStop();
  } else if (m.type === 'claims') {
    window.__claims = m;
  } else if (m.type === 'error') {
    showError(m.message);
  } else if (m.type === 'frame') {
    last = m;
    paintLayers(m);
    if (m.opened && zoomAbout > 0) zoomView();
    draw();
    showStatistics(m.statistics, m.compare && m.compare.statistics);
    $('caption').textContent = captionOf(m);
    canvas.classList.toggle('wide', !!m.compare);
    showKey(m);
    showRayTree(m.rayTree);
    $('play').textContent = m.running === 'play' ? 'Pause' : 'Play';
    if (m.notes && m.notes.length) $('stop').hidden = false;
    if (m.notes && m.notes.length) $('stop-notes').textContent = [stopNotes].concat(m.notes).filter(Boolean).join(' ');
    if (m.opened && pendingRun) { worker.postMessage({ type: pendingRun }); pendingRun = null; }
    if (m.runMs !== undefined && m.runMs !== null)
      $('timing').textContent = 'ran to the end in ' + m.runMs.toFixed(1) + ' ms';
    // The image's bytes are read for their hash only: not kept with the frame (`last`)
    if (m.done && m.image && m.generation === generation) writeHash(m.image);
    m.image = null;
  }
}

// ---- A tour stop: its settings as the core plans them (rc::planOf), set in the controls
let stopNotes = '';
function showStopTitle() {
  $('stop').hidden = false;
  $('stop-caption').textContent = stop.caption;
  $('as-written').hidden = false;
  const k = +(params.get('stop') || 1);
  $('prev-stop').hidden = k <= 1;
  $('next-stop').hidden = k >= stop.stops;
  $('stop-title').textContent = k + '/' + stop.stops + '  ' + stop.title + '.';
  const full = new URLSearchParams({ tour: params.get('tour'), stop: params.get('stop') || '1' });
  $('full').href = '?' + full.toString();
}
// A choice a menu does not list yet (a scene file, a compare pair) is added to it
function choose(id, value) {
  if (![...$(id).options].some((o) => o.value === value)) {
    const o = document.createElement('option');
    o.value = o.textContent = value;
    $(id).appendChild(o);
  }
  $(id).value = value;
}
function applyStop() {
  const p = stop.plan;
  showStopTitle();
  // The page carries the tours' scenes under /scenes: the menu names them scenes/NAME.nff
  choose('scene', p.scene.startsWith('/scenes/') ? p.scene.slice(1) : p.scene);
  $('width').value = p.width;
  $('height').value = p.height;
  $('cache').value = p.cache;
  $('order').value = p.order;
  $('accel').value = p.accel;
  for (const o of ['cylinder', 'hull', 'frontier', 'misses']) $('ov-' + o).checked = p.overlays.includes(o);
  $('heatmap').checked = p.heatmap === 'tests';
  choose('compare', p.compare);
  // What the web viewer leaves to the Qt GUI, said rather than dropped
  stopNotes = p.qtOnly.length ? 'The Qt GUI (raycache-gui --tour tours/' + params.get('tour') + '.json --stop ' +
    (params.get('stop') || 1) + ') also shows ' + p.qtOnly.join(', ') + '.' : '';
  $('stop-notes').textContent = stopNotes;
  viewRect = p.focus;
  zoomAbout = p.focus ? 0 : (p.zoom > 1 ? p.zoom : 0);
  openScene({ tour: params.get('tour'), stop: +(params.get('stop') || 1) });
}

// A stop's zoom: the image rectangle `zoomAbout` times smaller, about the pixel in focus
function zoomView() {
  const m = last;
  const pixel = m.legend.pixel !== undefined ? m.legend.pixel : m.focusPixel;
  const cx = pixel >= 0 ? pixel % m.width + 0.5 : m.width / 2, cy = pixel >= 0 ? Math.floor(pixel / m.width) + 0.5 : m.height / 2;
  const w = m.width / zoomAbout, h = m.height / zoomAbout;
  viewRect = [cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2];
  zoomAbout = 0;
  worker.postMessage({ type: 'view', view: overlayChoice() });
}

// The cache, order, search and compare menus: the core's registries, in their order
function fillChoices(registry) {
  const fill = (id, entries, chosen) => {
    for (const e of entries) {
      const o = document.createElement('option');
      o.value = o.textContent = e.name;
      o.title = e.description;
      $(id).appendChild(o);
    }
    $(id).value = chosen;
  };
  fill('cache', registry.caches, 'blocker+');
  fill('order', registry.orders, 'bfs');
  fill('accel', registry.searches.filter((e) => !e.comparison_only), 'linear');
  for (const c of registry.caches)
    for (const o of registry.orders) {
      const option = document.createElement('option');
      option.value = option.textContent = c.name + ':' + o.name;
      $('compare').appendChild(option);
    }
  // The URL's choices, once the menus hold them; a '+' the URL did not encode reads as a
  // space (blocker+ arrives as "blocker "): it is put back
  for (const key of ['cache', 'order', 'accel']) {
    if (!params.has(key)) continue;
    const wanted = params.get(key).replace(/ /g, '+');
    // A name no registry holds stays chosen, so that the render says it is unknown
    if (![...$(key).options].some((o) => o.value === wanted)) {
      const o = document.createElement('option');
      o.value = o.textContent = wanted;
      $(key).appendChild(o);
    }
    $(key).value = wanted;
  }
}
function addSceneOption(value, text) {
  const o = document.createElement('option');
  o.value = value;
  o.textContent = text;
  $('scene').appendChild(o);
  return o;
}

// The Scene menu: the core's list (rc::sceneChoices, as the Qt GUI's), the built-ins and
// the SPD scenes that travel with the page (as scenes/NAME.nff, the name the URL takes)
function fillScenes(list) {
  const select = $('scene');
  for (const c of list) addSceneOption(c.file ? c.spec.replace(/^\//, '') : c.spec, c.label).title = c.description;
  const wanted = params.get('scene');
  if (wanted && ![...select.options].some((o) => o.value === wanted)) addSceneOption(wanted, wanted);
  select.value = wanted || 'cube:4';
}

// ---- Drawing ---------------------------------------------------------------------------
// The picture at image size, as the core made it (the image or the heatmap, the regions
// of the fill, the misses): the frame's bitmap, in place of the last one
function paintLayers(m) {
  [m, m.compare].forEach((p, k) => {
    if (layers[k]) layers[k].close();
    layers[k] = p ? p.layer : null;
    if (p) p.layer = null;
  });
}

let drawnShapes = 0;
const drawnRoles = new Set();

// The render, or the two compared side by side, each in the image rectangle shown
function draw() {
  const m = last;
  if (!m) return;
  const panes = m.compare ? [m, m.compare] : [m];
  const v = viewRect || [0, 0, m.width, m.height];
  const dpr = window.devicePixelRatio || 1;
  const cssWidth = canvas.getBoundingClientRect().width || 512;
  const W = Math.round(cssWidth * dpr), gap = panes.length > 1 ? Math.round(8 * dpr) : 0;
  const paneWidth = (W - gap * (panes.length - 1)) / panes.length;
  const H = Math.round(paneWidth * (v[3] - v[1]) / (v[2] - v[0]));
  if (canvas.width !== W || canvas.height !== H) { canvas.width = W; canvas.height = H; }
  context.setTransform(1, 0, 0, 1, 0, 0);
  context.fillStyle = panes.length > 1 ? '#fff' : '#000';
  context.fillRect(0, 0, W, H);
  drawnShapes = 0;
  drawnRoles.clear();
  panes.forEach((p, k) => {
    const left = k * (paneWidth + gap);
    context.save();
    context.beginPath();
    context.rect(left, 0, paneWidth, H);
    context.clip();
    context.fillStyle = '#000';
    context.fillRect(left, 0, paneWidth, H);
    const scale = paneWidth / (v[2] - v[0]);
    context.setTransform(scale, 0, 0, scale, left - v[0] * scale, -v[1] * scale);
    drawPane(p, k, dpr / scale);
    context.restore();
  });
  $('overlay-count').textContent = drawnShapes;
  $('overlay-roles').textContent = [...drawnRoles].sort().join(',');
}

// One render (the `k`th pane), in image coordinates; `px` is one CSS pixel in image units
function drawPane(m, k, px) {
  context.imageSmoothingEnabled = false;
  if (layers[k]) context.drawImage(layers[k], 0, 0);
  for (const shape of m.shapes) {
    if (drawShape(shape, px)) { ++drawnShapes; drawnRoles.add(shape.role); }
  }
  const focus = m.legend.pixel;
  if (m.shapes.length && focus !== undefined) dot(focus % m.width + 0.5, Math.floor(focus / m.width) + 0.5, 5 * px, kRay);
  if (m.selectedPixel >= 0) {
    const cx = m.selectedPixel % m.width + 0.5, cy = Math.floor(m.selectedPixel / m.width) + 0.5;
    const half = Math.max(0.5, 7 * px);
    widthScale = px;
    strokePath([cx - half, cy - half, cx + half, cy - half, cx + half, cy + half, cx - half, cy + half], true,
               kSelection, 2.5 * px, false);
  }
  // A cross marks the pixel being traced, so that stepping shows on the image
  if (m.focusPixel >= 0 && !m.done) {
    const cx = m.focusPixel % m.width + 0.5, cy = Math.floor(m.focusPixel / m.width) + 0.5, r = Math.max(0.7, 9 * px);
    for (const [c, w] of [[[0, 0, 0], 4.5], [kRay, 2]]) {
      context.strokeStyle = rgba(c);
      context.lineWidth = w * px;
      context.setLineDash([]);
      context.beginPath();
      context.moveTo(cx - r, cy); context.lineTo(cx + r, cy);
      context.moveTo(cx, cy - r); context.lineTo(cx, cy + r);
      context.stroke();
    }
  }
  // The queue on top of everything: it is small and it is where the action is
  if (m.frontier) {
    const size = Math.max(1, 11 * px);
    context.lineWidth = 1.5 * px;
    context.strokeStyle = '#000';
    context.setLineDash([]);
    for (const [list, c] of [[m.frontier.deferred, kDeferred], [m.frontier.queued, kQueued]]) {
      context.fillStyle = rgba(c);
      for (const p of list) {
        const x = p % m.width + 0.5 - size / 2, y = Math.floor(p / m.width) + 0.5 - size / 2;
        context.fillRect(x, y, size, size);
        context.strokeRect(x, y, size, size);
      }
    }
  }
}

// The caption (rc::focusCaption's lines); beside a compared render, its own and the
// difference in tests, as the Qt GUI's
function captionOf(m) {
  let text = m.caption.trim();
  if (m.compare) {
    // The comparison's lines are the core's (rc::compareCaption), as the Qt GUI's
    text = 'left: ' + text + '\nright: ' + m.compare.caption.trim() + '\n' +
      m.compare.compareCaption.trim().split('\n').join(', ');
  }
  return text;
}

// A closed outline or a polyline of flat [x, y, ...]: a dark halo, then the colour
function strokePath(xy, closed, colour, width, dashed, fill, covers) {
  if (xy.length < 4) return false;
  context.beginPath();
  context.moveTo(xy[0], xy[1]);
  for (let i = 2; i < xy.length; i += 2) context.lineTo(xy[i], xy[i + 1]);
  if (closed) context.closePath();
  if (fill > 0) {
    context.fillStyle = rgba(colour, covers ? Math.min(fill, 25) : fill);
    context.fill();
  }
  if (covers) return true;  // an outline holding the whole view has no edge to show
  context.setLineDash([]);
  context.strokeStyle = 'rgba(0,0,0,0.63)';
  context.lineWidth = width + 2 * widthScale;
  context.stroke();
  context.setLineDash(dashed ? [5 * widthScale, 4 * widthScale] : []);
  context.strokeStyle = rgba(colour);
  context.lineWidth = width;
  context.stroke();
  return true;
}
let widthScale = 1;  // one CSS pixel in image units, while a shape is drawn

function dot(x, y, r, colour) {
  context.beginPath();
  context.arc(x, y, r, 0, 2 * Math.PI);
  context.fillStyle = rgba(colour);
  context.fill();
  context.setLineDash([]);
  context.strokeStyle = '#000';
  context.lineWidth = 2 * r / 5;
  context.stroke();
}

// One shape of the core's (rc::focusShapes), in its role's colour and line
function drawShape(shape, px) {
  const style = kRoleStyles[shape.role];
  if (!style) return false;
  widthScale = px;
  if (style.star) {
    if (!shape.point) return false;
    const [x, y] = shape.point;
    context.setLineDash([]);
    context.strokeStyle = rgba(style.colour);
    context.lineWidth = (style.arms === 2 ? 2 : 3) * px;
    context.beginPath();
    for (let k = 0; k < style.arms; ++k) {
      const a = (style.arms === 2 ? Math.PI / 4 : 0) + k * Math.PI / style.arms;
      const dx = style.star * px * Math.cos(a), dy = style.star * px * Math.sin(a);
      context.moveTo(x - dx, y - dy); context.lineTo(x + dx, y + dy);
    }
    context.stroke();
    return true;
  }
  if (shape.segment) {
    const [ax, ay, bx, by] = shape.segment;
    if (Math.hypot(bx - ax, by - ay) <= 0.5) return false;
    return strokePath(shape.segment, false, style.colour, style.width * px, style.dash, 0, false);
  }
  // A polygon may hold much of the view: dashed, never tinted
  return strokePath(shape.outline, true, style.colour, style.width * px, style.dash || shape.flat,
                    shape.flat ? 0 : style.fill, shape.covers);
}

// ---- The key and the statistics -----------------------------------------------------
// The key: the core's entries (rc::legendEntries, rc::focusEntries), as the Qt GUI's,
// then the heatmap's scale
function showKey(m) {
  const keys = m.keys.map((k) => [k.colour, k.text]);
  if ($('heatmap').checked) {
    keys.push([kRamp[kRamp.length - 1], 'heatmap: intersection tests per pixel, log scale, 0 to ' + m.heatTop +
               (m.compare ? ', one scale for both' : '')]);
  }
  $('key').innerHTML = '';
  for (const [c, text] of keys) {
    const li = document.createElement('li');
    if (c) {
      const i = document.createElement('i');
      i.style.background = rgba(c);
      li.appendChild(i);
    }
    li.appendChild(document.createTextNode(text));
    $('key').appendChild(li);
  }
}

// The ray tree of the pixel in focus: the core's rows (rc::rayTreeRows), as the Qt GUI's
// Ray tree panel, each ray under the one that spawned it
function showRayTree(tree) {
  const table = $('ray-tree');
  table.innerHTML = '';
  if (!tree || !tree.pixel) {
    $('ray-tree-title').textContent = 'Click a pixel to list its rays.';
    return;
  }
  $('ray-tree-title').textContent = 'Every ray of pixel (' + tree.pixel.join(', ') + '), under the ray that spawned it';
  const head = table.insertRow();
  for (const h of ['ray', 'hit', 'decision', 'tests']) {
    const th = document.createElement('th');
    th.textContent = h;
    head.appendChild(th);
  }
  for (const r of tree.rows) {
    const row = table.insertRow();
    // The path's last step (which names its kind), indented under its parent, the whole
    // path as its tooltip
    const cells = [r.path.split('/').pop(), r.hit, r.decision, r.tests].map((text) => {
      const td = row.insertCell();
      td.textContent = text;
      return td;
    });
    cells[0].style.paddingLeft = r.depth + 'em';
    cells[0].title = r.path;
    if (r.focus) row.className = 'focus';
    cells[2].className = 'decision';
    cells[3].className = 'tests';
    if (r.deferred || r.miss) cells[2].style.color = rgba(r.deferred ? kDeferredText : kMissText);
  }
}

function showStatistics(...renders) {
  const rows = [['rays', 'rays'], ['eye rays', 'primary'], ['shadow rays', 'shadow'],
                ['reflection rays', 'reflection'], ['refraction rays', 'refraction'],
                ['intersection tests', 'tests'], ['complete searches', 'searches'],
                ['cache hits', 'hits'], ['cache misses', 'misses'], ['tests per ray', null]];
  const cell = (s, key) => {
    const v = key ? s[key] : s.rays ? (s.tests / s.rays).toFixed(2) : '';
    return '<td>' + (typeof v === 'number' ? v.toLocaleString('en') : v) + '</td>';
  };
  const shown = renders.filter(Boolean);
  // What the render leaves out (rc::leftOut), as the CLI's stats and the Qt GUI's panel say
  $('left-out').innerHTML = '';
  for (const line of shown[0].leftOut || []) {
    const li = document.createElement('li');
    li.textContent = 'left out: ' + line;
    $('left-out').appendChild(li);
  }
  $('stats').innerHTML = (shown.length > 1 ? '<tr><td></td><td>left</td><td>right</td></tr>' : '') +
    rows.map(([label, key]) => '<tr><td>' + label + '</td>' + shown.map((s) => cell(s, key)).join('') + '</tr>').join('');
}

// The SHA-256 of the 8-bit RGB pixel bytes, rows top to bottom: `raycache render --hash`'s
async function writeHash(image) {
  if (!(window.crypto && crypto.subtle)) { $('image-hash').textContent = 'no Web Crypto here'; return; }
  const opened = generation;
  const digest = new Uint8Array(await crypto.subtle.digest('SHA-256', image));
  if (opened === generation) $('image-hash').textContent = [...digest].map((b) => b.toString(16).padStart(2, '0')).join('');
}

// ---- Controls; the URL's ?scene=S&width=W&height=H&cache=C&order=O&accel=A&run=end sets them
for (const key of ['width', 'height'])
  if (params.has(key)) $(key).value = params.get(key);
$('open').onclick = () => openScene();
$('as-written').onclick = () => { if (stop) applyStop(); };
// Another stop: the same page at it (the render starts afresh, as the Qt GUI's does)
const goToStop = (step) => {
  const next = new URLSearchParams(location.search);
  next.set('stop', String(+(params.get('stop') || 1) + step));
  location.search = next.toString();
};
$('prev-stop').onclick = () => goToStop(-1);
$('next-stop').onclick = () => goToStop(1);
for (const id of ['scene', 'width', 'height', 'cache', 'order', 'accel', 'compare']) $(id).onchange = () => openScene();
$('step-ray').onclick = () => worker.postMessage({ type: 'ray' });
$('step-pixel').onclick = () => worker.postMessage({ type: 'pixel' });
$('step-miss').onclick = () => worker.postMessage({ type: 'miss' });
$('play').onclick = () => worker.postMessage({ type: last && last.running === 'play' ? 'pause' : 'play' });
$('end').onclick = () => worker.postMessage({ type: 'end' });
for (const id of ['ov-cylinder', 'ov-hull', 'ov-frontier', 'ov-misses'])
  $(id).onchange = () => worker.postMessage({ type: 'view', view: overlayChoice() });
$('heatmap').onchange = () => worker.postMessage({ type: 'view', view: overlayChoice() });
window.addEventListener('resize', draw);

// A click puts the pixel's eye ray in focus
canvas.onclick = (e) => {
  if (!last) return;
  const r = canvas.getBoundingClientRect();
  const v = viewRect || [0, 0, last.width, last.height];
  // Either picture of a comparison: the same pixel in both
  const panes = last.compare ? 2 : 1;
  const across = ((e.clientX - r.left) / r.width * panes) % 1;
  const x = Math.floor(v[0] + across * (v[2] - v[0]));
  const y = Math.floor(v[1] + (e.clientY - r.top) / r.height * (v[3] - v[1]));
  worker.postMessage({ type: 'select', x, y });
};

// An NFF file opened with the button or dropped on the picture
async function openFile(file) {
  if (!file) return;
  dropped = { name: file.name.replace(/[^A-Za-z0-9._-]/g, '_'), text: await file.text() };
  let option = [...$('scene').options].find((o) => o.value === 'dropped');
  if (!option) option = addSceneOption('dropped', file.name);
  option.textContent = file.name;
  $('scene').value = 'dropped';
  openScene();
}
$('file').onchange = () => { openFile($('file').files[0]); $('file').value = ''; };
$('open-file').onclick = () => $('file').click();
canvas.ondragover = (e) => { e.preventDefault(); canvas.classList.add('dragging'); };
canvas.ondragleave = () => canvas.classList.remove('dragging');
canvas.ondrop = (e) => {
  e.preventDefault();
  canvas.classList.remove('dragging');
  openFile(e.dataTransfer.files[0]);
};

// For the browser tests (tests/web): the last frame the worker sent
// and the shown stop's claims checked by the core on what is drawn (`claims`, a list of
// texts, replaces the stop's own), the answer in window.__claims
window.__viewer = {
  frame: () => last,
  claims: (claims) => {
    window.__claims = null;
    worker.postMessage({ type: 'claims', tour: params.get('tour'), stop: +(params.get('stop') || 1), claims });
  },
};

startWorker();
