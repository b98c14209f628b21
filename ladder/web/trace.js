// The signal trace panel of the live page (docs/trace.md "Page"): 信号跟踪 beside the ladder. A
// form defines the trace (addresses in the program's dialect or its symbols, the trigger,
// pre/post ticks, single or repeat) and arms, triggers and stops it through POST api/trace, the
// same requests as `ladderjit monitor trace`; GET api/trace?have=ID polls the status and brings
// a new capture once. The capture is plotted with Debian's dygraphs (served by serve from
// /usr/share/javascript/dygraphs, loaded when the panel first opens): bits as step waveforms on
// lanes of their own, bytes and words as lines below, one time axis in ticks and ms, zoom (drag)
// and pan (shift-drag), the trigger tick marked, two cursors (click: A, second click or
// shift-click: B) with the time between them and the values at both; a click on a signal's name
// finds it in the ladder with the live page's search. Embedded into the binary as it is
// (ladder/CMakeLists.txt) and linted (tests/lint/web_js.py).
(function () {
  'use strict';
  const L = window.ladder;
  if (!L || !L.esc || !L.say) return;
  const h = L.esc;
  const KEY = window.LJ_KEY || '';
  const LANE = 1.5; // a bit's lane: 0 or 1, then half a lane of space

  // ---- state ---------------------------------------------------------------------------------
  // cap: the capture shown ({id, signals, ticks, cols, bits (indices), words (indices),
  // triggerTick, periodMs}); a, b: the cursors' ticks (or null).
  const T = {
    on: false, lib: null, cap: null, haveId: 0, a: null, b: null, graphs: [], status: null,
    touched: false, timer: null, readOnly: false, syncing: false
  };
  L.trace = T;

  // GET the status (and a capture newer than the one shown), or POST a command (live.js L.api).
  function api(body) {
    return L.api(body === undefined ? 'api/trace?have=' + T.haveId : 'api/trace', body);
  }

  // ---- the panel -----------------------------------------------------------------------------
  const panel = document.createElement('div');
  panel.id = 'trace';
  panel.innerHTML =
    '<div class="row head"><b>信号跟踪 trace</b><span id="trstate">idle</span></div>' +
    '<div class="row"><label for="trsig">信号 signals</label>' +
    '<input id="trsig" size="46" placeholder="X483.5, R10.0, Y0.3, D12 (addresses or symbols)"></div>' +
    '<div class="row"><label for="trkind">触发 trigger</label><select id="trkind">' +
    '<option value="rising">rising ↑</option><option value="falling">falling ↓</option>' +
    '<option value="compare">compare</option><option value="manual">manual</option>' +
    '<option value="immediate">immediate</option></select>' +
    '<input id="traddr" size="10" placeholder="address"><select id="trop">' +
    ['=', '<>', '<', '>', '<=', '>='].map(function (o) { return '<option>' + h(o) + '</option>'; }).join('') +
    '</select><input id="trval" size="6" placeholder="value"></div>' +
    '<div class="row"><label for="trpre">pre</label><input id="trpre" type="number" min="0" value="100" style="width:6em">' +
    '<label for="trpost">post</label><input id="trpost" type="number" min="0" value="100" style="width:6em">' +
    '<select id="trmode"><option value="single">single 单次</option><option value="repeat">repeat 连续</option></select>' +
    '<span style="flex:1"></span><button data-act="arm" id="trarm">启动 arm</button>' +
    '<button data-act="trigger" id="trtrig">触发 trigger</button><button data-act="stop" id="trstop">停止 stop</button></div>' +
    '<div class="row" id="trmsg"></div>' +
    '<div class="row" id="trdl" hidden>download the last capture: <a id="trvcd" download>VCD</a>' +
    '<a id="trvcdb" download>VCD (bit wires, PulseView)</a><a id="trcsv" download>CSV</a></div>' +
    '<div id="trplots"><div id="trbits"></div><div id="trwords"></div></div>' +
    '<div class="row" id="trcur">click the plot: cursor A; a second click (or shift-click): cursor B. ' +
    'Drag: zoom; shift-drag: pan; double-click: all.</div>' +
    '<table id="trvals"></table>';
  document.body.appendChild(panel);
  const $ = function (id) { return document.getElementById(id); };

  function msg(t, bad) {
    const m = $('trmsg');
    m.textContent = t;
    m.className = 'row ' + (bad ? 'bad' : 'ok');
  }

  const btn = document.createElement('button');
  btn.id = 'trbtn';
  btn.textContent = '信号跟踪 trace';
  btn.title = 'record signals around a trigger and plot them (docs/trace.md)';
  $('live').appendChild(btn);
  btn.addEventListener('click', function () {
    T.on = !T.on;
    document.body.classList.toggle('tracing', T.on);
    btn.classList.toggle('on', T.on);
    if (T.on) {
      loadLib();
      poll();
    }
  });

  // ---- the charting library (served by serve from Debian's libjs-dygraphs) -------------------
  function loadLib() {
    if (T.lib) return T.lib;
    T.lib = new Promise(function (resolve) {
      const css = document.createElement('link');
      css.rel = 'stylesheet';
      css.href = 'dygraph.min.css';
      document.head.appendChild(css);
      const s = document.createElement('script');
      s.src = 'dygraph.min.js';
      s.onload = function () { resolve(!!window.Dygraph); };
      s.onerror = function () {
        // Say plainly why: the server's answer names what is missing.
        fetch('dygraph.min.js').then(function (r) { return r.text(); }).then(function (t) {
          $('trplots').innerHTML = '<div class="bad" id="trnolib">' + h(t) + '</div>';
        }).catch(function () {
          $('trplots').innerHTML = '<div class="bad" id="trnolib">dygraphs could not be loaded</div>';
        });
        resolve(false);
      };
      document.head.appendChild(s);
    });
    T.lib.then(function (ok) { if (ok && T.cap) plot(); });
    return T.lib;
  }

  // ---- the definition form -------------------------------------------------------------------
  function kindShown() {
    const k = $('trkind').value;
    $('traddr').style.display = k === 'rising' || k === 'falling' || k === 'compare' ? '' : 'none';
    $('trop').style.display = $('trval').style.display = k === 'compare' ? '' : 'none';
  }
  $('trkind').addEventListener('change', kindShown);
  kindShown();
  panel.querySelectorAll('input,select').forEach(function (e) {
    e.addEventListener('input', function () { T.touched = true; });
  });

  /// The definition file's text (docs/trace.md "Definition file") of the form; null with a
  /// message when a field is missing. Addresses are checked by the server.
  function definition() {
    const sig = $('trsig').value.split(/[,\s]+/).filter(function (x) { return x; });
    if (!sig.length) return msg('name at least one signal', true), null;
    const k = $('trkind').value, a = $('traddr').value.trim(), v = $('trval').value.trim();
    let trig = k;
    if (k === 'rising' || k === 'falling' || k === 'compare') {
      if (!a) return msg('the trigger needs an address', true), null;
      trig = k === 'compare' ? a + ' ' + $('trop').value + ' ' + v : k + ' ' + a;
      if (k === 'compare' && !v) return msg('the comparison needs a value', true), null;
    }
    if (/[#\n]/.test(sig.join('') + trig)) return msg('no # or line breaks in a field', true), null;
    return 'signal ' + sig.join(', ') + '\ntrigger ' + trig + '\npre ' + (+$('trpre').value || 0) +
      '\npost ' + (+$('trpost').value || 0) + '\nmode ' + $('trmode').value + '\n';
  }
  /// The form from the server's definition (once, while the user has not typed).
  function fill(text) {
    text.split('\n').forEach(function (line) {
      const w = line.trim().split(/\s+/), rest = line.trim().slice(w[0].length).trim();
      if (w[0] === 'signal') $('trsig').value = ($('trsig').value ? $('trsig').value + ', ' : '') + rest;
      if (w[0] === 'pre') $('trpre').value = w[1];
      if (w[0] === 'post') $('trpost').value = w[1];
      if (w[0] === 'mode') $('trmode').value = w[1];
      if (w[0] === 'trigger') {
        if (w[1] === 'rising' || w[1] === 'falling' || w[1] === 'manual' || w[1] === 'immediate') {
          $('trkind').value = w[1];
          $('traddr').value = w[2] || '';
        } else {
          $('trkind').value = 'compare';
          $('traddr').value = w[1];
          $('trop').value = w[2];
          $('trval').value = w[3];
        }
      }
    });
    kindShown();
  }

  function command(action) {
    let chain = Promise.resolve({ status: 200, body: { ok: true } });
    if (action === 'arm') {
      // The form is what is armed: defined first when it differs from the server's trace.
      const text = definition();
      if (text === null) return Promise.resolve(null);
      if (!T.status || T.status.definition !== text) {
        chain = api({ action: 'define', text: text, file: 'page' });
      }
    }
    return chain.then(function (r) {
      if (!r.body.ok) return r;
      return api({ action: action });
    }).then(function (r) {
      if (!r) return r;
      if (r.body.ok) {
        msg(action + ': ok');
        show(r.body);
      } else {
        msg(action + ' refused (' + r.status + '): ' + (r.body.error || '?'), true);
      }
      poll();
      return r;
    });
  }
  panel.addEventListener('click', function (e) {
    const act = e.target.dataset && e.target.dataset.act;
    if (act) command(act);
    const s = e.target.dataset && e.target.dataset.sig;
    if (s) find(s);
  });
  L.traceCommand = command;

  // ---- status and polling --------------------------------------------------------------------
  function show(st) {
    T.status = st;
    T.readOnly = !!st.read_only;
    $('trstate').textContent = st.state + (st.armed && st.state !== 'done' ? ' (armed)' : '') + ' · samples ' + st.samples +
      ' · captures ' + st.captures + (st.dropped ? ' · dropped ' + st.dropped : '') +
      (st.last_capture ? ' · last: capture ' + st.last_capture.capture + ', trigger at tick ' +
        st.last_capture.trigger_tick : '');
    $('trstate').className = st.armed && st.state !== 'done' ? 'armed' : '';
    panel.querySelectorAll('button[data-act]').forEach(function (b) { b.disabled = T.readOnly; });
    if (T.readOnly) msg('read-only server (serve --http-read-only): the trace is shown; it is driven by monitor trace');
    if (st.definition && !T.touched) {
      T.touched = true;
      fill(st.definition);
    }
  }
  function poll() {
    clearTimeout(T.timer);
    if (!T.on) return;
    api().then(function (r) {
      if (r.body && r.body.ok) {
        show(r.body);
        if (r.body.capture) take(r.body.capture);
      } else {
        msg('trace status (' + r.status + '): ' + ((r.body && r.body.error) || '?'), true);
      }
    }).catch(function () { msg('trace status: no answer', true); }).then(function () {
      clearTimeout(T.timer);
      T.timer = setTimeout(poll, T.status && T.status.armed ? 300 : 1500);
    });
  }

  // ---- a capture -----------------------------------------------------------------------------
  function column(c, rows) {
    if (Array.isArray(c)) return c;
    const out = new Array(rows);
    let at = 0;
    for (let i = 0; i + 1 < c.rle.length; i += 2) {
      for (let n = 0; n < c.rle[i + 1]; n++) out[at++] = c.rle[i];
    }
    return out;
  }
  function take(c) {
    const rows = c.rows, steps = column(c.ticks.steps, rows - 1), ticks = new Array(rows);
    for (let r = 0; r < rows; r++) ticks[r] = r ? ticks[r - 1] + steps[r - 1] : c.ticks.from;
    const cap = {
      id: c.id, capture: c.capture, signals: c.signals, ticks: ticks, rows: rows,
      cols: c.columns.map(function (x) { return column(x, rows); }),
      triggerTick: c.trigger_tick, triggerRow: c.trigger_row, periodMs: c.period_ns / 1e6,
      bits: [], words: []
    };
    c.signals.forEach(function (s, k) { (s.bits === 1 ? cap.bits : cap.words).push(k); });
    T.cap = cap;
    T.haveId = c.id;
    T.a = T.b = null;
    msg('capture ' + c.capture + ': ' + rows + ' ticks, trigger at tick ' + c.trigger_tick);
    // Downloads through GET api/trace?save= (the server's VCD / CSV writer, as monitor trace save).
    const k = '&k=' + encodeURIComponent(KEY);
    $('trvcd').href = 'api/trace?save=vcd' + k;
    $('trvcdb').href = 'api/trace?save=vcd&bits=1' + k;
    $('trcsv').href = 'api/trace?save=csv' + k;
    $('trdl').hidden = false;
    loadLib().then(function (ok) { if (ok) plot(); });
  }
  /// The value of signal k at tick t: the last row at or before t (a tick that did not run has
  /// no row and keeps the previous one's values).
  function valueAt(k, t) {
    const cap = T.cap;
    let lo = 0, hi = cap.rows - 1;
    if (t < cap.ticks[0]) return null;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (cap.ticks[mid] <= t) lo = mid;
      else hi = mid - 1;
    }
    return cap.cols[k][lo];
  }
  T.valueAt = function (name, t) {
    const k = T.cap.signals.findIndex(function (s) { return s.name === name; });
    return k < 0 ? undefined : valueAt(k, t);
  };
  function ms(t) {
    const v = t * T.cap.periodMs;
    return (Math.round(v * 1000) / 1000) + ' ms';
  }

  // ---- the plots -----------------------------------------------------------------------------
  /// Marks drawn under both plots: the trigger tick and the cursors.
  function underlay(ctx, area, g) {
    const cap = T.cap;
    function vline(t, colour, label, dash) {
      if (t === null) return;
      const x = Math.round(g.toDomXCoord(t)); // on whole pixels: the mark keeps its colour
      if (x < area.x - 1 || x > area.x + area.w + 1) return;
      ctx.save();
      ctx.strokeStyle = colour;
      ctx.lineWidth = 2;
      ctx.setLineDash(dash);
      ctx.beginPath();
      ctx.moveTo(x, area.y);
      ctx.lineTo(x, area.y + area.h);
      ctx.stroke();
      ctx.fillStyle = colour;
      ctx.font = 'bold 11px sans-serif';
      ctx.fillText(label, x + 3, area.y + 11);
      ctx.restore();
    }
    vline(cap.triggerTick, '#d50000', 'T', [5, 3]);
    vline(T.a, '#1565c0', 'A', []);
    vline(T.b, '#6a1b9a', 'B', []);
  }
  function axisX(t) { // an axis label: the tick over its time
    return String(t) + '<br><small>' + h(ms(t)) + '</small>';
  }
  function axisValue(t) { // the legend's
    return 'tick ' + t + ' (' + ms(t) + ')';
  }
  function clicked(e, x) {
    const t = Math.round(x);
    if (e.shiftKey || (T.a !== null && T.b === null)) T.b = t;
    else {
      T.a = t;
      T.b = null;
    }
    cursors();
  }
  L.traceCursor = function (which, t) { // tests and keys: set a cursor by tick
    if (which === 'A') T.a = t;
    else T.b = t;
    cursors();
  };
  function redraw() {
    T.graphs.forEach(function (g) { g.updateOptions({}, false); });
  }
  function cursors() {
    const cap = T.cap;
    let s = 'A: ' + (T.a === null ? '—' : 'tick ' + T.a + ' (' + ms(T.a) + ')') + ' · B: ' +
      (T.b === null ? '—' : 'tick ' + T.b + ' (' + ms(T.b) + ')');
    if (T.a !== null && T.b !== null) {
      s += ' · B − A: <b id="trdelta">' + (T.b - T.a) + ' ticks = ' + ms(T.b - T.a) + '</b>';
    }
    $('trcur').innerHTML = s;
    $('trvals').innerHTML = '<tr><th>signal</th><th>A</th><th>B</th><th>at trigger</th></tr>' +
      cap.signals.map(function (sg, k) {
        const cell = function (t) { return '<td>' + (t === null ? '' : h(valueAt(k, t))) + '</td>'; };
        return '<tr><td><a data-sig="' + h(sg.name) + '" title="find in the ladder">' + h(sg.name) + '</a>' +
          (sg.bits > 1 ? ' <small>(' + sg.bits + ' bits)</small>' : '') + '</td>' +
          cell(T.a) + cell(T.b) + cell(cap.triggerTick) + '</tr>';
      }).join('');
    redraw();
  }
  function plot() {
    const cap = T.cap, D = window.Dygraph, nb = cap.bits.length, nw = cap.words.length;
    T.graphs.forEach(function (g) { g.destroy(); });
    T.graphs = [];
    $('trbits').innerHTML = '';
    $('trwords').innerHTML = '';
    // One plot for the bits (a lane each), one small plot per byte or word (its own scale), all
    // with the same plot area and one time axis, drawn under the last plot.
    function options(last, extra) {
      return Object.assign({
        stepPlot: true, drawPoints: false, strokeWidth: 1.6, legend: 'follow', labelsSeparateLines: true,
        underlayCallback: underlay, clickCallback: clicked, width: 596, xLabelHeight: 14, xAxisHeight: last ? 32 : 4,
        xlabel: last ? 'tick · ms (period ' + cap.periodMs + ' ms)' : null, rightGap: 8,
        axes: {
          x: { drawAxis: last, axisLabelFormatter: axisX, valueFormatter: axisValue, pixelsPerLabel: 90 },
          y: { axisLabelWidth: 66 }
        },
        drawCallback: function (g, initial) {
          // Zoom and pan on one plot move the others: one time axis.
          if (initial || T.syncing) return;
          T.syncing = true;
          const w = g.xAxisRange();
          T.graphs.forEach(function (o) { if (o !== g) o.updateOptions({ dateWindow: w }); });
          T.syncing = false;
        }
      }, extra);
    }
    if (nb) {
      const names = cap.bits.map(function (k) { return cap.signals[k].name; });
      const data = cap.ticks.map(function (t, r) {
        return [t].concat(cap.bits.map(function (k, i) { return (nb - 1 - i) * LANE + cap.cols[k][r]; }));
      });
      const div = document.createElement('div');
      $('trbits').appendChild(div);
      const o = options(!nw, {
        labels: ['tick'].concat(names), height: 22 * nb + 18 + (nw ? 4 : 46),
        valueRange: [-0.3, (nb - 1) * LANE + 1.3], drawGrid: false
      });
      // The lanes' names are drawn in the axis' place (underlay); the legend shows the bit, not
      // its lane's height.
      o.axes.y = Object.assign({}, o.axes.y, {
        drawGrid: false, axisLabelFormatter: function () { return ''; },
        valueFormatter: function (v, op, name) {
          const i = names.indexOf(name);
          return String(i < 0 ? v : Math.round(v - (nb - 1 - i) * LANE));
        }
      });
      T.graphs.push(new D(div, data, o));
    }
    cap.words.forEach(function (k, j) {
      const div = document.createElement('div');
      $('trwords').appendChild(div);
      const last = j === nw - 1;
      T.graphs.push(new D(div, cap.ticks.map(function (t, r) { return [t, cap.cols[k][r]]; }), options(last, {
        labels: ['tick', cap.signals[k].name], height: last ? 116 : 72, colors: ['#00695c'],
        ylabel: null, axes: {
          x: { drawAxis: last, axisLabelFormatter: axisX, valueFormatter: axisValue, pixelsPerLabel: 90 },
          y: { axisLabelWidth: 66, pixelsPerLabel: 24 }
        }
      })));
    });
    nameLinks();
    cursors();
  }
  /// The signals' names beside their lanes (the bits) or plots (a byte or word), as links: a
  /// click finds the signal in the ladder.
  function nameLinks() {
    const cap = T.cap;
    panel.querySelectorAll('a.trname').forEach(function (a) { a.remove(); });
    function label(box, k, y, x) {
      const a = document.createElement('a');
      a.className = 'trname';
      a.dataset.sig = cap.signals[k].name;
      a.title = cap.signals[k].name + ': find in the ladder';
      a.textContent = cap.signals[k].name;
      a.style.top = Math.round(y - 8) + 'px';
      if (x !== undefined) a.style.left = Math.round(x) + 'px';
      box.appendChild(a);
    }
    let at = 0;
    if (cap.bits.length) {
      const g = T.graphs[at++];
      cap.bits.forEach(function (k, i) { label($('trbits').firstChild, k, g.toDomYCoord((cap.bits.length - 1 - i) * LANE + 0.5)); });
    }
    cap.words.forEach(function (k, j) {
      const g = T.graphs[at++];
      label($('trwords').children[j], k, g.getArea().y + 12, g.getArea().x + 4);
    });
  }

  // ---- a signal's name: its contacts in the ladder --------------------------------------------
  // The live page's search finds it and lists every use in the cross-reference; then the view
  // goes to its first contact (where the signal is read), when the search's first hit is not one.
  function find(name) {
    const q = $('q');
    if (!q) return;
    q.value = name;
    q.dispatchEvent(new Event('input'));
    q.dispatchEvent(new KeyboardEvent('keydown', { key: 'Enter' }));
    const want = name.toLowerCase();
    let contact = null;
    L.layout.parts.forEach(function (p) {
      p.rungs.forEach(function (r) {
        r.cells.forEach(function (c) {
          const t = (c.text || '').toLowerCase(), s = (c.symbol || '').toLowerCase();
          if (contact === null && /^contact/.test(c.kind) && c.stmt >= 0 && (t === want || s === want)) contact = c.stmt;
        });
      });
    });
    if (contact !== null && L.goTo) L.goTo(contact);
  }
})();
