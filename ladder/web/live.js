// The live part of the ladder page (docs/ladder-view.md "Live view"), appended to renderHtml's
// page by `serve --http`. It reads /api/model once per program version and the SSE stream
// /api/events, colours elements by their trace words, writes box values, draws forces, offers
// search, cross-reference, force on/off/restore, the lock list and the statistics plots. No
// network beyond the serving process, no build step: this file is embedded into the binary as
// it is (ladder/CMakeLists.txt) and linted (tests/lint/live_js.sh).
(function () {
  'use strict';
  var L = window.ladder, model = null, hash = window.LJ_HASH || null, prev = [], lastMsg = null;
  var hits = [], hitAt = -1;

  // ---- lazy drawing: only rungs in or near the view are in the DOM ---------------------------
  var R = JSON.parse(document.getElementById('ladder-rungs').textContent), byId = {}, nDrawn = 0;
  var drawn = new Set();
  function register(div, add) {
    div.querySelectorAll('g.el[data-stmt]').forEach(function (g) {
      var id = g.dataset.stmt;
      if (add) {
        (byId[id] = byId[id] || []).push(g);
      } else if (byId[id]) {
        byId[id] = byId[id].filter(function (x) { return x !== g; });
        if (!byId[id].length) delete byId[id];
      }
    });
  }
  function draw(div) {
    if (div.firstChild) return;
    div.innerHTML = R[div.dataset.p][div.dataset.r];
    register(div, true);
    nDrawn++;
    drawn.add(div);
    markDouble(div);
    if (lastMsg && model) {
      div.querySelectorAll('g.el[data-stmt]').forEach(function (g) { paintOne(g.dataset.stmt, lastMsg.w); });
      paintFlow(div, lastMsg.w);
      forced(lastMsg);
    }
  }
  function undraw(div) {
    if (!div.firstChild) return;
    register(div, false);
    div.innerHTML = '';
    nDrawn--;
    drawn.delete(div);
  }
  var rgs = document.querySelectorAll('div.rg');
  var io = new IntersectionObserver(function (es) {
    es.forEach(function (e) {
      if (e.isIntersecting) draw(e.target);
      else undraw(e.target);
    });
  }, { rootMargin: '800px 400px' });
  rgs.forEach(function (d) { io.observe(d); });
  function rungDiv(p, k) {
    return document.querySelector('div.rg[data-p="' + p + '"][data-r="' + k + '"]');
  }

  // The token is in an HttpOnly cookie (set when the page was opened with ?token=); the API also
  // wants the page's key, which only a reader of this page has (no cross-site request can send it).
  var KEY = window.LJ_KEY || '', HK = { 'X-Ladderjit-Key': KEY };
  // Program text (addresses, symbols, part names) into markup only through h().
  function h(s) {
    return String(s).replace(/[&<>"']/g, function (c) { return '&#' + c.charCodeAt(0) + ';'; });
  }
  var bar = document.createElement('div');
  bar.id = 'live';
  bar.innerHTML = '<span class="st" id="conn">connecting</span><span id="ver"></span><span id="tick"></span>' +
    '<label>search <input id="q" size="18" placeholder="address, symbol, text or #rung"></label>' +
    '<button id="qup" title="previous hit (Shift+Enter, 向上查找)">▲</button>' +
    '<button id="qdn" title="next hit (Enter, 向下查找)">▼</button><span id="qres"></span>' +
    '<span id="msg"></span>';
  document.body.insertBefore(bar, document.querySelector('nav'));
  document.body.classList.add('live');
  var side = document.createElement('div');
  side.id = 'side';
  side.innerHTML = '<h3>Statistics</h3><div id="counters"></div><div>scan time (us)</div>' +
    '<canvas id="hscan" width="310" height="90"></canvas>' +
    '<div>jitter (us)</div><canvas id="hjit" width="310" height="90"></canvas>' +
    '<div>overruns + missed deadlines over time</div><canvas id="tser" width="310" height="70"></canvas>' +
    '<h3>Forces</h3><div id="forces">none</div><h3>Lock list</h3><div id="locks">none</div>' +
    '<h3>Watch table (状态显示)</h3><div id="watch"></div>' +
    '<h3>Cross-reference</h3><div id="xref">click an element or search an address</div>' +
    '<h3>Double coils</h3><div id="dbl"></div>';
  document.body.appendChild(side);
  var menu = document.createElement('div');
  menu.id = 'menu';
  document.body.appendChild(menu);
  // The status line: a message stays readable for 6 s (a refusal 20 s), then fades; the text
  // stays in place until the next one.
  var sayTimer = null;
  function say(t, bad) {
    var m = document.getElementById('msg');
    m.textContent = t;
    m.style.color = bad ? '#f99' : '#9f9';
    m.classList.remove('old');
    clearTimeout(sayTimer);
    sayTimer = setTimeout(function () { m.classList.add('old'); }, bad ? 20000 : 6000);
  }
  function setConn(t, ok) {
    var c = document.getElementById('conn');
    c.textContent = t;
    c.className = 'st ' + (ok ? 'ok' : 'bad');
  }

  // ---- the layout: where each address is used ------------------------------------------------
  var uses = {}, cellOf = {};
  L.layout.parts.forEach(function (p, pi) {
    p.rungs.forEach(function (r, ri) {
      r.cells.forEach(function (c) {
        if (c.stmt >= 0) cellOf[c.stmt] = { part: pi, index: ri, name: p.name, rung: r.number, cell: c };
        function use(a, role) {
          if (!a) return;
          a = a.replace(/\s*<.*>$/, '');
          (uses[a] = uses[a] || []).push({ part: pi, name: p.name, rung: r.number, role: role, stmt: c.stmt });
        }
        if (c.kind === 'contact-instr' || c.kind === 'compare' || c.kind === 'operate') {
          // drawn as written (XOR %M2, %MW0 > 5): its operands are the addresses it uses
          (c.operands || []).forEach(function (o) { use(o, 'operand of ' + c.text); });
        } else if (/^contact/.test(c.kind)) {
          use(c.text, 'read');
        } else if (/^(coil|coil-not|set|rst)$/.test(c.kind)) {
          use(c.text, c.kind === 'coil' || c.kind === 'coil-not' ? 'write (coil)' : 'write (' + c.kind + ')');
        } else if (c.kind === 'box') {
          (c.operands || []).forEach(function (o) { use(o, 'operand of ' + c.text); });
        }
      });
    });
  });
  // An element as a technician names it: its address (or instruction), part and rung.
  function named(id) {
    var c = cellOf[id];
    return c ? (c.cell.text || c.cell.kind) + ' (' + c.name + ' rung ' + c.rung + ')' : 'statement ' + id;
  }
  L.named = named;
  // A coil whose address another coil also writes (双线圈) is drawn marked: red glyph, "2×".
  function markDouble(div) {
    div.querySelectorAll('g.el.coil[data-stmt], g.el.coil-not[data-stmt]').forEach(function (g) {
      var c = cellOf[g.dataset.stmt];
      if (!c || !uses[c.cell.text] || coils(c.cell.text) < 2 || g.querySelector('text.dblm')) return;
      g.classList.add('dbl');
      var s = g.querySelector('path.sym'), t = document.createElementNS('http://www.w3.org/2000/svg', 'text');
      var bb = s.getBBox();
      t.setAttribute('class', 'dblm'); // left of the glyph above the wire: clear of the rail
      t.setAttribute('x', bb.x - 4);
      t.setAttribute('y', bb.y + 3);
      t.setAttribute('text-anchor', 'end');
      t.textContent = coils(c.cell.text) + '× 双线圈';
      g.appendChild(t);
    });
  }
  function coils(a) { return uses[a].filter(function (u) { return u.role === 'write (coil)'; }).length; }
  var dbl = Object.keys(uses).filter(function (a) { return coils(a) > 1; });
  document.getElementById('dbl').innerHTML = dbl.length ? dbl.map(function (a) {
    return '<div class="warn">' + h(a) + ': ' + coils(a) + ' coils <a data-x="' + h(a) + '">where</a></div>';
  }).join('') : 'none';
  function goTo(stmt) {
    var c = cellOf[stmt];
    if (!c) return;
    var b = document.querySelectorAll('.tab')[c.part];
    if (b) b.click();
    var d = rungDiv(c.part, c.index);
    if (d) draw(d);
    var g = (byId[stmt] || [])[0];
    if (g) {
      mark([g]);
      g.scrollIntoView({ block: 'center', inline: 'center' });
    }
  }
  L.goTo = goTo;
  L.drawn = function () { return nDrawn; };
  L.rungDiv = rungDiv;
  L.drawRung = draw;
  function mark(gs) {
    document.querySelectorAll('g.hit').forEach(function (g) {
      g.classList.remove('hit');
      var r = g.querySelector('rect.hl');
      if (r) r.remove();
    });
    gs.forEach(function (g) {
      g.classList.add('hit');
      var bb = g.getBBox(), r = document.createElementNS('http://www.w3.org/2000/svg', 'rect');
      r.setAttribute('class', 'hl');
      r.setAttribute('x', bb.x - 3);
      r.setAttribute('y', bb.y - 3);
      r.setAttribute('width', bb.width + 6);
      r.setAttribute('height', bb.height + 6);
      g.insertBefore(r, g.firstChild);
    });
  }
  // The cross-reference of an address (docs/ladder-view.md "Cross-reference"): its uses as
  // drawn, then the statements whose operands overlap it in memory (R0.2 is written by
  // `WAND R0 0xE0 R0`), from the model's operand extents; the current values of it and of each
  // overlapping operand, read when it opens.
  function overlap(x, y) {
    if (x[1] + x[2] <= y[1] || y[1] + y[2] <= x[1]) return false;
    return x[3] < 0 || y[3] < 0 || x[1] * 8 + x[3] === y[1] * 8 + y[3];
  }
  function overlapping(a, u) {
    var mem = (model && model.mem) || {}, A = a.toLowerCase(), mine = {}, targets = [], out = [];
    u.forEach(function (x) {
      mine[x.stmt] = true;
      var es = mem[x.stmt] || [];
      es.forEach(function (e) { if (es.length === 1 || e[0].toLowerCase() === A) targets.push(e); });
    });
    Object.keys(mem).forEach(function (id) {
      if (mine[id]) return;
      mem[id].forEach(function (e) {
        if (!targets.some(function (t) { return overlap(t, e); }) || !cellOf[id]) return;
        var same = out.filter(function (x) { return x.stmt === +id && x.text === e[0]; })[0];
        if (same) {
          same.r = same.r || !e[4];
          same.w = same.w || !!e[4];
        } else {
          out.push({ stmt: +id, text: e[0], w: !!e[4], r: !e[4] });
        }
      });
    });
    return out;
  }
  // One API request of the page's scripts (editor.js and trace.js use it too): GET, or POST of
  // `body` as JSON, with the page's key; {status, body} with the answer's JSON ({} if none).
  L.api = function (path, body) {
    var init = { headers: { 'X-Ladderjit-Key': KEY } };
    if (body !== undefined) {
      init.method = 'POST';
      init.headers['Content-Type'] = 'application/json';
      init.body = JSON.stringify(body);
    }
    return fetch(path, init).then(function (r) {
      return r.json().catch(function () { return {}; }).then(function (j) {
        return { status: r.status, body: j };
      });
    });
  };
  function readAddrs(list) {
    return fetch('api/read?a=' + list.map(encodeURIComponent).join(','), { headers: HK }).then(function (r) {
      return r.json().then(function (j) { return { ok: r.ok, body: j }; });
    });
  }
  function xref(a) {
    var u = uses[a] || [], d = document.getElementById('xref'), o = overlapping(a, u);
    var w = u.filter(function (x) { return x.role === 'write (coil)'; }).length;
    var where = function (id, name, rung) {
      return '<a data-s="' + h(id) + '">' + h(name) + ' rung ' + h(rung) + '</a> ';
    };
    d.innerHTML = '<b>' + h(a) + '</b> <span class="xv" data-a="' + h(a) + '"></span>: ' + u.length + ' use(s)' +
      (w > 1 ? ' <span class="warn">double coil (' + w + ')</span>' : '') +
      u.map(function (x) { return '<div>' + where(x.stmt, x.name, x.rung) + h(x.role) + '</div>'; }).join('') +
      (o.length ? '<div class="xo">overlapping in memory:</div>' + o.map(function (x) {
        var cc = cellOf[x.stmt], c = cc.cell;
        return '<div>' + where(x.stmt, cc.name, cc.rung) + (x.w ? (x.r ? 'reads and writes ' : 'writes ') : 'reads ') + h(x.text) + ' <span class="xv" data-a="' +
          h(x.text) + '"></span> in ' + h(c.text + (c.operands ? ' ' + c.operands.join(' ') : '')) + '</div>';
      }).join('') : '');
    var names = [a].concat(o.map(function (x) { return x.text; })).filter(function (x, i, l) { return l.indexOf(x) === i; });
    readAddrs(names.slice(0, 64)).then(function (r) {
      if (!r.ok) return;
      d.querySelectorAll('span.xv').forEach(function (sp) {
        var k = names.indexOf(sp.dataset.a);
        if (k >= 0) sp.textContent = '= ' + L.watch.shown(r.body.values[k], r.body.bits[k], r.body.bits[k] > 1 ? 'hex' : 'dec');
      });
    }, function () {});
  }
  L.xref = xref;
  side.addEventListener('click', function (e) {
    var t = e.target;
    if (t.dataset.s) goTo(t.dataset.s);
    if (t.dataset.x) xref(t.dataset.x);
  });
  // Search as on the HNC-8 screen (docs/ladder-view.md "Search"): Enter or ▼ the next hit,
  // Shift+Enter or ▲ the previous one (向下/向上查找). A hit is an element whose address or
  // symbol is the text (or whose symbol holds it), a box or written instruction whose mnemonic
  // is it (TMRB, CALL), or an element or rung whose comment holds it. `#N` or `rung N` goes to
  // rung N of the shown part, `PLC2#N` / `PLC2 rung N` of that part.
  function findHits(v) {
    var out = [];
    L.layout.parts.forEach(function (p) {
      p.rungs.forEach(function (r) {
        var first = null, inRung = (r.comment || []).join(' ').toLowerCase().indexOf(v) >= 0;
        r.cells.forEach(function (c) {
          if (c.stmt < 0 || c.stmt === undefined || c.kind === 'wire' || c.kind === 'vlink' || c.kind === 'join') return;
          if (first === null) first = c.stmt;
          var t = (c.text || '').toLowerCase(), sy = (c.symbol || '').toLowerCase();
          var o = (c.operands || []).join(' ').toLowerCase(), cm = (c.comment || '').toLowerCase();
          if (t === v || t.split(' ')[0] === v || sy.indexOf(v) >= 0 || (' ' + o + ' ').indexOf(' ' + v + ' ') >= 0 ||
              cm.indexOf(v) >= 0) out.push(c.stmt);
        });
        if (inRung && first !== null && out.indexOf(first) < 0) out.push(first);
      });
    });
    return out;
  }
  function goToRung(part, n) {
    var sel = document.querySelector('section.part.sel'), pi = -1;
    L.layout.parts.forEach(function (p, k) {
      if (part ? p.name.toLowerCase() === part.toLowerCase() : sel && p.name === sel.dataset.part) pi = k;
    });
    if (pi < 0) return false;
    var ri = -1;
    L.layout.parts[pi].rungs.forEach(function (r, k) { if (r.number === n) ri = k; });
    if (ri < 0) return false;
    var b = document.querySelectorAll('.tab')[pi];
    if (b) b.click();
    var d = rungDiv(pi, ri);
    draw(d);
    d.scrollIntoView({ block: 'center' });
    var c = L.layout.parts[pi].rungs[ri].cells.filter(function (x) { return x.stmt >= 0 && byId[x.stmt]; })[0];
    mark(c ? byId[c.stmt].slice(0, 1) : []);
    return true;
  }
  var lastQ = '';
  function search(dir) {
    var raw = document.getElementById('q').value.trim(), v = raw.toLowerCase(), res = document.getElementById('qres');
    if (!v) return;
    var m = /^(?:(\S+?)\s*)?(?:#|rung\s+)(\d+)$/i.exec(raw);
    if (m) {
      res.textContent = goToRung(m[1], +m[2]) ? 'rung ' + m[2] : 'no rung ' + m[2];
      return;
    }
    if (v !== lastQ) {
      hits = findHits(v);
      hitAt = dir > 0 ? -1 : 0;
      lastQ = v;
    }
    var n = Math.max(hits.length, 1);
    hitAt = ((hitAt + dir) % n + n) % n;
    res.textContent = hits.length ? (hitAt + 1) + '/' + hits.length : 'not found';
    if (hits.length) {
      goTo(hits[hitAt]);
      var c = cellOf[hits[hitAt]].cell;
      if (c.text && /^(contact|coil|set|rst)/.test(c.kind)) xref(c.text);
      else if (uses[raw] || uses[raw.toUpperCase()]) xref(uses[raw] ? raw : raw.toUpperCase());
    }
  }
  L.search = search;
  document.getElementById('q').addEventListener('keydown', function (e) {
    if (e.key === 'Enter') search(e.shiftKey ? -1 : 1);
  });
  document.getElementById('qup').addEventListener('click', function () { search(-1); });
  document.getElementById('qdn').addEventListener('click', function () { search(1); });
  document.getElementById('q').addEventListener('input', function () { lastQ = ''; });
  document.addEventListener('click', function (e) {
    menu.style.display = 'none';
    var g = e.target.closest && e.target.closest('g.el[data-stmt]');
    if (g && !e.target.closest('#side')) {
      var c = cellOf[g.dataset.stmt];
      if (c && c.cell.text) xref(c.cell.text);
    }
  });

  // ---- force from the page (允许 on / 禁止 off / 恢复 restore) -------------------------------
  // The addresses an element names: a contact's or coil's address, a box's register operands.
  function addressesOf(c) {
    if (!c) return [];
    if (/^(contact-(no|nc|rise|fall)|coil|coil-not|set|rst)$/.test(c.kind)) return [c.text];
    return (c.operands || []).filter(function (o) { return /[A-Za-z%]/.test(o) && !/^[-+]?(0x)?[0-9A-Fa-f]+$/.test(o); });
  }
  document.addEventListener('contextmenu', function (e) {
    var g = e.target.closest && e.target.closest('g.el[data-stmt]');
    if (!g) return;
    var id = g.dataset.stmt, contact = /contact-(no|nc|rise|fall)/.test(g.getAttribute('class'));
    var watch = addressesOf((cellOf[id] || {}).cell);
    if (!contact && !watch.length) return;
    e.preventDefault();
    menu.innerHTML = (contact ? '<div data-m="on">force on (允许)</div><div data-m="off">force off (禁止)</div>' +
      '<div data-m="restore">restore (恢复)</div>' : '') + watch.map(function (a) {
      return '<div data-w="' + h(a) + '">watch ' + h(a) + ' (状态显示)</div>';
    }).join('');
    menu.style.left = e.clientX + 'px';
    menu.style.top = e.clientY + 'px';
    menu.style.display = 'block';
    menu.onclick = function (ev) {
      var m = ev.target.dataset.m;
      if (m) L.force(id, m);
      if (ev.target.dataset.w) L.watch.add(ev.target.dataset.w);
      menu.style.display = 'none';
    };
  });
  L.force = function (id, mode) {
    return fetch('api/force', {
      method: 'POST',
      headers: { 'Content-Type': 'application/json', 'X-Ladderjit-Key': KEY },
      body: JSON.stringify({ id: +id, mode: mode })
    }).then(function (r) {
      return r.json().then(function (j) {
        var what = { on: 'forced ON (允许)', off: 'forced OFF (禁止)', restore: 'restored (恢复)' }[mode] || mode;
        say(r.ok ? named(id) + ' ' + what : 'force of ' + named(id) + ' refused (' + r.status + '): ' + j.error, !r.ok);
        return { status: r.status, body: j };
      });
    });
  };

  // ---- the watch table (诊断→状态显示, docs/ladder-view.md "Watch table") ------------------------
  // Addresses or symbols in the program's dialect, read through GET /api/read (monitor read's
  // command) four times a second, each shown in the format chosen for its row; written through
  // POST /api/write with the token (refused under --http-read-only). The rows are kept in the
  // browser per program file.
  L.watch = (function () {
    var key = 'ladderjit-watch:' + L.layout.file, rows = [], box = document.getElementById('watch');
    var FMT = ['dec', 'unsigned', 'hex', 'bin', 'BCD'];
    try { rows = JSON.parse(localStorage.getItem(key) || '[]'); } catch (e) { rows = []; }
    function save() { localStorage.setItem(key, JSON.stringify(rows.map(function (r) { return { a: r.a, f: r.f }; }))); }
    function mask(bits) { return bits >= 32 ? 4294967296 : Math.pow(2, bits); }
    function unsigned(v, bits) { return ((v % mask(bits)) + mask(bits)) % mask(bits); }
    // A value in a format: bits 1 as 0/1; BCD digit by digit (a nibble over 9 is not BCD).
    function shown(v, bits, f) {
      if (v === undefined || v === null) return '';
      if (bits === 1) return String(v);
      var u = unsigned(v, bits);
      if (f === 'unsigned') return String(u);
      if (f === 'hex') return '0x' + ('00000000' + u.toString(16).toUpperCase()).slice(-bits / 4);
      if (f === 'bin') return ('0'.repeat(bits) + u.toString(2)).slice(-bits).replace(/(\d{4})(?=\d)/g, '$1 ');
      if (f === 'BCD') {
        var x = u.toString(16);
        return /^[0-9]+$/.test(x) ? String(+x) : 'not BCD (0x' + x.toUpperCase() + ')';
      }
      return String(v);
    }
    // What a typed value writes: BCD digits as their nibbles, else the text (decimal or 0x hex).
    function typed(t, f) {
      t = t.trim();
      if (f === 'BCD') return /^[0-9]{1,8}$/.test(t) ? '0x' + t : null;
      if (f === 'bin') return /^[01 ]+$/.test(t) ? String(parseInt(t.replace(/ /g, ''), 2)) : null;
      return /^([-+]?[0-9]+|0x[0-9A-Fa-f]+)$/.test(t) ? t : null;
    }
    function render() {
      var rw = !window.LJ_RO; // a --http-read-only page shows no write controls
      box.innerHTML = '<div><input id="wadd" size="12" placeholder="address or symbol"> <button id="waddb">add</button>' +
        ' <span id="werr" class="warn"></span></div>' + (rows.length ? '<div class="wscroll"><table id="wt"><tr><th>address</th><th>value</th>' +
        '<th>format</th>' + (rw ? '<th>write</th>' : '') + '<th></th></tr>' + rows.map(function (r, i) {
          return '<tr data-i="' + i + '"><td><a data-x="' + h(r.a) + '">' + h(r.a) + '</a></td><td class="wv">' +
            h(shown(r.v, r.bits, r.f)) + '</td><td>' + (r.bits === 1 ? 'bit' : '<select>' + FMT.map(function (f) {
              return '<option' + (f === r.f ? ' selected' : '') + '>' + f + '</option>';
            }).join('') + '</select>') + '</td>' + (rw ? '<td>' + (r.bits === 1 ? '<button data-b="1">1</button><button data-b="0">0</button>'
            : '<input size="5" class="wi"><button data-b="w">set</button>') + '</td>' : '') +
            '<td><button data-b="x" title="remove">×</button></td></tr>';
        }).join('') + '</table></div>' : '');
    }
    function paintValues() {
      box.querySelectorAll('tr[data-i]').forEach(function (tr) {
        var r = rows[+tr.dataset.i];
        tr.querySelector('td.wv').textContent = shown(r.v, r.bits, r.f);
      });
    }
    var read = readAddrs;
    var busy = false, known = false;
    function poll() {
      if (busy || !rows.length) return;
      busy = true;
      read(rows.map(function (r) { return r.a; })).then(function (a) {
        busy = false;
        if (!a.ok) return;
        a.body.values.forEach(function (v, i) {
          if (rows[i]) {
            rows[i].v = v;
            rows[i].bits = a.body.bits[i];
          }
        });
        if (!known) render(); // the rows kept from an earlier visit learn their widths
        else paintValues();
        known = true;
      }, function () { busy = false; });
    }
    setInterval(poll, 250);
    function add(a) {
      a = String(a).trim();
      var err = document.getElementById('werr');
      if (!a) return Promise.resolve(false);
      if (rows.some(function (r) { return r.a.toLowerCase() === a.toLowerCase(); })) return Promise.resolve(true);
      return read([a]).then(function (res) {
        if (!res.ok) {
          document.getElementById('werr').textContent = res.body.error || 'refused';
          return false;
        }
        rows.push({ a: a, f: 'dec', v: res.body.values[0], bits: res.body.bits[0] });
        save();
        render();
        return true;
      }, function () {
        if (err) err.textContent = 'no answer';
        return false;
      });
    }
    function write(i, text) {
      var r = rows[i], v = r.bits === 1 ? text : typed(text, r.f);
      if (v === null) {
        say('not a ' + r.f + ' value for ' + r.a + ': ' + text, true);
        return Promise.resolve(false);
      }
      return fetch('api/write', {
        method: 'POST',
        headers: { 'Content-Type': 'application/json', 'X-Ladderjit-Key': KEY },
        body: JSON.stringify({ writes: [r.a + '=' + v] })
      }).then(function (res) {
        return res.json().then(function (j) {
          say(res.ok ? r.a + ' := ' + text + ' written' : 'write of ' + r.a + ' refused (' + res.status + '): ' + j.error, !res.ok);
          poll();
          return res.ok;
        });
      });
    }
    box.addEventListener('click', function (e) {
      var t = e.target, tr = t.closest('tr[data-i]');
      if (t.id === 'waddb') add(document.getElementById('wadd').value);
      if (!tr || !t.dataset.b) return;
      var i = +tr.dataset.i;
      if (t.dataset.b === 'x') {
        rows.splice(i, 1);
        save();
        render();
      } else if (t.dataset.b === 'w') {
        write(i, tr.querySelector('input.wi').value);
      } else {
        write(i, t.dataset.b);
      }
    });
    box.addEventListener('keydown', function (e) {
      if (e.key !== 'Enter') return;
      if (e.target.id === 'wadd') add(e.target.value);
      var tr = e.target.closest('tr[data-i]');
      if (tr && e.target.classList.contains('wi')) write(+tr.dataset.i, e.target.value);
    });
    box.addEventListener('change', function (e) {
      var tr = e.target.closest('tr[data-i]');
      if (!tr || e.target.tagName !== 'SELECT') return;
      rows[+tr.dataset.i].f = e.target.value;
      save();
      paintValues();
    });
    render();
    poll();
    return { add: add, write: write, rows: function () { return rows; }, shown: shown };
  })();

  // ---- live state ----------------------------------------------------------------------------
  function loadModel() {
    return fetch('api/model', { headers: HK })
      .then(function (r) { return r.json(); })
      .then(function (m) { model = m; prev = []; });
  }
  // A box's values (docs/ladder-view.md "Box values"): each register operand's value after its
  // own operand line ("F2560 = 2"), constants not echoed, and the rest (a timer's elapsed ms, a
  // counter's count, an operand the box does not draw as written) on the values line, labelled.
  function valLine(g) {
    var t = g.querySelector('text.val');
    if (t) return t;
    var r = g.querySelector('rect.box');
    if (!r) return null;
    t = document.createElementNS('http://www.w3.org/2000/svg', 'text');
    t.setAttribute('class', 'val');
    t.setAttribute('text-anchor', 'middle');
    t.setAttribute('x', +r.getAttribute('x') + +r.getAttribute('width') / 2);
    var by = +r.getAttribute('y'), vy = by + +r.getAttribute('height') - 4, ts = g.querySelectorAll('text.mn,text.op');
    // A box whose operand lines fill it (a one-row EQB D0 8): its lines move closer so the
    // values line covers none.
    if (ts.length > 1 && +ts[ts.length - 1].getAttribute('y') > vy - 12) {
      var s = (vy - 12 - (by + 12)) / (ts.length - 1);
      ts.forEach(function (x, i) { x.setAttribute('y', by + 12 + i * s); });
    }
    t.setAttribute('y', vy);
    g.appendChild(t);
    return t;
  }
  function boxVal(g, vals, labels) {
    var t = valLine(g);
    if (!t) return;
    var ops = Array.prototype.slice.call(g.querySelectorAll('text.op')), rest = [];
    ops.forEach(function (o) {
      var v = o.querySelector('tspan.v');
      if (v) v.remove();
    });
    if (!vals) {
      t.textContent = 'not scanned';
      return;
    }
    if (!labels) {
      t.textContent = vals.join('  ');
      return;
    }
    vals.forEach(function (x, k) {
      var name = labels[k];
      if (name === null || name === undefined) return;
      var o = ops.filter(function (e) { return e.firstChild && e.firstChild.nodeValue === name && !e.querySelector('tspan.v'); })[0];
      if (o) {
        var s = document.createElementNS('http://www.w3.org/2000/svg', 'tspan');
        s.setAttribute('class', 'v');
        s.textContent = ' = ' + x;
        o.appendChild(s);
      } else {
        rest.push(name + ' = ' + x);
      }
    });
    t.textContent = rest.join('  ');
  }
  function paintOne(id, w) {
    var d = model.stmts[id], gs = byId[id];
    if (!d || !gs || !w) return;
    var at = d[0], k = d[1], n = d[2], ns = w[at] === null;
    var on = !ns && !!(k === 'box' ? w[at + 1] : w[at]);
    gs.forEach(function (g) {
      g.classList.toggle('on', on);
      g.classList.toggle('off', !on && !ns);
      g.classList.toggle('ns', ns);
      if (k === 'box' && n > 2) {
        boxVal(g, ns ? null : w.slice(at + 2, at + n).map(function (x) { return x === null ? -2147483648 : x; }), d[3]);
      }
    });
  }
  // ---- power flow along the wires (docs/ladder-view.md "Power flow") -------------------------
  // Relay logic over the drawn grid, from the traced values of the same frame: the left rail
  // powers column 0 of every row; a vertical link joins the grid points it spans; an element
  // passes power from its left point to its right one when it conducts (a contact or compare:
  // its traced value; a box: its traced output; a wire: always); an output ends its path. Power
  // only flows rightwards, so one pass over the cells by column settles every point.
  var CONTACT = /^(contact|compare$)/;
  // The traced value of statement `id`: a box's output (its first word, EN, when `input`), else
  // its first word (a contact's conduction, a coil's input, a jump's EN).
  function traced(id, w, input) {
    var d = model.stmts[id];
    if (!d) return null;
    var x = w[d[0] + (d[1] === 'box' && !input ? 1 : 0)];
    return x === null || x === undefined ? null : x ? 1 : 0;
  }
  function flowOf(rung, w) {
    var up = {}, pw = {}, el = {}, ns = false;
    function find(k) {
      while (up[k] !== undefined) k = up[k];
      return k;
    }
    function at(r, c) { return find(r + ',' + c); }
    var cells = rung.cells.slice().sort(function (a, b) { return a.col - b.col; });
    cells.forEach(function (c) {
      for (var k = 0; c.kind === 'vlink' && k < (c.height || 1); k++) {
        var a = at(c.row + k, c.col), b = at(c.row + k + 1, c.col);
        if (a !== b) up[a] = b;
      }
    });
    for (var r = 0; r < rung.rows; r++) pw[at(r, 0)] = true;
    cells.forEach(function (c) {
      if (c.kind === 'vlink' || c.kind === 'join') return;
      var i = !!pw[at(c.row, c.col)], o = false, v = null;
      if (c.kind === 'wire') {
        o = i;
      } else if (c.stmt >= 0) {
        var sink = !CONTACT.test(c.kind) && c.kind !== 'box';
        v = traced(c.stmt, w, sink); // an output (a coil, END drawn as written...): its input
        if (v === null) ns = true;
        if (CONTACT.test(c.kind)) o = i && v === 1;
        else if (c.kind === 'box') o = v === 1;
        el[c.stmt] = { i: i, o: o, v: v, pins: (c.pins || []).filter(function (p) { return p > 0; }).map(function (p) {
          return !!pw[at(c.row + p, c.col)];
        }), sink: sink };
      }
      if (o) pw[at(c.row, c.col + c.width)] = true;
    });
    return { on: function (row, col) { return !!pw[at(row, col)]; }, el: el, ns: ns };
  }
  // Wires and links by the point they start at, each element's input and output stubs by its
  // own input and output (an output's stub to the rail by its traced input), and a contact that
  // conducts with no power reaching it marked apart from the live path (class cnp).
  function paintFlow(div, w) {
    var rung = L.layout.parts[div.dataset.p].rungs[div.dataset.r];
    if (!rung || rung.kind !== 'ladder' || !w) return;
    var f = flowOf(rung, w);
    div.querySelectorAll('[data-at]').forEach(function (e) {
      var a = e.getAttribute('data-at').split(',');
      e.classList.toggle('p', !f.ns && f.on(+a[0], +a[1]));
    });
    div.querySelectorAll('g.el[data-stmt]').forEach(function (g) {
      var s = f.el[g.dataset.stmt], ws = g.querySelectorAll('line.w');
      if (!s) return;
      g.classList.toggle('pwi', !f.ns && s.i);
      g.classList.toggle('cnp', !f.ns && !s.sink && s.v === 1 && !s.i);
      ws.forEach(function (l, k) {
        var p = k === 0 ? s.i : k === ws.length - 1 ? (s.sink ? s.v === 1 : s.o) : s.pins[k - 1];
        l.classList.toggle('p', !f.ns && !!p);
      });
    });
  }
  L.flowOf = function (p, r) { return lastMsg && model ? flowOf(L.layout.parts[p].rungs[r], lastMsg.w) : null; };
  function paint(m) {
    if (!model || !m.w) return;
    var w = m.w;
    for (var id in byId) {
      var d = model.stmts[id];
      if (!d) continue;
      var at = d[0], n = d[2], ch = prev.length === 0;
      for (var i = 0; i < n && !ch; i++) if (prev[at + i] !== w[at + i]) ch = true;
      if (ch) paintOne(id, w);
    }
    drawn.forEach(function (div) { paintFlow(div, w); });
    prev = w;
  }
  function forced(m) {
    document.querySelectorAll('g.forced-on,g.forced-off').forEach(function (g) {
      g.classList.remove('forced-on', 'forced-off');
      var t = g.querySelector('text.fmark');
      if (t) t.remove();
    });
    var f = m.forced || {}, ids = Object.keys(f);
    ids.forEach(function (id) {
      (byId[id] || []).forEach(function (g) {
        g.classList.add(f[id] ? 'forced-on' : 'forced-off');
        var s = g.querySelectorAll('line.sym')[0], t = document.createElementNS('http://www.w3.org/2000/svg', 'text');
        if (!s) return;
        // Right of the glyph above the wire: clear of the address above it and of the left rail
        // a contact in column 0 stands on.
        var s2 = g.querySelectorAll('line.sym')[1] || s;
        t.setAttribute('class', 'fmark');
        t.setAttribute('x', +s2.getAttribute('x1') + 3);
        t.setAttribute('y', +s.getAttribute('y1') + 9);
        t.setAttribute('text-anchor', 'start');
        t.setAttribute('fill', f[id] ? '#00c853' : '#d50000');
        t.textContent = f[id] ? 'F-ON' : 'F-OFF';
        g.appendChild(t);
      });
    });
    document.getElementById('forces').innerHTML = ids.length ? ids.map(function (id) {
      var c = cellOf[id];
      return '<div><a data-s="' + h(id) + '">' + h(c ? c.cell.text + ' (' + c.name + ' rung ' + c.rung + ')' : 'id ' + id) +
        '</a> ' + (f[id] ? 'on' : 'off') + '</div>';
    }).join('') : 'none';
    var lk = m.locks || [];
    document.getElementById('locks').innerHTML = lk.length ? lk.map(function (x) { return '<div>' + h(x) + '</div>'; }).join('') : 'none';
  }
  var series = [];
  function bars(id, hist) {
    var c = document.getElementById(id), x = c.getContext('2d');
    x.clearRect(0, 0, c.width, c.height);
    if (!hist || !hist.bins) return;
    var mx = Math.max.apply(null, hist.bins.concat([1])), bw = (c.width - 2) / hist.bins.length;
    x.fillStyle = '#1565c0';
    hist.bins.forEach(function (v, i) {
      var y = v ? Math.max(1, (c.height - 14) * Math.log(1 + v) / Math.log(1 + mx)) : 0;
      x.fillRect(1 + i * bw, c.height - 12 - y, Math.max(1, bw - 1), y);
    });
    x.fillStyle = '#333';
    x.font = '10px sans-serif';
    x.fillText('0', 1, c.height - 2);
    x.fillText(String(hist.binUs * hist.bins.length), c.width - 30, c.height - 2);
    x.fillText('p99 ' + hist.p99_us + '  max ' + hist.max_us, 90, 10);
  }
  function stats(s) {
    document.getElementById('counters').innerHTML = 'at tick ' + s.tick + ': ticks run ' + s.ticks +
      ' &middot; overruns <b>' + s.overruns + '</b> &middot; missed deadlines <b>' + s.missed_deadlines +
      '</b> &middot; period ' + (s.period_ns / 1e6) + ' ms';
    bars('hscan', s.scan);
    bars('hjit', s.jitter);
    series.push(s.overruns + s.missed_deadlines);
    if (series.length > 120) series.shift();
    var c = document.getElementById('tser'), x = c.getContext('2d');
    x.clearRect(0, 0, c.width, c.height);
    var lo = series[0], hi = Math.max(series[series.length - 1], lo + 1);
    x.strokeStyle = '#d50000';
    x.beginPath();
    series.forEach(function (v, i) {
      var px = i * (c.width / 120), py = c.height - 4 - (c.height - 8) * (v - lo) / (hi - lo);
      if (i) x.lineTo(px, py);
      else x.moveTo(px, py);
    });
    x.stroke();
    x.fillStyle = '#333';
    x.font = '10px sans-serif';
    x.fillText('+' + (hi - lo) + ' over ' + series.length / 2 + ' s', 4, 10);
  }
  function apply(m) {
    lastMsg = m;
    L.live.last = m;
    if (hash && m.hash !== hash) {
      // A new program version: the page of that version (an editor with unsent edits asks first).
      if (L.beforeReload && !L.beforeReload(m)) return;
      setConn('new program version: reloading', true);
      location.reload();
      return;
    }
    hash = m.hash;
    document.getElementById('ver').textContent = 'version ' + m.v +
      (m.traced ? '' : m.aot ? ' (AOT: untraced, no power flow)' : ' (waiting for the traced build)');
    document.getElementById('tick').textContent = 'tick ' + m.tick + (m.w ? '' : ' (no trace)');
    L.live.tick = m.tick;
    var go = function () {
      paint(m);
      forced(m);
      if (m.stats) stats(m.stats);
    };
    if (!model || model.version !== m.v || model.traced !== m.traced) loadModel().then(go);
    else go();
  }
  L.live = { tick: -1, last: null };
  L.say = say;
  L.esc = h;
  function connect() {
    var es = new EventSource('api/events?k=' + encodeURIComponent(KEY));
    es.addEventListener('state', function (e) {
      setConn('live', true);
      apply(JSON.parse(e.data));
    });
    es.onerror = function () { setConn('disconnected: retrying', false); };
  }
  connect();
})();
