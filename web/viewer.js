// The viewer page: controls, the canvas, the statistics. The render itself runs in a
// worker (render_worker.js) that owns the web edition's Render.
(function () {
  const $ = (id) => document.getElementById(id);
  const params = new URLSearchParams(location.search);
  const canvas = $('canvas');
  const context = canvas.getContext('2d');
  let last = null;        // the last frame the worker sent
  let dropped = null;     // {name, text} of a dropped NFF file
  let worker = null;
  let generation = 0;     // renders opened so far: a hash written late for an earlier one is dropped

  // The worker, from a Blob: raycache.js's factory and renderWorkerMain, as source text
  function startWorker() {
    const source = 'var _scriptDir = undefined;\nvar RayCache = ' + RayCache.toString() + ';\n(' +
      renderWorkerMain.toString() + ')(self, RayCache);\n';
    const url = URL.createObjectURL(new Blob([source], { type: 'text/javascript' }));
    worker = new Worker(url);
    worker.onmessage = (e) => onMessage(e.data);
    worker.onerror = (e) => showError('worker: ' + e.message);
  }

  function showError(message) {
    $('caption').textContent = message;
    $('caption').className = 'error';
  }

  // Scene names: a built-in name (cube:5), an SPD scene of scenes/ (scenes/balls2.nff)
  function sceneSpec(name) { return name.startsWith('scenes/') ? '/' + name : name; }

  function open() {
    const width = +$('width').value, height = +$('height').value;
    const m = { type: 'open', width, height, cache: $('cache').value, order: $('order').value,
                accel: $('accel').value };
    if ($('scene').value === 'dropped' && dropped) { m.nff = dropped.text; m.name = dropped.name; }
    else m.scene = sceneSpec($('scene').value);
    ++generation;
    $('image-hash').textContent = '';
    $('timing').textContent = '';
    $('caption').className = '';
    worker.postMessage(m);
  }

  function onMessage(m) {
    if (m.type === 'loaded') {
      fillScenes(m.scenes);
      fillMissLegend(m.missReasons);
      open();
      if (params.get('run') === 'end') pendingRun = 'end';
    } else if (m.type === 'error') {
      showError(m.message);
    } else if (m.type === 'frame') {
      last = m;
      draw();
      showStatistics(m.statistics);
      $('caption').textContent = m.caption;
      $('play').textContent = m.running === 'play' ? 'Pause' : 'Play';
      if (m.opened && pendingRun) { worker.postMessage({ type: pendingRun }); pendingRun = null; }
      if (m.runMs !== undefined && m.runMs !== null)
        $('timing').textContent = 'ran to the end in ' + m.runMs.toFixed(1) + ' ms';
      if (m.done) writeHash(m.image);
    }
  }
  let pendingRun = null;

  // The built-in scenes with a size, and the SPD scenes that travel with the page
  function fillScenes(list) {
    const select = $('scene');
    const names = ['cube:3', 'cube:4', 'cube:5', 'balls:1', 'balls:2', 'balls:3', 'glass', 'fill', 'pair', 'trio'];
    const files = ['balls1', 'balls2', 'gears2', 'jacks2', 'lattice2', 'mount2', 'rings2', 'shells1', 'teapot2',
                   'tetra2', 'tree2'].map((s) => 'scenes/' + s + '.nff');
    const described = new Map(list.trim().split('\n').map((l) => l.split('\t')));
    for (const n of names.concat(files)) {
      const o = document.createElement('option');
      o.value = o.textContent = n;
      o.title = described.get(n.replace(/:\d+$/, ':N')) || '';
      select.appendChild(o);
    }
    const wanted = params.get('scene');
    if (wanted && ![...select.options].some((o) => o.value === wanted)) {
      const o = document.createElement('option');
      o.value = o.textContent = wanted;
      select.appendChild(o);
    }
    select.value = wanted || 'cube:4';
  }

  function draw() {
    const m = last;
    if (!m) return;
    if (canvas.width !== m.width || canvas.height !== m.height) { canvas.width = m.width; canvas.height = m.height; }
    const out = context.createImageData(m.width, m.height);
    const n = m.width * m.height;
    if ($('heatmap').checked) {
      // Intersection tests per pixel, on a log scale from black through red to yellow
      let most = 1;
      for (let i = 0; i < n; ++i) most = Math.max(most, m.heat[i]);
      const scale = 1 / Math.log1p(most);
      for (let i = 0; i < n; ++i) {
        const v = Math.log1p(m.heat[i]) * scale;
        out.data[4 * i] = 255 * Math.min(1, 2 * v);
        out.data[4 * i + 1] = 255 * Math.max(0, 2 * v - 1);
        out.data[4 * i + 2] = 64 * (1 - v) * (m.heat[i] > 0);
        out.data[4 * i + 3] = 255;
      }
    } else {
      for (let i = 0; i < n; ++i) {
        out.data[4 * i] = m.image[3 * i];
        out.data[4 * i + 1] = m.image[3 * i + 1];
        out.data[4 * i + 2] = m.image[3 * i + 2];
        out.data[4 * i + 3] = 255;
      }
    }
    if ($('misses').checked) {
      // Each pixel's last cache miss, coloured by its reason
      for (let i = 0; i < n; ++i) {
        const c = kMissColours[m.misses[i]];
        if (!m.misses[i] || !c) continue;
        out.data[4 * i] = c[0];
        out.data[4 * i + 1] = c[1];
        out.data[4 * i + 2] = c[2];
      }
    }
    context.putImageData(out, 0, 0);
    // The pixel of the ray in focus, while the render is not done
    if (m.focusPixel >= 0 && !m.done) {
      const x = m.focusPixel % m.width, y = Math.floor(m.focusPixel / m.width);
      context.fillStyle = 'rgba(0, 255, 255, 0.35)';
      context.fillRect(0, y, m.width, 1);
      context.fillRect(x, 0, 1, m.height);
      context.fillStyle = 'rgb(0, 255, 255)';
      context.fillRect(x, y, 1, 1);
    }
  }

  function showStatistics(s) {
    const rows = [['rays', s.rays], ['eye rays', s.primary], ['shadow rays', s.shadow],
                  ['reflection rays', s.reflection], ['refraction rays', s.refraction],
                  ['intersection tests', s.tests], ['complete searches', s.searches],
                  ['cache hits', s.hits], ['cache misses', s.misses],
                  ['tests per ray', s.rays ? (s.tests / s.rays).toFixed(2) : '']];
    $('stats').innerHTML = rows.map(([k, v]) => '<tr><td>' + k + '</td><td>' +
      (typeof v === 'number' ? v.toLocaleString('en') : v) + '</td></tr>').join('');
  }

  // The SHA-256 of the 8-bit RGB pixel bytes, rows top to bottom: `raycache render --hash`'s
  async function writeHash(image) {
    if (!(window.crypto && crypto.subtle)) { $('image-hash').textContent = 'no Web Crypto here'; return; }
    const opened = generation;
    const digest = new Uint8Array(await crypto.subtle.digest('SHA-256', image));
    if (opened === generation) $('image-hash').textContent = [...digest].map((b) => b.toString(16).padStart(2, '0')).join('');
  }

  // The Qt GUI's colours of the miss reasons (ui/palette.cpp), by MissReason's number
  const kMissColours = [null, [153, 153, 153], [240, 228, 66], [0, 114, 178], [213, 94, 0], [230, 159, 0],
                        [86, 180, 233], [204, 121, 167]];
  function fillMissLegend(names) {
    $('miss-legend').innerHTML = names.slice(1).map((name, i) => {
      const c = kMissColours[i + 1] || [255, 255, 255];
      return '<span><i style="background: rgb(' + c.join(',') + ')"></i>' + name.replace(/_/g, ' ') + '</span>';
    }).join(' ');
  }

  // Controls; the URL's ?scene=S&width=W&height=H&cache=C&order=O&accel=A&run=end sets them
  for (const key of ['width', 'height', 'cache', 'order', 'accel'])
    if (params.has(key)) $(key).value = params.get(key);
  $('open').onclick = open;
  for (const id of ['scene', 'width', 'height', 'cache', 'order', 'accel']) $(id).onchange = open;
  $('step-ray').onclick = () => worker.postMessage({ type: 'ray' });
  $('step-pixel').onclick = () => worker.postMessage({ type: 'pixel' });
  $('step-miss').onclick = () => worker.postMessage({ type: 'miss' });
  $('play').onclick = () => worker.postMessage({ type: last && last.running === 'play' ? 'pause' : 'play' });
  $('end').onclick = () => worker.postMessage({ type: 'end' });
  $('heatmap').onchange = draw;
  $('misses').onchange = draw;

  // An NFF file dropped on the picture
  canvas.ondragover = (e) => { e.preventDefault(); canvas.classList.add('dragging'); };
  canvas.ondragleave = () => canvas.classList.remove('dragging');
  canvas.ondrop = async (e) => {
    e.preventDefault();
    canvas.classList.remove('dragging');
    const file = e.dataTransfer.files[0];
    if (!file) return;
    dropped = { name: file.name.replace(/[^A-Za-z0-9._-]/g, '_'), text: await file.text() };
    let option = [...$('scene').options].find((o) => o.value === 'dropped');
    if (!option) {
      option = document.createElement('option');
      option.value = 'dropped';
      $('scene').appendChild(option);
    }
    option.textContent = file.name;
    $('scene').value = 'dropped';
    open();
  };

  startWorker();
})();
