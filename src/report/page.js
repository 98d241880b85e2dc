// A detail page: CPU, GL and their difference, computed here from the two embedded PNGs.
// State (mode, zoom, centre, cursor, region) lives in `st`; every change redraws every view and
// writes the state as JSON into <pre id="state"> (the tests read it with --dump-dom).
(function () {
  'use strict';
  var F = JSON.parse(document.getElementById('frame-data').textContent);
  var $ = function (id) { return document.getElementById(id); };
  var st = { mode: 'side', show: 'cpu', zoom: 1, cx: 0, cy: 0, gain: F.gain, marks: true,
             region: -1, cur: null, split: 0.5, ready: false };
  var W = 0, H = 0, cpu = null, gl = null, worst = null, heat = null, regions = [], overTol = 0, regionsOverTol = true;
  var views = [];

  function decode(uri) {
    return new Promise(function (resolve, reject) {
      var img = new Image();
      img.onload = function () { resolve(img); };
      img.onerror = function () { reject(new Error('cannot decode image')); };
      img.src = uri;
    });
  }
  function pixels(img) {
    var c = document.createElement('canvas');
    c.width = img.naturalWidth; c.height = img.naturalHeight;
    var x = c.getContext('2d');
    x.drawImage(img, 0, 0);
    return { canvas: c, w: c.width, h: c.height,
             data: c.width && c.height ? x.getImageData(0, 0, c.width, c.height).data : new Uint8ClampedArray(0) };
  }
  function rgba(p, x, y) {
    if (x < 0 || y < 0 || x >= p.w || y >= p.h) return null;
    var i = 4 * (y * p.w + x);
    return [p.data[i], p.data[i + 1], p.data[i + 2], p.data[i + 3]];
  }

  // The largest channel difference per pixel (255 outside either image), as compare.rs has it.
  function computeDiff() {
    worst = new Uint8Array(W * H);
    overTol = 0;
    for (var y = 0; y < H; y++) for (var x = 0; x < W; x++) {
      var a = rgba(cpu, x, y), b = rgba(gl, x, y), d = 255;
      if (a && b) d = Math.max(Math.abs(a[0] - b[0]), Math.abs(a[1] - b[1]), Math.abs(a[2] - b[2]), Math.abs(a[3] - b[3]));
      worst[y * W + x] = d;
      if (d > F.tol) overTol++;
    }
  }
  function heatColour(d, gain) {
    if (d === 0) return [0, 0, 0];
    var t = Math.min(d * gain * 3, 765);
    var ramp = function (s) { return Math.min(Math.max(t - s, 0), 255); };
    return [Math.max(ramp(0), 64), ramp(255), ramp(510)];
  }
  function buildHeat() {
    heat = heat || document.createElement('canvas');
    heat.width = W; heat.height = H;
    var x = heat.getContext('2d');
    if (!W || !H) return;
    var im = x.createImageData(W, H);
    for (var i = 0; i < W * H; i++) {
      var c = heatColour(worst[i], st.gain);
      im.data[4 * i] = c[0]; im.data[4 * i + 1] = c[1]; im.data[4 * i + 2] = c[2]; im.data[4 * i + 3] = 255;
    }
    x.putImageData(im, 0, 0);
  }

  // Differing pixels grouped into regions: 8x8 cells holding one, joined when they touch; each
  // region's box is tight around its pixels. Largest region first.
  function findRegions(threshold) {
    var G = 8, gw = Math.ceil(W / G), gh = Math.ceil(H / G), cells = new Int32Array(gw * gh).fill(-1);
    var marked = new Uint8Array(gw * gh);
    for (var y = 0; y < H; y++) for (var x = 0; x < W; x++)
      if (worst[y * W + x] > threshold) marked[((y / G) | 0) * gw + ((x / G) | 0)] = 1;
    var out = [];
    for (var c0 = 0; c0 < gw * gh; c0++) {
      if (!marked[c0] || cells[c0] >= 0) continue;
      var id = out.length, stack = [c0], list = [];
      cells[c0] = id;
      while (stack.length) {
        var c = stack.pop(); list.push(c);
        var cx = c % gw, cy = (c / gw) | 0;
        for (var dy = -1; dy <= 1; dy++) for (var dx = -1; dx <= 1; dx++) {
          var nx = cx + dx, ny = cy + dy;
          if (nx < 0 || ny < 0 || nx >= gw || ny >= gh) continue;
          var n = ny * gw + nx;
          if (marked[n] && cells[n] < 0) { cells[n] = id; stack.push(n); }
        }
      }
      var r = { x0: W, y0: H, x1: -1, y1: -1, count: 0, max: -1, px: 0, py: 0 };
      list.forEach(function (c) {
        var bx = (c % gw) * G, by = ((c / gw) | 0) * G;
        for (var y = by; y < Math.min(by + G, H); y++) for (var x = bx; x < Math.min(bx + G, W); x++) {
          var d = worst[y * W + x];
          if (d <= threshold) continue;
          r.count++;
          if (x < r.x0) r.x0 = x; if (y < r.y0) r.y0 = y; if (x > r.x1) r.x1 = x; if (y > r.y1) r.y1 = y;
          if (d > r.max) { r.max = d; r.px = x; r.py = y; }
        }
      });
      out.push(r);
    }
    out.sort(function (a, b) { return b.count - a.count || a.y0 - b.y0 || a.x0 - b.x0; });
    return out;
  }

  function clampView() {
    st.zoom = Math.min(Math.max(st.zoom, 1), 64);
    var sw = W / st.zoom, sh = H / st.zoom;
    st.cx = Math.min(Math.max(st.cx, sw / 2), W - sw / 2);
    st.cy = Math.min(Math.max(st.cy, sh / 2), H - sh / 2);
  }
  function viewRect() { var sw = W / st.zoom, sh = H / st.zoom; return [st.cx - sw / 2, st.cy - sh / 2, sw, sh]; }

  function drawView(v) {
    var c = v.canvas, x = c.getContext('2d'), r = viewRect(), z = st.zoom;
    x.imageSmoothingEnabled = false;
    x.clearRect(0, 0, W, H);
    var blit = function (src) { x.drawImage(src, r[0], r[1], r[2], r[3], 0, 0, W, H); };
    if (v.kind === 'a') {
      if (st.mode === 'slider') {
        blit(cpu.canvas);
        var sx = Math.round(st.split * W);
        x.save(); x.beginPath(); x.rect(sx, 0, W - sx, H); x.clip(); x.clearRect(sx, 0, W - sx, H); blit(gl.canvas); x.restore();
        x.fillStyle = '#ff00ff'; x.fillRect(sx - 1, 0, 2, H);
      } else {
        blit(st.mode === 'flip' && st.show === 'gl' ? gl.canvas : cpu.canvas);
      }
    } else if (v.kind === 'b') {
      blit(gl.canvas);
    } else {
      blit(heat);
    }
    var lw = Math.max(1, W / c.getBoundingClientRect().width || 1);
    if (st.marks) {
      regions.forEach(function (g, i) {
        var pad = 2 * lw;
        x.lineWidth = (i === st.region ? 3 : 1.5) * lw;
        x.strokeStyle = i === st.region ? '#ff00ff' : '#00e5ff';
        x.strokeRect((g.x0 - r[0]) * z - pad, (g.y0 - r[1]) * z - pad, (g.x1 - g.x0 + 1) * z + 2 * pad, (g.y1 - g.y0 + 1) * z + 2 * pad);
      });
    }
    if (st.cur && z >= 4) {
      x.lineWidth = 2 * lw; x.strokeStyle = '#ffffff';
      x.strokeRect((st.cur[0] - r[0]) * z, (st.cur[1] - r[1]) * z, z, z);
      x.lineWidth = lw; x.strokeStyle = '#000000';
      x.strokeRect((st.cur[0] - r[0]) * z, (st.cur[1] - r[1]) * z, z, z);
    }
  }

  function fmt(v) { return v ? v.map(function (n) { return ('   ' + n).slice(-3); }).join(' ') : '(outside)'; }
  function readout() {
    var el = $('readout');
    if (!st.cur) { el.textContent = 'move over an image to read its pixels (R G B A)'; return null; }
    var x = st.cur[0], y = st.cur[1], a = rgba(cpu, x, y), b = rgba(gl, x, y);
    var d = a && b ? a.map(function (v, i) { return b[i] - v; }) : null;
    var w = worst[y * W + x];
    var sd = d ? d.map(function (n) { return ('   ' + (n > 0 ? '+' + n : n)).slice(-4); }).join('') : '(outside)';
    el.innerHTML = '';
    var line = function (t, cls) { var s = document.createElement('span'); s.textContent = t + '\n'; if (cls) s.className = cls; el.appendChild(s); };
    line('pixel x ' + x + ' y ' + y + '      R   G   B   A');
    line('CPU            ' + fmt(a));
    line('GL             ' + fmt(b));
    line('GL - CPU      ' + sd + '   max |d| ' + w + (w > F.tol ? ' > tolerance ' + F.tol : ''), w > F.tol ? 'd' : '');
    return { cpu: a, gl: b, diff: d ? d.map(Math.abs) : null, worst: w };
  }

  function update() {
    clampView();
    document.body.classList.remove('mode-side', 'mode-flip', 'mode-slider');
    document.body.classList.add('mode-' + st.mode);
    ['side', 'flip', 'slider'].forEach(function (m) { $('mode-' + m).setAttribute('aria-pressed', String(st.mode === m)); });
    $('cap-a').textContent = st.mode === 'flip' ? (st.show === 'gl' ? 'GL  (flip: click or F)' : 'CPU  (flip: click or F)')
      : st.mode === 'slider' ? 'CPU | GL  (drag the handle below)' : 'CPU';
    $('cap-d').textContent = 'difference \u00d7' + st.gain;
    $('zoom-label').textContent = st.zoom + 'x';
    $('gain').value = String(st.gain);
    $('split').value = String(Math.round(st.split * 1000));
    var what = regionsOverTol ? 'over tolerance' : 'within tolerance';
    $('region-label').textContent = regions.length === 0 ? 'no differing pixels'
      : (st.region >= 0 ? (st.region + 1) + ' of ' : '') + regions.length + ' region' + (regions.length === 1 ? '' : 's') + ' ' + what
        + (st.region >= 0 ? ' (' + regions[st.region].count + ' px)' : '');
    $('next-diff').disabled = regions.length === 0;
    views.forEach(drawView);
    var values = readout();
    $('state').textContent = JSON.stringify({
      ready: st.ready, mode: st.mode, show: st.show, zoom: st.zoom, center: [st.cx, st.cy], gain: st.gain,
      cursor: st.cur, values: values, tol: F.tol, width: W, height: H, over_tolerance: overTol,
      regions: regions.length, regions_over_tolerance: regionsOverTol, region: st.region,
      region_box: st.region >= 0 ? regions[st.region] : null, split: st.split,
      fits: document.documentElement.scrollWidth <= window.innerWidth
    });
  }

  function setZoom(z, ax, ay) {
    z = Math.min(Math.max(z, 1), 64);
    if (ax !== undefined) {
      // Keep the image point (ax, ay) under the same spot of the view.
      var r = viewRect(), fx = (ax - r[0]) / r[2], fy = (ay - r[1]) / r[3];
      var sw = W / z, sh = H / z;
      st.cx = ax - fx * sw + sw / 2; st.cy = ay - fy * sh + sh / 2;
    }
    st.zoom = z;
    update();
  }
  function nextRegion(step) {
    if (!regions.length) return;
    st.region = (st.region + (step || 1) + regions.length) % regions.length;
    var g = regions[st.region], bw = g.x1 - g.x0 + 1, bh = g.y1 - g.y0 + 1;
    var z = 1;
    while (z < 32 && bw * z * 2 <= W * 0.6 && bh * z * 2 <= H * 0.6) z *= 2;
    st.zoom = z; st.cx = g.x0 + bw / 2; st.cy = g.y0 + bh / 2;
    st.cur = [g.px, g.py];
    update();
  }
  function imagePoint(canvas, e) {
    var b = canvas.getBoundingClientRect(), r = viewRect();
    var x = Math.floor(r[0] + (e.clientX - b.left) / b.width * r[2]);
    var y = Math.floor(r[1] + (e.clientY - b.top) / b.height * r[3]);
    return [Math.min(Math.max(x, 0), W - 1), Math.min(Math.max(y, 0), H - 1), b];
  }

  function wire(v) {
    var c = v.canvas, drag = null;
    c.width = W; c.height = H;
    c.style.maxWidth = W + 'px';
    c.addEventListener('pointerdown', function (e) {
      drag = { x: e.clientX, y: e.clientY, cx: st.cx, cy: st.cy, moved: false };
      try { c.setPointerCapture(e.pointerId); } catch (err) { /* a synthetic pointer */ }
    });
    c.addEventListener('pointermove', function (e) {
      var p = imagePoint(c, e);
      if (drag) {
        var dx = e.clientX - drag.x, dy = e.clientY - drag.y;
        if (Math.abs(dx) + Math.abs(dy) > 3) { drag.moved = true; c.classList.add('grab'); }
        if (drag.moved) {
          st.cx = drag.cx - dx / p[2].width * W / st.zoom;
          st.cy = drag.cy - dy / p[2].height * H / st.zoom;
        }
      }
      st.cur = [p[0], p[1]];
      update();
    });
    c.addEventListener('pointerup', function () {
      var clicked = drag && !drag.moved;
      drag = null; c.classList.remove('grab');
      if (clicked && v.kind === 'a' && st.mode === 'flip') { st.show = st.show === 'gl' ? 'cpu' : 'gl'; update(); }
    });
    c.addEventListener('wheel', function (e) {
      e.preventDefault();
      var p = imagePoint(c, e);
      setZoom(e.deltaY < 0 ? st.zoom * 2 : st.zoom / 2, p[0] + 0.5, p[1] + 0.5);
    }, { passive: false });
  }

  function applyHash() {
    var h = {};
    location.hash.replace(/^#/, '').split('&').forEach(function (kv) {
      var i = kv.indexOf('='); if (kv) h[decodeURIComponent(i < 0 ? kv : kv.slice(0, i))] = i < 0 ? '' : decodeURIComponent(kv.slice(i + 1));
    });
    if ('flip' in h) st.mode = 'flip';
    if (h.mode === 'side' || h.mode === 'flip' || h.mode === 'slider') st.mode = h.mode;
    if (h.show === 'gl' || h.show === 'cpu') st.show = h.show;
    if (h.gain && +h.gain > 0) { st.gain = +h.gain; buildHeat(); }
    if (h.split) st.split = Math.min(Math.max(+h.split, 0), 1);
    if ('next' in h) { st.region = -1; for (var k = +(h.next || 1); k > 0; k--) nextRegion(1); }
    if (h.zoom && +h.zoom > 0) st.zoom = +h.zoom;
    if (h.at) {
      var p = h.at.split(',').map(Number);
      if (p.length === 2 && p.every(isFinite)) { st.cur = [p[0] | 0, p[1] | 0]; st.cx = p[0] + 0.5; st.cy = p[1] + 0.5; }
    }
    // do=click:ID,key:K,tap:CANVAS,hover:CANVAS@fx/fy: user actions replayed through the page's
    // own event handlers (the browser test drives the page with them).
    if (h.do) h.do.split(',').forEach(act);
  }
  function act(a) {
    var i = a.indexOf(':'), what = a.slice(0, i), arg = a.slice(i + 1);
    if (what === 'click' && $(arg)) $(arg).click();
    else if (what === 'key') document.dispatchEvent(new KeyboardEvent('keydown', { key: arg, bubbles: true }));
    else if (what === 'tap' || what === 'hover') {
      var parts = arg.split('@'), c = $(parts[0]);
      if (!c) return;
      var f = (parts[1] || '0.5/0.5').split('/').map(Number), b = c.getBoundingClientRect();
      var at = { clientX: b.left + f[0] * b.width, clientY: b.top + f[1] * b.height, pointerId: 1, bubbles: true };
      if (what === 'tap') { c.dispatchEvent(new PointerEvent('pointerdown', at)); c.dispatchEvent(new PointerEvent('pointerup', at)); }
      else c.dispatchEvent(new PointerEvent('pointermove', at));
    }
  }

  function keys(e) {
    if (e.target && (e.target.tagName === 'INPUT' || e.target.tagName === 'SELECT') && e.target.type !== 'checkbox') return;
    var k = e.key;
    if (k === 'f' || k === 'F' || k === ' ') {
      e.preventDefault();
      if (st.mode !== 'flip') st.mode = 'flip'; else st.show = st.show === 'gl' ? 'cpu' : 'gl';
      update();
    } else if (k === '+' || k === '=') setZoom(st.zoom * 2, st.cur ? st.cur[0] + 0.5 : undefined, st.cur ? st.cur[1] + 0.5 : undefined);
    else if (k === '-') setZoom(st.zoom / 2);
    else if (k === '0') { st.zoom = 1; update(); }
    else if (k === 'n' || k === 'N') nextRegion(e.shiftKey ? -1 : 1);
    else if (k === 'p' || k === 'P') nextRegion(-1);
    else if (k === '1') { st.mode = 'side'; update(); }
    else if (k === '2') { st.mode = 'flip'; update(); }
    else if (k === '3') { st.mode = 'slider'; update(); }
    else if (st.cur && k.indexOf('Arrow') === 0) {
      e.preventDefault();
      var dx = k === 'ArrowLeft' ? -1 : k === 'ArrowRight' ? 1 : 0, dy = k === 'ArrowUp' ? -1 : k === 'ArrowDown' ? 1 : 0;
      st.cur = [Math.min(Math.max(st.cur[0] + dx, 0), W - 1), Math.min(Math.max(st.cur[1] + dy, 0), H - 1)];
      update();
    }
  }

  Promise.all([decode(F.cpu), decode(F.gl)]).then(function (imgs) {
    cpu = pixels(imgs[0]); gl = pixels(imgs[1]);
    W = Math.max(cpu.w, gl.w); H = Math.max(cpu.h, gl.h);
    st.cx = W / 2; st.cy = H / 2;
    computeDiff();
    buildHeat();
    regions = findRegions(F.tol);
    regionsOverTol = true;
    if (!regions.length) { regions = findRegions(0); regionsOverTol = false; }
    views = [{ kind: 'a', canvas: $('canvas-a') }, { kind: 'b', canvas: $('canvas-b') }, { kind: 'd', canvas: $('canvas-d') }];
    views.forEach(wire);
    ['side', 'flip', 'slider'].forEach(function (m) { $('mode-' + m).addEventListener('click', function () { st.mode = m; update(); }); });
    $('zoom-in').addEventListener('click', function () { setZoom(st.zoom * 2); });
    $('zoom-out').addEventListener('click', function () { setZoom(st.zoom / 2); });
    $('zoom-reset').addEventListener('click', function () { st.zoom = 1; update(); });
    $('gain').addEventListener('change', function () { st.gain = +$('gain').value; buildHeat(); update(); });
    $('marks').addEventListener('change', function () { st.marks = $('marks').checked; update(); });
    $('split').addEventListener('input', function () { st.split = $('split').value / 1000; update(); });
    $('next-diff').addEventListener('click', function () { nextRegion(1); });
    document.addEventListener('keydown', keys);
    window.addEventListener('hashchange', function () { applyHash(); update(); });
    window.addEventListener('resize', update);
    applyHash();
    st.ready = true;
    update();
  }).catch(function (err) {
    $('readout').textContent = 'cannot read the images: ' + err;
    $('state').textContent = JSON.stringify({ ready: false, error: String(err) });
  });
})();
