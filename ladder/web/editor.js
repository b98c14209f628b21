// The ladder editor of the live page (docs/ladder-edit.md "The page editor"): 梯图编辑 beside the
// live view. It opens the running program's rungs as editor grids (POST api/edit/grid, built by
// ladder/Grid on the server), edits them with a cursor, a toolbar and keys, has every edited rung
// converted and checked as it changes (errors drawn on their cells before anything is sent),
// and on 更新修改 sends the draft (api/edit/draft), checks it (api/edit/check), shows what the
// update does (the diff and what the init part writes) and, once confirmed, updates
// (api/edit/update). 放弃修改 drops the edits and the draft. Only pages that may edit get this
// script (not under --http-read-only); every route checks the token and the page's key again.
(function () {
  'use strict';
  const L = window.ladder;
  if (!L || !L.esc || !L.say || !L.api) return;
  const h = L.esc;
  // The editor's name for itself (docs/ladder-edit.md "One holder"): one per browser tab.
  let EDITOR = 'page-' + Math.random().toString(36).slice(2, 10);
  try {
    EDITOR = sessionStorage.getItem('ljEditor') || EDITOR;
    sessionStorage.setItem('ljEditor', EDITOR);
  } catch (e) {
    // no session storage (a sandboxed frame): a fresh name per page load
  }

  const CW = 84, CH = 58, LM = 16, TOP = 6; // cell width and height, left margin, top margin
  const KINDS = {
    line: '直线 line', no: '常开 NO contact', nc: '常闭 NC contact', rise: 'rising edge contact',
    fall: 'falling edge contact', coil: '逻辑输出 output', 'coil-not': '取反输出 negated output',
    set: 'set output', reset: 'reset output', box: '功能模块 function box'
  };
  const CONTACTS = ['no', 'nc', 'rise', 'fall'], OUTPUTS = ['coil', 'coil-not', 'set', 'reset'];

  // ---- state ---------------------------------------------------------------------------------
  // parts[p]: {name, orig (index in the running JSON's parts, -1 for a new subroutine), sub (a
  // subroutine: 列表编辑 renames and deletes it), rungs}. parts[p].rungs[r]: {orig (index in the
  // running JSON's part, -1 for a new rung), grid (or null with why), json (a rung sent as is: a
  // new part's marker, a rung whose call a rename changed), comment, dirty, errors
  // [{row,col,message}], net (the converted network), cells (statement k -> [row,col]), pending
  // (a conversion is on its way)}. A rung object is never changed in place once shown: an edit
  // makes a new one, so undo keeps the old objects.
  const E = {
    on: false, loaded: false, base: null, running: null, init: null, dialect: '', boxes: [],
    edges: false, symbols: {}, parts: [], p: 0, r: 0, row: 0, col: 0, undo: [], redo: [],
    sent: false, posted: false, input: null, checkTimer: null, mark: null, clip: null, subs: null,
    removes: []
  };

  const api = L.api; // live.js: the page's key, {status, body}

  // ---- the grid model (ladder/Grid.h GridRung) ----------------------------------------------
  function gridOf(j) {
    const g = { rows: j.rows, cols: j.cols, cells: j.cells.map(function (c) { return Object.assign({}, c); }), links: {} };
    (j.links || []).forEach(function (l) { g.links[l[0] + ',' + l[1]] = true; });
    return g;
  }
  function gridJson(g, comment) {
    return {
      rows: g.rows, cols: g.cols, cells: g.cells,
      links: Object.keys(g.links).map(function (k) { return k.split(',').map(Number); }),
      comment: comment || []
    };
  }
  function copyGrid(g) {
    return {
      rows: g.rows, cols: g.cols, cells: g.cells.map(function (c) { return Object.assign({}, c); }),
      links: Object.assign({}, g.links)
    };
  }
  function blank(rows, cols) {
    const g = { rows: rows, cols: cols, cells: [], links: {} };
    for (let i = 0; i < rows * cols; i++) g.cells.push({ k: 'empty' });
    return g;
  }
  function at(g, r, c) { return g.cells[r * g.cols + c]; }
  function put(g, r, c, cell) { g.cells[r * g.cols + c] = cell; }
  function link(g, r, b) { return !!g.links[r + ',' + b]; }
  function setLink(g, r, b, on) {
    if (r < 0 || r + 1 >= g.rows || b < 1 || b >= g.cols) return;
    if (on) g.links[r + ',' + b] = true;
    else delete g.links[r + ',' + b];
  }
  function isEmptyGrid(g) {
    return g.cells.every(function (c) { return c.k === 'empty'; }) && !Object.keys(g.links).length;
  }
  // The rectangle a box at (r, c) covers (its box-part cells to the right and below).
  function boxSpan(g, r, c) {
    let w = 1, hh = 1;
    while (c + w < g.cols && at(g, r, c + w).k === 'box-part') w++;
    while (r + hh < g.rows && at(g, r + hh, c).k === 'box-part') hh++;
    return { w: w, h: hh };
  }
  function clearCell(g, r, c) {
    const cell = at(g, r, c);
    if (cell.k === 'box') {
      const s = boxSpan(g, r, c);
      for (let i = 0; i < s.h; i++) for (let k = 0; k < s.w; k++) put(g, r + i, c + k, { k: 'empty' });
    } else {
      put(g, r, c, { k: 'empty' });
    }
  }
  // 插入行: a row below `r`; a vertical line that crossed the gap passes through the new row.
  function insertRow(g, r) {
    const n = blank(g.rows + 1, g.cols), at2 = r + 1;
    for (let i = 0; i < g.rows; i++) for (let c = 0; c < g.cols; c++) put(n, i < at2 ? i : i + 1, c, Object.assign({}, at(g, i, c)));
    for (let i = 0; i + 1 < g.rows; i++) {
      for (let b = 1; b < g.cols; b++) {
        if (!link(g, i, b)) continue;
        if (i === r) {
          setLink(n, i, b, true);
          setLink(n, i + 1, b, true);
        } else {
          setLink(n, i < at2 ? i : i + 1, b, true);
        }
      }
    }
    return n;
  }
  // 删除行: row `r` goes with its cells; a vertical line that passed through it stays joined.
  function deleteRow(g, r) {
    const n = blank(g.rows - 1, g.cols);
    for (let i = 0; i < n.rows; i++) for (let c = 0; c < g.cols; c++) put(n, i, c, Object.assign({}, at(g, i < r ? i : i + 1, c)));
    for (let i = 0; i + 1 < g.rows; i++) {
      for (let b = 1; b < g.cols; b++) {
        if (!link(g, i, b)) continue;
        if (i === r) continue;
        if (i === r - 1 && !link(g, r, b)) continue;
        setLink(n, i < r ? i : i - 1, b, true);
      }
    }
    return n;
  }
  // 插入列: a column before `c`; where it cuts a connected row a line fills it.
  function insertColumn(g, c) {
    const n = blank(g.rows, g.cols + 1);
    for (let i = 0; i < g.rows; i++) {
      for (let k = 0; k < g.cols; k++) put(n, i, k < c ? k : k + 1, Object.assign({}, at(g, i, k)));
      const right = c < g.cols ? at(g, i, c).k : 'empty', left = c > 0 ? at(g, i, c - 1).k : 'rail';
      const outputLeft = OUTPUTS.indexOf(left) >= 0 || left === 'box' || left === 'box-part';
      if (right !== 'empty' && right !== 'box-part' && left !== 'empty' && !outputLeft) put(n, i, c, { k: 'line' });
    }
    for (let i = 0; i + 1 < g.rows; i++) for (let b = 1; b < g.cols; b++) if (link(g, i, b)) setLink(n, i, b <= c ? b : b + 1, true);
    return n;
  }

  // ---- opening -------------------------------------------------------------------------------
  function rungObj(r, orig) {
    return {
      orig: orig, grid: r.grid ? gridOf(r.grid) : null, why: r.why || '', comment: (r.comment || []).slice(),
      dirty: false, errors: [], net: null, cells: null, pending: false
    };
  }
  // `keep`: stay on the rung shown (放弃修改), else start at the shown part's first rung.
  function open(keep) {
    const was = { p: E.p, r: E.r };
    say('opening the editor...', false);
    return Promise.all([api('api/edit'), api('api/edit/grid', { open: true })]).then(function (a) {
      const st = a[0], g = a[1];
      if (st.status !== 200 || g.status !== 200) {
        say('the editor cannot open: ' + (st.body.error || g.body.error || st.status + '/' + g.status), true);
        return false;
      }
      if (!st.body.running.editable) {
        say('this program cannot be edited here: ' + (st.body.running.why || ''), true);
        return false;
      }
      E.running = st.body.running.networks;
      E.base = st.body.running.hash;
      E.init = st.body.init;
      E.dialect = g.body.dialect;
      E.boxes = g.body.boxes || [];
      E.edges = !!g.body.edges;
      E.symbols = g.body.symbols || {};
      E.subs = g.body.subroutines || null;
      E.parts = g.body.parts.map(function (p, pi) {
        return { name: p.name, orig: pi, sub: !!p.subroutine, rungs: p.rungs.map(function (r, i) { return rungObj(r, i); }) };
      });
      E.undo = [];
      E.redo = [];
      E.sent = false;
      E.posted = false;
      E.loaded = true;
      const d = st.body.draft;
      if (d && d.open && d.editor !== EDITOR) {
        say('a draft is open by editor ' + d.editor + ' (' + d.client + ') since ' + d.since +
          ': 更新修改 is refused while it holds it', true);
      } else {
        say('editing ' + E.dialect + ' program, version ' + st.body.running.version, false);
      }
      if (keep && E.parts[was.p]) {
        select(was.p, was.r);
      } else {
        // Start at the first rung the grid can edit in the shown part.
        const shown = Array.prototype.indexOf.call(document.querySelectorAll('.tab'), document.querySelector('.tab.sel'));
        select(shown >= 0 ? shown : 0, 0, true);
      }
      return true;
    });
  }

  // ---- the panel -----------------------------------------------------------------------------
  const panel = document.createElement('div');
  panel.id = 'editor';
  function tb(act, label, key) {
    return '<button data-act="' + act + '" title="' + h(label + (key ? ' (key ' + key + ')' : '')) + '">' + h(label) +
      (key ? '<kbd>' + h(key) + '</kbd>' : '') + '</button>';
  }
  panel.innerHTML =
    '<div class="row head"><b>梯图编辑 editor</b><span id="edwhere"></span>' +
    tb('prev', '◀ rung', 'PgUp') + tb('next', 'rung ▶', 'PgDn') +
    '<span id="edstate"></span><span style="flex:1"></span>' +
    tb('undo', '撤销 undo', 'Ctrl+Z') + tb('redo', '重做 redo', 'Ctrl+Y') +
    '<button data-act="update" class="go" id="edupdate">更新修改 update</button>' +
    '<button data-act="discard" class="drop" id="eddiscard">放弃修改 discard</button></div>' +
    '<div class="row" id="edtools">' +
    tb('line', '直线 ─', '-') + tb('vline', '竖线 │', '|') + tb('no', '常开 ┤├', '1') + tb('nc', '常闭 ┤/├', '2') +
    '<span id="ededges">' + tb('rise', '┤P├ rising', '3') + tb('fall', '┤N├ falling', '4') + '</span>' +
    tb('coil', '逻辑输出 ( )', '5') + tb('coil-not', '取反输出 (/)', '6') + tb('set', '(S) set', '7') +
    tb('reset', '(R) reset', '8') + tb('box', '功能模块 box', '9') +
    tb('del', '删除元件 delete', 'Del') + tb('delv', '删除竖线', 'Backspace') +
    tb('insrow', '插入行 row', 'r') + tb('delrow', '删除行', 'Shift+R') + tb('inscol', '插入列 column', 'c') +
    tb('newrung', '新网络 new rung', 'n') + tb('comment', '注释 comment', ';') + '</div>' +
    '<div class="row" id="ednets">' + tb('selnet', '选择网络 select rungs', 's') + tb('copynet', '复制 copy', 'Ctrl+C') +
    tb('cutnet', '剪切 cut', 'Ctrl+X') + tb('pastenet', '粘贴 paste', 'Ctrl+V') +
    tb('delnet', '删除网络 delete rungs', 'Ctrl+Del') + '<span class="sep">列表编辑</span>' +
    tb('addsub', '新子程序 new subroutine', 'p') + tb('rensub', '重命名 rename', 'Shift+P') +
    tb('delsub', '删除子程序 delete subroutine', '') + '</div>' +
    '<div class="row"><label id="edinlab" for="edin">address</label><input id="edin" autocomplete="off" disabled>' +
    '<span id="edinmsg"></span></div>' +
    '<div id="edbody"><div id="edgridbox" tabindex="0"></div><div id="edside">' +
    '<h4>列表编辑 parts</h4><div id="edparts"></div><h4>双线圈 double coils</h4><div id="eddbl">none</div><h4>Rungs with errors</h4><div id="edbad">none</div></div></div>' +
    '<div id="ederrs"></div>';
  document.body.appendChild(panel);
  const confirmBox = document.createElement('div');
  confirmBox.id = 'edconfirm';
  document.body.appendChild(confirmBox);
  const gridBox = document.getElementById('edgridbox'), input = document.getElementById('edin');

  function say(t, bad) {
    const s = document.getElementById('edstate');
    s.textContent = t;
    s.className = bad ? 'bad' : 'ok';
    L.say(t, bad);
  }

  // The edit button in the live bar.
  const btn = document.createElement('button');
  btn.id = 'edbtn';
  btn.textContent = '编辑 edit';
  btn.title = 'edit the running program as ladder (更新修改 puts it live)';
  document.getElementById('live').appendChild(btn);
  btn.addEventListener('click', function () {
    if (E.on) {
      if (dirtyCount() && !window.confirm('Leave the editor? The edits stay until 放弃修改 or a reload.')) return;
      E.on = false;
      document.body.classList.remove('editing');
      btn.classList.remove('on');
      return;
    }
    (E.loaded ? Promise.resolve(true) : open()).then(function (ok) {
      if (!ok) return;
      E.on = true;
      document.body.classList.add('editing');
      btn.classList.add('on');
      render();
      gridBox.focus();
    });
  });

  function cur() { return E.parts[E.p] && E.parts[E.p].rungs[E.r]; }
  // Edited rungs, plus one per part whose rung list changed (a network deleted, cut or moved).
  // Parts added, renamed or removed (列表编辑) count too.
  function dirtyCount() {
    let n = 0;
    E.parts.forEach(function (p) {
      p.rungs.forEach(function (r) { if (r.dirty) n++; });
      const run = E.running && p.orig >= 0 && E.running.parts[p.orig];
      if (!run || run.name !== p.name) n++;
      else if (p.rungs.length !== run.rungs.length || p.rungs.some(function (r, i) { return r.orig !== i; })) n++;
    });
    return n + removedParts().length;
  }
  // The running program's parts the edits removed (deleted, or renamed away).
  function removedParts() {
    if (!E.running) return [];
    return E.running.parts.filter(function (rp) {
      return !E.parts.some(function (p) { return p.name.toUpperCase() === rp.name.toUpperCase(); });
    }).map(function (rp) { return rp.name; });
  }
  // The selected networks of the shown part: from the mark (选择网络) to the shown rung.
  function selRange() {
    if (!E.mark || E.mark.p !== E.p) return [E.r, E.r];
    return [Math.min(E.mark.r, E.r), Math.max(E.mark.r, E.r)];
  }
  // A rung's JSON in the running program (null for a new one).
  function runningRung(part, r) {
    const run = E.running && part.orig >= 0 && E.running.parts[part.orig];
    return r.orig >= 0 && run && run.rungs[r.orig] ? run.rungs[r.orig] : null;
  }
  function runningKind(part, r) {
    if (r.json) return r.json.kind;
    const rr = runningRung(part, r);
    return rr ? rr.kind : 'ladder';
  }
  function select(p, r, forward) {
    const part = E.parts[p];
    if (!part || !part.rungs.length) return;
    r = Math.max(0, Math.min(r, part.rungs.length - 1));
    if (forward !== undefined) {
      // Skip rungs the grid cannot show (markers, statement text) in the direction of travel.
      let k = r;
      while (k >= 0 && k < part.rungs.length && !part.rungs[k].grid) k += forward ? 1 : -1;
      if (k >= 0 && k < part.rungs.length) r = k;
    }
    E.p = p;
    E.r = r;
    const g = cur().grid;
    if (g) {
      E.row = Math.min(E.row, g.rows - 1);
      E.col = Math.min(E.col, g.cols - 1);
    }
    closeInput();
    render();
    // Show the same rung in the view (a new part has none there yet).
    const vp = part.orig, tab = vp >= 0 ? document.querySelectorAll('.tab')[vp] : null;
    if (tab && !tab.classList.contains('sel')) tab.click();
    const orig = cur().orig, div = vp >= 0 && orig >= 0 && L.rungDiv ? L.rungDiv(vp, orig) : null;
    if (div) {
      if (L.drawRung) L.drawRung(div);
      div.scrollIntoView({ block: 'nearest' });
    }
  }

  // ---- drawing the grid ----------------------------------------------------------------------
  function symbolOf(addr) {
    const a = String(addr || '').toUpperCase();
    for (const k in E.symbols) if (String(E.symbols[k]).toUpperCase() === a) return k;
    return '';
  }
  function svgCell(g, r, c, cell) {
    const x = LM + c * CW, y = TOP + r * CH, mid = y + 34, cx = x + CW / 2;
    let s = '';
    const txt = function (t, tx, ty, cls) {
      return '<text x="' + tx + '" y="' + ty + '" text-anchor="middle" class="' + cls + '">' + h(t) + '</text>';
    };
    const operand = function () {
      let o = txt(cell.op || '?', cx, y + 15, 'op');
      const sy = E.symbols[cell.op] ? '' : symbolOf(cell.op);
      if (sy) o += txt(sy, cx, y + 56, 'sy');
      return o;
    };
    if (cell.k === 'line') {
      s += '<line class="w" x1="' + x + '" y1="' + mid + '" x2="' + (x + CW) + '" y2="' + mid + '"/>';
    } else if (CONTACTS.indexOf(cell.k) >= 0) {
      s += '<line class="w" x1="' + x + '" y1="' + mid + '" x2="' + (cx - 9) + '" y2="' + mid + '"/>' +
        '<line class="w" x1="' + (cx + 9) + '" y1="' + mid + '" x2="' + (x + CW) + '" y2="' + mid + '"/>' +
        '<line class="sym" x1="' + (cx - 9) + '" y1="' + (mid - 11) + '" x2="' + (cx - 9) + '" y2="' + (mid + 11) + '"/>' +
        '<line class="sym" x1="' + (cx + 9) + '" y1="' + (mid - 11) + '" x2="' + (cx + 9) + '" y2="' + (mid + 11) + '"/>';
      if (cell.k === 'nc') s += '<line class="sym" x1="' + (cx - 9) + '" y1="' + (mid + 11) + '" x2="' + (cx + 9) + '" y2="' + (mid - 11) + '"/>';
      if (cell.k === 'rise') s += txt('P', cx, mid + 4, 'mk');
      if (cell.k === 'fall') s += txt('N', cx, mid + 4, 'mk');
      s += operand();
    } else if (OUTPUTS.indexOf(cell.k) >= 0) {
      let end = c + 1;
      while (end < g.cols && at(g, r, end).k === 'empty') end++;
      const xr = end >= g.cols ? LM + g.cols * CW : x + CW;
      s += '<line class="w" x1="' + x + '" y1="' + mid + '" x2="' + (cx - 12) + '" y2="' + mid + '"/>' +
        '<line class="w" x1="' + (cx + 12) + '" y1="' + mid + '" x2="' + xr + '" y2="' + mid + '"/>' +
        '<path class="sym" d="M' + (cx - 6) + ' ' + (mid - 12) + ' A 12 12 0 0 0 ' + (cx - 6) + ' ' + (mid + 12) + '"/>' +
        '<path class="sym" d="M' + (cx + 6) + ' ' + (mid - 12) + ' A 12 12 0 0 1 ' + (cx + 6) + ' ' + (mid + 12) + '"/>';
      const mark = { 'coil-not': '/', set: 'S', reset: 'R' }[cell.k];
      if (mark) s += txt(mark, cx, mid + 4, 'mk');
      s += operand();
    } else if (cell.k === 'box') {
      const sp = boxSpan(g, r, c);
      const w = sp.w * CW - 10, hh = sp.h * CH - 12;
      s += '<line class="w" x1="' + x + '" y1="' + mid + '" x2="' + (x + 5) + '" y2="' + mid + '"/>' +
        '<rect class="sym" x="' + (x + 5) + '" y="' + (y + 6) + '" width="' + w + '" height="' + hh + '"/>' +
        txt(cell.instr || '?', x + 5 + w / 2, y + 20, 'op') + txt((cell.ops || []).join(' '), x + 5 + w / 2, y + 36, 'op');
    }
    return s;
  }
  function render() {
    if (!E.on || !E.loaded) return;
    const rg = cur(), part = E.parts[E.p];
    document.getElementById('edwhere').textContent = part.name + ' rung ' + (E.r + 1) + ' of ' + part.rungs.length +
      (rg.orig < 0 ? ' (new)' : '') + (rg.dirty ? ' (edited)' : '') +
      (E.mark && E.mark.p === E.p ? ' · rungs ' + (selRange()[0] + 1) + '-' + (selRange()[1] + 1) + ' selected' : '') +
      (E.clip ? ' · ' + E.clip.length + ' copied' : '');
    document.getElementById('ededges').style.display = E.edges ? '' : 'none';
    document.getElementById('edupdate').disabled = !dirtyCount();
    if (!rg.grid) {
      gridBox.innerHTML = '<p>This rung has no grid the editor can edit: ' + h(rg.why) +
        '. Edit it as program text and <code>monitor load</code> it.</p>';
      document.getElementById('ederrs').innerHTML = '';
      sideLists();
      return;
    }
    const g = rg.grid, W = LM * 2 + g.cols * CW, H = TOP * 2 + g.rows * CH;
    let s = '<svg class="edgrid" xmlns="http://www.w3.org/2000/svg" width="' + W + '" height="' + H + '">';
    for (let r = 0; r < g.rows; r++) {
      for (let c = 0; c < g.cols; c++) {
        s += '<rect class="hit" data-r="' + r + '" data-c="' + c + '" x="' + (LM + c * CW) + '" y="' + (TOP + r * CH) +
          '" width="' + CW + '" height="' + CH + '"/>';
      }
    }
    for (let r = 0; r < g.rows; r++) for (let c = 0; c < g.cols; c++) s += svgCell(g, r, c, at(g, r, c));
    Object.keys(g.links).forEach(function (k) {
      const rb = k.split(',').map(Number), x = LM + rb[1] * CW;
      s += '<line class="link" x1="' + x + '" y1="' + (TOP + rb[0] * CH + 34) + '" x2="' + x + '" y2="' + (TOP + (rb[0] + 1) * CH + 34) + '"/>';
    });
    s += '<line class="rail" x1="' + LM + '" y1="' + TOP + '" x2="' + LM + '" y2="' + (H - TOP) + '"/>' +
      '<line class="rail" x1="' + (LM + g.cols * CW) + '" y1="' + TOP + '" x2="' + (LM + g.cols * CW) + '" y2="' + (H - TOP) + '"/>';
    rg.errors.forEach(function (e) {
      if (e.row < 0 || e.row >= g.rows || e.col < 0 || e.col >= g.cols) return;
      const x = LM + e.col * CW, y = TOP + e.row * CH;
      s += '<g class="errcell" data-r="' + e.row + '" data-c="' + e.col + '"><title>' + h(e.message) + '</title>' +
        '<rect class="err" x="' + (x + 2) + '" y="' + (y + 2) + '" width="' + (CW - 4) + '" height="' + (CH - 4) + '"/>' +
        '<text class="errmark" x="' + (x + CW - 10) + '" y="' + (y + 16) + '">!</text></g>';
    });
    s += '<rect class="cur" id="edcursor" data-r="' + E.row + '" data-c="' + E.col + '" x="' + (LM + E.col * CW + 1) + '" y="' +
      (TOP + E.row * CH + 1) + '" width="' + (CW - 2) + '" height="' + (CH - 2) + '" pointer-events="none"/></svg>';
    const cm = rg.comment.length ? '<div class="cm">; ' + rg.comment.map(h).join('<br>; ') + '</div>' : '';
    gridBox.innerHTML = cm + s;
    const cell = at(g, E.row, E.col);
    document.getElementById('ederrs').innerHTML =
      '<div>cursor: row ' + (E.row + 1) + ' column ' + (E.col + 1) + ': ' + h(KINDS[cell.k] || cell.k) +
      (cell.op ? ' ' + h(cell.op) : '') + (cell.instr ? ' ' + h(cell.instr + ' ' + (cell.ops || []).join(' ')) : '') +
      (rg.pending ? ' &middot; checking...' : '') + '</div>' +
      rg.errors.map(function (e) {
        return '<div class="warn">' + (e.row >= 0 ? 'row ' + (e.row + 1) + ' column ' + (e.col + 1) + ': ' : '') + h(e.message) + '</div>';
      }).join('');
    sideLists();
  }
  // 双线圈 and the rungs with errors, over the whole draft.
  function sideLists() {
    // Removed parts, but not those renamed (shown as "renamed from").
    const removed = removedParts().filter(function (n) {
      return !E.parts.some(function (p) {
        const run = p.orig >= 0 && E.running ? E.running.parts[p.orig] : null;
        return run && run.name === n;
      });
    });
    document.getElementById('edparts').innerHTML = E.parts.map(function (p, pi) {
      const run = p.orig >= 0 && E.running ? E.running.parts[p.orig] : null;
      const tag = !run ? ' <i>new</i>' : run.name !== p.name ? ' <i>renamed from ' + h(run.name) + '</i>' : '';
      return '<div' + (pi === E.p ? ' class="cur"' : '') + '><a data-part="' + pi + '">' + h(p.name) + '</a> ' +
        p.rungs.length + ' rung(s)' + tag + '</div>';
    }).join('') + removed.map(function (n) { return '<div class="warn">' + h(n) + ' <i>removed</i></div>'; }).join('');
    const coils = {};
    E.parts.forEach(function (p, pi) {
      p.rungs.forEach(function (r, ri) {
        const add = function (a) {
          if (!a) return;
          a = String(E.symbols[a] || a).replace(/\s*<.*>$/, '').toUpperCase();
          (coils[a] = coils[a] || []).push([pi, ri]);
        };
        if (r.grid) {
          r.grid.cells.forEach(function (c) { if (c.k === 'coil' || c.k === 'coil-not') add(c.op); });
        } else if (r.orig >= 0 && p.orig >= 0) {
          const lr = (L.layout.parts[p.orig] || { rungs: [] }).rungs[r.orig];
          if (lr) lr.cells.forEach(function (c) { if (c.kind === 'coil' || c.kind === 'coil-not') add(c.text); });
        }
      });
    });
    const dbl = Object.keys(coils).filter(function (a) { return coils[a].length > 1; }).sort();
    document.getElementById('eddbl').innerHTML = dbl.length ? dbl.map(function (a) {
      return '<div class="warn">' + h(a) + ': ' + coils[a].map(function (x) {
        return '<a data-go="' + x[0] + ',' + x[1] + '">' + h(E.parts[x[0]].name) + ' rung ' + (x[1] + 1) + '</a>';
      }).join(', ') + '</div>';
    }).join('') : 'none';
    const bad = [];
    E.parts.forEach(function (p, pi) {
      p.rungs.forEach(function (r, ri) { if (r.errors.length) bad.push([pi, ri]); });
    });
    document.getElementById('edbad').innerHTML = bad.length ? bad.map(function (x) {
      return '<div class="warn"><a data-go="' + x[0] + ',' + x[1] + '">' + h(E.parts[x[0]].name) + ' rung ' + (x[1] + 1) + '</a></div>';
    }).join('') : 'none';
  }
  document.getElementById('edside').addEventListener('click', function (e) {
    const part = e.target.dataset && e.target.dataset.part;
    if (part !== undefined) {
      select(+part, 0, true);
      gridBox.focus();
      return;
    }
    const go = e.target.dataset && e.target.dataset.go;
    if (!go) return;
    const pr = go.split(',').map(Number);
    select(pr[0], pr[1]);
    gridBox.focus();
  });

  // ---- edits ---------------------------------------------------------------------------------
  // Every edit: the part's rung list before it on the undo stack, a new rung object after it.
  function edit(fn, what) {
    const rg = cur();
    if (!rg || !rg.grid) {
      say('this rung cannot be edited in the grid', true);
      return false;
    }
    const g = copyGrid(rg.grid), comment = rg.comment.slice();
    const why = fn(g, comment);
    if (typeof why === 'string') {
      say(why, true);
      return false;
    }
    pushUndo(snap());
    E.redo = [];
    const n = Object.assign({}, rg, { grid: g, comment: comment, dirty: true, errors: [], net: null, cells: null });
    E.parts[E.p].rungs[E.r] = n;
    say(what, false);
    render();
    scheduleCheck();
    return true;
  }
  // An undo step: the shown part's rung list (an edit of rungs), or every part with its name and
  // rungs (列表编辑: a part added, renamed or deleted).
  function snap() {
    return { part: E.parts[E.p], r: E.r, row: E.row, col: E.col, rungs: E.parts[E.p].rungs.slice() };
  }
  function snapParts() {
    return {
      list: E.parts.slice(), names: E.parts.map(function (p) { return p.name; }),
      all: E.parts.map(function (p) { return p.rungs.slice(); }), p: E.p, r: E.r, row: E.row, col: E.col
    };
  }
  function pushUndo(s) {
    E.undo.push(s);
    if (E.undo.length > 200) E.undo.shift();
  }
  function undo(from, to) {
    const s = from.pop();
    if (!s) {
      say('nothing to ' + (from === E.undo ? 'undo' : 'redo'), true);
      return;
    }
    if (s.list) {
      to.push(Object.assign(snapParts(), { row: E.row, col: E.col }));
      E.parts = s.list;
      s.list.forEach(function (p, i) {
        p.name = s.names[i];
        p.rungs = s.all[i];
      });
      E.p = Math.min(s.p, E.parts.length - 1);
    } else {
      to.push({ part: s.part, r: s.r, row: E.row, col: E.col, rungs: s.part.rungs.slice() });
      s.part.rungs = s.rungs;
      E.p = Math.max(0, E.parts.indexOf(s.part));
    }
    E.r = Math.max(0, Math.min(s.r, E.parts[E.p].rungs.length - 1));
    E.row = s.row;
    E.col = s.col;
    say(from === E.undo ? 'undone' : 'redone', false);
    closeInput();
    render();
    scheduleCheck();
  }
  function place(kind, operand, extra) {
    return edit(function (g) {
      const c = at(g, E.row, E.col);
      if (c.k === 'box-part') return 'this cell is part of a box: delete the box first';
      if (c.k === 'box') clearCell(g, E.row, E.col);
      const cell = { k: kind };
      if (operand !== undefined) cell.op = operand;
      Object.assign(cell, extra || {});
      put(g, E.row, E.col, cell);
      return null;
    }, (KINDS[kind] || kind) + (operand ? ' ' + operand : '') + ' at row ' + (E.row + 1) + ' column ' + (E.col + 1));
  }
  // 复制: the selected networks to the editor's clipboard (their grids and comments).
  function copyNets() {
    const sr = selRange(), rungs = E.parts[E.p].rungs.slice(sr[0], sr[1] + 1);
    const bad = rungs.findIndex(function (r) { return !r.grid; });
    if (bad >= 0) {
      say('rung ' + (sr[0] + bad + 1) + ' is not a ladder network the editor can copy: ' +
        (rungs[bad].why || 'statements without a grid') + '; nothing copied', true);
      return false;
    }
    E.clip = rungs.map(function (r) { return { grid: copyGrid(r.grid), comment: r.comment.slice() }; });
    E.mark = null;
    say('复制网络: ' + E.clip.length + ' rung(s) copied; 粘贴 (Ctrl+V) puts them after the shown rung', false);
    render();
    return true;
  }
  // 删除网络: the selected networks leave the draft; a marker (END1, SP, a label) is the
  // program's structure, not a network, and stays.
  function deleteNets(what) {
    const sr = selRange(), part = E.parts[E.p];
    for (let k = sr[0]; k <= sr[1]; k++) {
      if (runningKind(part, part.rungs[k]) === 'marker') {
        say('rung ' + (k + 1) + ' is a marker of the program\'s structure (' + (part.rungs[k].why || 'not a network') +
          '): it is not deleted; nothing deleted', true);
        return false;
      }
    }
    if (sr[1] - sr[0] + 1 >= part.rungs.length) {
      say('a part keeps at least one rung: nothing deleted', true);
      return false;
    }
    pushUndo(snap());
    E.redo = [];
    part.rungs = part.rungs.slice(0, sr[0]).concat(part.rungs.slice(sr[1] + 1));
    E.mark = null;
    E.r = Math.min(sr[0], part.rungs.length - 1);
    say(what + ' ' + (sr[1] - sr[0] + 1) + ' rung(s) from ' + part.name + ' (更新修改 puts it live)', false);
    closeInput();
    render();
    return true;
  }
  // ---- 列表编辑: the part list (docs/ladder-edit.md "The part list") ----------------------------
  // Whether a rung mentions `name` as an operand (a call of the subroutine, its SP marker).
  function gridMentions(g, name) {
    const n = name.toUpperCase();
    return g.cells.some(function (c) {
      return String(c.op || '').toUpperCase() === n ||
        (c.ops || []).some(function (o) { return String(o).toUpperCase() === n; });
    });
  }
  function jsonRenamed(j, from, to) {
    let hit = false;
    const walk = function (x) {
      if (Array.isArray(x)) return x.map(walk);
      if (!x || typeof x !== 'object') return x;
      const o = {};
      Object.keys(x).forEach(function (k) { o[k] = walk(x[k]); });
      if (typeof o.text === 'string' && o.text.toUpperCase() === from.toUpperCase()) {
        o.text = to;
        hit = true;
      }
      return o;
    };
    const out = walk(j);
    return hit ? out : null;
  }
  // `r` of `part` with every operand `from` written `to` (a new rung object), or `r` itself.
  function rungRenamed(part, r, from, to) {
    if (r.grid) {
      if (!gridMentions(r.grid, from)) return r;
      const g = copyGrid(r.grid), F = from.toUpperCase();
      g.cells.forEach(function (c) {
        if (String(c.op || '').toUpperCase() === F) c.op = to;
        if (c.ops) c.ops = c.ops.map(function (o) { return String(o).toUpperCase() === F ? to : o; });
      });
      return Object.assign({}, r, { grid: g, dirty: true, errors: [], net: null, cells: null });
    }
    const j = r.json || runningRung(part, r), n = j ? jsonRenamed(j, from, to) : null;
    return n ? Object.assign({}, r, { json: n, dirty: true, errors: [] }) : r;
  }
  // Where `name` is used outside its own part: [[part index, rung index], ...].
  function callersOf(name) {
    const out = [];
    E.parts.forEach(function (p, pi) {
      if (p.name.toUpperCase() === name.toUpperCase()) return;
      p.rungs.forEach(function (r, ri) { if (rungRenamed(p, r, name, name) !== r) out.push([pi, ri]); });
    });
    return out;
  }
  function placesText(list) {
    return list.map(function (x) { return E.parts[x[0]].name + ' rung ' + (x[1] + 1); }).join(', ');
  }
  function nameTaken(name, except) {
    return E.parts.some(function (p) { return p !== except && p.name.toUpperCase() === name.toUpperCase(); });
  }
  // 新子程序: the part the server made for `a` ({name, rungs}: its markers in the dialect), with
  // an empty rung between them, after the last part.
  function addSub(a) {
    pushUndo(snapParts());
    E.redo = [];
    const marker = function (j) {
      return { orig: -1, json: j, grid: null, why: 'a marker', comment: (j.comment || []).slice(), dirty: true, errors: [], net: null, cells: null, pending: false };
    };
    const rungs = a.rungs.map(marker);
    rungs.splice(1, 0, { orig: -1, grid: blank(1, 8), why: '', comment: [], dirty: true, errors: [], net: null, cells: null, pending: false });
    E.parts.push({ name: a.name, orig: -1, sub: true, rungs: rungs });
    E.p = E.parts.length - 1;
    E.r = 1;
    E.row = 0;
    E.col = 0;
    say('新子程序: ' + a.name + ' added after the last part; its rungs go between its markers (更新修改 puts it live)', false);
    render();
  }
  function renameSub(a) {
    const part = E.parts[E.p], from = part.name;
    pushUndo(snapParts());
    E.redo = [];
    let calls = 0;
    E.parts.forEach(function (p) {
      p.rungs = p.rungs.map(function (r) {
        const n = rungRenamed(p, r, from, a.name);
        if (n !== r && p !== part) calls++;
        return n;
      });
    });
    part.name = a.name;
    say('重命名: ' + from + ' is now ' + a.name + ' (its marker and ' + calls + ' calling rung(s) changed; 更新修改 puts it live)', false);
    render();
    scheduleCheck();
  }
  function deleteSub() {
    const part = E.parts[E.p];
    if (!part.sub) {
      say(part.name + ' is not a subroutine: the main parts are the program\'s structure; nothing deleted', true);
      return;
    }
    const calls = callersOf(part.name);
    pushUndo(snapParts());
    E.redo = [];
    E.parts.splice(E.p, 1);
    E.p = Math.min(E.p, E.parts.length - 1);
    E.r = 0;
    say('删除子程序: ' + part.name + ' deleted' + (calls.length ? '; still called from ' + placesText(calls) +
      ': the check refuses the update until those calls go' : '') + ' (更新修改 asks before removing it)', !!calls.length);
    select(E.p, 0, true);
  }
  const actions = {
    line: function () { place('line'); },
    vline: function () {
      edit(function (g) {
        if (E.col < 1) return 'the left rail joins every row already: put the vertical line right of a cell';
        if (E.row + 1 >= g.rows) return 'a vertical line joins this row and the one below: insert a row first (r)';
        setLink(g, E.row, E.col, !link(g, E.row, E.col));
        return null;
      }, 'vertical line at the left of row ' + (E.row + 1) + ' column ' + (E.col + 1) + ' to the row below');
    },
    delv: function () {
      edit(function (g) {
        if (!link(g, E.row, E.col)) return 'no vertical line at the left of the cursor to the row below';
        setLink(g, E.row, E.col, false);
        return null;
      }, '删除竖线: vertical line deleted');
    },
    del: function () {
      edit(function (g) {
        const c = at(g, E.row, E.col);
        if (c.k === 'empty') return 'nothing to delete here';
        if (c.k === 'box-part') return 'this cell is part of a box: delete it where its name is';
        clearCell(g, E.row, E.col);
        return null;
      }, '删除元件: element deleted');
    },
    insrow: function () {
      edit(function (g) {
        if (g.rows >= 64) return 'a rung has at most 64 rows';
        const n = insertRow(g, E.row);
        Object.assign(g, n);
        return null;
      }, '插入行: a row inserted below row ' + (E.row + 1));
    },
    delrow: function () {
      edit(function (g) {
        if (g.rows <= 1) return 'the only row of a rung: delete its elements instead';
        Object.assign(g, deleteRow(g, E.row));
        E.row = Math.min(E.row, g.rows - 1);
        return null;
      }, '删除行: row deleted');
    },
    inscol: function () {
      edit(function (g) {
        if (g.cols >= 64) return 'a rung has at most 64 columns';
        Object.assign(g, insertColumn(g, E.col));
        return null;
      }, '插入列: a column inserted before column ' + (E.col + 1));
    },
    newrung: function () {
      const rg = cur(), cols = rg && rg.grid ? rg.grid.cols : 9;
      pushUndo(snap());
      E.redo = [];
      E.parts[E.p].rungs.splice(E.r + 1, 0, {
        orig: -1, grid: blank(1, Math.max(cols, 8)), why: '', comment: [], dirty: true, errors: [], net: null, cells: null, pending: false
      });
      E.r += 1;
      E.row = 0;
      E.col = 0;
      say('新网络: a new rung after rung ' + E.r + ' (a rung left empty is dropped on update)', false);
      render();
    },
    comment: function () { openInput('comment'); },
    box: function () { openInput('box', 'box'); },
    selnet: function () {
      if (E.mark && E.mark.p === E.p) {
        E.mark = null;
        say('选择网络: selection cleared', false);
      } else {
        E.mark = { p: E.p, r: E.r };
        say('选择网络: rung ' + (E.r + 1) + ' marked; PgUp/PgDn select up to the shown rung', false);
      }
      render();
    },
    copynet: function () { copyNets(); },
    cutnet: function () { if (copyNets()) deleteNets('剪切网络: cut'); },
    pastenet: function () {
      if (!E.clip) {
        say('nothing copied: 复制 (Ctrl+C) a rung first', true);
        return;
      }
      pushUndo(snap());
      E.redo = [];
      const add = E.clip.map(function (c) {
        return { orig: -1, grid: copyGrid(c.grid), why: '', comment: c.comment.slice(), dirty: true, errors: [], net: null, cells: null, pending: false };
      });
      Array.prototype.splice.apply(E.parts[E.p].rungs, [E.r + 1, 0].concat(add));
      E.r += 1;
      E.mark = null;
      say('粘贴网络: ' + add.length + ' rung(s) pasted after rung ' + E.r, false);
      render();
      scheduleCheck();
    },
    delnet: function () { deleteNets('删除网络: deleted'); },
    addsub: function () { openInput('part-add'); },
    rensub: function () {
      if (!E.parts[E.p].sub) {
        say(E.parts[E.p].name + ' is not a subroutine: only a subroutine is renamed', true);
        return;
      }
      openInput('part-rename');
    },
    delsub: function () { deleteSub(); },
    undo: function () { undo(E.undo, E.redo); },
    redo: function () { undo(E.redo, E.undo); },
    prev: function () { select(E.p, E.r - 1, false); },
    next: function () { select(E.p, E.r + 1, true); },
    update: function () { update(); },
    discard: function () { discard(); }
  };
  CONTACTS.concat(OUTPUTS).forEach(function (k) {
    actions[k] = function () {
      if ((k === 'rise' || k === 'fall') && !E.edges) {
        say('the ' + E.dialect + ' dialect has no edge contacts', true);
        return;
      }
      openInput('operand', k);
    };
  });
  panel.addEventListener('click', function (e) {
    const b = e.target.closest && e.target.closest('button[data-act]');
    if (!b) return;
    actions[b.dataset.act]();
    if (document.activeElement !== input) gridBox.focus();
  });

  // ---- the input line: an operand, a box, a comment, checked as typed -------------------------
  let inputTimer = null, inputSeq = 0;
  function openInput(mode, kind) {
    if (mode === 'part-add' || mode === 'part-rename') {
      E.input = { mode: mode, kind: kind };
      input.disabled = false;
      const pre = E.subs ? E.subs.prefix : '';
      let free = E.subs ? E.subs.first : 0;
      while (E.subs && nameTaken(pre + free) && free < E.subs.last) free++;
      document.getElementById('edinlab').textContent = mode === 'part-add' ? '新子程序 new subroutine' :
        '重命名 rename ' + E.parts[E.p].name + ' to';
      input.value = mode === 'part-add' ? pre + free : E.parts[E.p].name;
      input.focus();
      input.select();
      checkInput();
      return;
    }
    const rg = cur();
    if (!rg || !rg.grid) return;
    const c = at(rg.grid, E.row, E.col);
    if (c.k === 'box-part') {
      say('this cell is part of a box: delete the box first', true);
      return;
    }
    E.input = { mode: mode, kind: kind };
    input.disabled = false;
    const lab = document.getElementById('edinlab');
    if (mode === 'comment') {
      lab.textContent = 'rung comment (lines split by |)';
      input.value = rg.comment.join(' | ');
    } else if (mode === 'box') {
      lab.textContent = '功能模块 box: instruction and operands';
      input.value = c.k === 'box' ? [c.instr].concat(c.ops || []).join(' ') : '';
      input.setAttribute('list', 'edboxes');
    } else {
      lab.textContent = (KINDS[kind] || kind) + ': address';
      input.value = c.op || '';
    }
    input.focus();
    input.select();
    checkInput();
  }
  function closeInput() {
    E.input = null;
    input.value = '';
    input.disabled = true;
    input.className = '';
    input.removeAttribute('list');
    document.getElementById('edinlab').textContent = 'address';
    document.getElementById('edinmsg').textContent = '';
  }
  function inputMsg(t, ok) {
    const m = document.getElementById('edinmsg');
    m.textContent = t;
    m.className = ok ? 'ok' : 'bad';
    input.className = ok ? 'ok' : 'bad';
  }
  function boxEntry(word) {
    const w = String(word || '').toUpperCase();
    return E.boxes.filter(function (b) { return b.instr.toUpperCase() === w; })[0];
  }
  // The answer for what the input holds: {ok, message}.
  function checkText(text) {
    const mode = E.input && E.input.mode;
    if (mode === 'comment') return Promise.resolve({ ok: true, message: 'comment' });
    if (mode === 'part-add' || mode === 'part-rename') {
      const self = mode === 'part-rename' ? E.parts[E.p] : null;
      return api('api/edit/grid', { subroutine: text.trim() }).then(function (a) {
        if (!a.body.ok) return { ok: false, message: a.body.error || 'refused' };
        if (nameTaken(a.body.name, self)) return { ok: false, message: a.body.name + ' is a part of the program already' };
        if (self && self.name.toUpperCase() === a.body.name.toUpperCase()) return { ok: false, message: 'the same name' };
        return { ok: true, message: a.body.name + ' ok', body: a.body };
      });
    }
    const words = text.trim().split(/\s+/).filter(Boolean);
    if (mode === 'box') {
      const b = boxEntry(words[0]);
      if (!b) {
        return Promise.resolve({
          ok: false,
          message: words.length ? "'" + words[0] + "' is no one-input box of the " + E.dialect + ' dialect' : 'type the box, e.g. ' + (E.boxes[0] ? E.boxes[0].instr : 'MOV')
        });
      }
      const roles = b.operands.map(function (o) { return o.role; }).join(', ');
      if (words.length - 1 !== b.operands.length) {
        return Promise.resolve({ ok: false, message: b.instr + ' takes ' + b.operands.length + ' operand(s): ' + roles });
      }
      return Promise.all(words.slice(1).map(function (w, i) {
        return api('api/edit/grid', { operand: w, box: b.instr, index: i });
      })).then(function (as) {
        const badOne = as.filter(function (a) { return !a.body.ok; })[0];
        return badOne ? { ok: false, message: badOne.body.error || 'refused' } : { ok: true, message: b.instr + ': ' + roles + ' ok' };
      });
    }
    if (words.length !== 1) return Promise.resolve({ ok: false, message: 'one address' });
    return api('api/edit/grid', { operand: words[0] }).then(function (a) {
      return a.body.ok ? { ok: true, message: words[0] + (a.body.address ? ' = ' + a.body.address : '') + ' ok' } : { ok: false, message: a.body.error || 'refused' };
    });
  }
  function checkInput() {
    clearTimeout(inputTimer);
    const seq = ++inputSeq, text = input.value;
    inputTimer = setTimeout(function () {
      checkText(text).then(function (a) { if (seq === inputSeq && E.input) inputMsg(a.message, a.ok); });
    }, 120);
  }
  input.addEventListener('input', checkInput);
  input.addEventListener('keydown', function (e) {
    if (e.key === 'Escape') {
      e.preventDefault();
      closeInput();
      say('cancelled', false);
      gridBox.focus();
      return;
    }
    if (e.key !== 'Enter') return;
    e.preventDefault();
    const inp = E.input, text = input.value;
    if (!inp) return;
    checkText(text).then(function (a) {
      if (E.input !== inp) return;
      if (!a.ok) {
        inputMsg(a.message, false);
        say('not entered: ' + a.message, true);
        return;
      }
      const words = text.trim().split(/\s+/).filter(Boolean);
      closeInput();
      if (inp.mode === 'part-add') {
        addSub(a.body);
      } else if (inp.mode === 'part-rename') {
        renameSub(a.body);
      } else if (inp.mode === 'comment') {
        const lines = text.split('|').map(function (s) { return s.trim(); }).filter(Boolean);
        edit(function (g, comment) { comment.splice(0, comment.length); lines.forEach(function (l) { comment.push(l); }); return null; },
          '注释: rung comment set');
      } else if (inp.mode === 'box') {
        const b = boxEntry(words[0]);
        place('box', undefined, { instr: b.instr, ops: words.slice(1) });
      } else {
        place(inp.kind, words[0]);
        // HNC-8 moves on after an element: the cursor to the next cell of the row.
        const g = cur().grid;
        if (E.col + 1 < g.cols && OUTPUTS.indexOf(inp.kind) < 0) E.col++;
        render();
      }
      gridBox.focus();
    });
  });
  const dl = document.createElement('datalist');
  dl.id = 'edboxes';
  panel.appendChild(dl);

  // ---- keys and mouse on the grid ------------------------------------------------------------
  const KEYS = {
    '-': 'line', '|': 'vline', '1': 'no', '2': 'nc', '3': 'rise', '4': 'fall', '5': 'coil', '6': 'coil-not',
    '7': 'set', '8': 'reset', '9': 'box', Delete: 'del', Backspace: 'delv', r: 'insrow', R: 'delrow',
    c: 'inscol', n: 'newrung', ';': 'comment', PageUp: 'prev', PageDown: 'next', s: 'selnet',
    p: 'addsub', P: 'rensub'
  };
  const CTRL_KEYS = { c: 'copynet', x: 'cutnet', v: 'pastenet', Delete: 'delnet' };
  gridBox.addEventListener('keydown', function (e) {
    const rg = cur();
    if (!rg) return;
    if (e.ctrlKey && (e.key === 'z' || e.key === 'Z')) {
      e.preventDefault();
      actions.undo();
      return;
    }
    if (e.ctrlKey && (e.key === 'y' || e.key === 'Y')) {
      e.preventDefault();
      actions.redo();
      return;
    }
    const ck = e.ctrlKey && !e.altKey && !e.metaKey && CTRL_KEYS[e.key.length === 1 ? e.key.toLowerCase() : e.key];
    if (ck) {
      e.preventDefault();
      actions[ck]();
      return;
    }
    if (e.ctrlKey || e.altKey || e.metaKey) return;
    const g = rg.grid, mv = { ArrowUp: [-1, 0], ArrowDown: [1, 0], ArrowLeft: [0, -1], ArrowRight: [0, 1] }[e.key];
    if (mv && g) {
      e.preventDefault();
      E.row = Math.max(0, Math.min(g.rows - 1, E.row + mv[0]));
      E.col = Math.max(0, Math.min(g.cols - 1, E.col + mv[1]));
      render();
      return;
    }
    if (e.key === 'Enter' && g) {
      e.preventDefault();
      const c = at(g, E.row, E.col);
      if (c.k === 'box') openInput('box', 'box');
      else if (CONTACTS.indexOf(c.k) >= 0 || OUTPUTS.indexOf(c.k) >= 0) openInput('operand', c.k);
      return;
    }
    if (e.key === 'Escape' && E.mark) {
      E.mark = null;
      say('选择网络: selection cleared', false);
      render();
      return;
    }
    const act = KEYS[e.key];
    if (act) {
      e.preventDefault();
      actions[act]();
    }
  });
  gridBox.addEventListener('mousedown', function (e) {
    const t = e.target.closest && e.target.closest('[data-r]');
    if (!t || !cur() || !cur().grid) return;
    E.row = +t.dataset.r;
    E.col = +t.dataset.c;
    render();
    e.preventDefault();
    gridBox.focus();
  });
  gridBox.addEventListener('dblclick', function () {
    const g = cur() && cur().grid;
    if (!g) return;
    const c = at(g, E.row, E.col);
    if (c.k === 'box') openInput('box', 'box');
    else if (CONTACTS.indexOf(c.k) >= 0 || OUTPUTS.indexOf(c.k) >= 0) openInput('operand', c.k);
  });
  // In edit mode a click on a rung of the view opens it in the editor.
  document.addEventListener('click', function (e) {
    if (!E.on || !E.loaded) return;
    const div = e.target.closest && e.target.closest('div.rg');
    if (!div) return;
    const p = E.parts.findIndex(function (x) { return x.orig === +div.dataset.p; }), orig = +div.dataset.r, part = E.parts[p];
    if (!part) return;
    const r = part.rungs.findIndex(function (x) { return x.orig === orig; });
    if (r >= 0) select(p, r);
  });

  // ---- converting and checking edited rungs (ladder/Grid on the server) ----------------------
  function scheduleCheck() {
    clearTimeout(E.checkTimer);
    E.checkTimer = setTimeout(function () { convertDirty(); }, 150);
  }
  // Every edited rung without a fresh conversion goes to the server's grid check; the answer
  // belongs to the rung object it was asked for (a later edit makes a new object).
  function convertDirty() {
    const todo = [];
    E.parts.forEach(function (p, pi) {
      p.rungs.forEach(function (r, ri) {
        if (!r.dirty || r.net || r.errors.length || !r.grid) return;
        if (isEmptyGrid(r.grid)) return;
        todo.push({ obj: r, req: { part: pi, rung: ri, partName: p.name, grid: gridJson(r.grid, r.comment) } });
      });
    });
    if (!todo.length) return Promise.resolve(true);
    todo.forEach(function (t) { t.obj.pending = true; });
    render();
    return gridCheck(todo.map(function (t) { return t.req; }), function (i, ans) {
      const t = todo[i];
      t.obj.pending = false;
      if (ans.ok) {
        t.obj.net = ans.network;
        t.obj.cells = ans.cells;
        t.obj.errors = [];
      } else {
        t.obj.errors = ans.errors;
      }
    }).then(function () {
      render();
      return true;
    });
  }
  // The server's grid check of `reqs` ({grid, ...} each), at most 32 a request (the route
  // takes 256); `each(i, answer)` for every one, a refused request answering for all of its own.
  function gridCheck(reqs, each) {
    const calls = [];
    for (let k = 0; k < reqs.length; k += 32) {
      const from = k, part = reqs.slice(k, k + 32);
      calls.push(api('api/edit/grid', { rungs: part }).then(function (a) {
        part.forEach(function (_r, i) {
          each(from + i, a.status === 200 ? a.body.rungs[i] : { ok: false, errors: [{ row: -1, col: -1, message: a.body.error || 'HTTP ' + a.status }] });
        });
      }));
    }
    return Promise.all(calls);
  }

  // ---- 更新修改 / 放弃修改 ---------------------------------------------------------------------
  // The draft: the running program's network JSON with the edited rungs replaced (a new rung
  // inserted, an emptied one dropped); `where[part name][rung]` is the rung object of each draft
  // rung, for drawing the check's diagnostics.
  function makeDraft() {
    const d = JSON.parse(JSON.stringify(E.running)), where = {};
    // The parts in the editor's order (列表编辑: new ones, renamed ones, deleted ones left out).
    d.parts = E.parts.map(function (p) {
      const run = p.orig >= 0 ? E.running.parts[p.orig] : null;
      const jp = run ? JSON.parse(JSON.stringify(run)) : {};
      jp.name = p.name;
      const rungs = [];
      where[p.name] = [];
      p.rungs.forEach(function (r) {
        if (r.json) {
          rungs.push(r.json);
        } else if (!r.dirty) {
          rungs.push(run.rungs[r.orig]);
        } else if (r.grid && isEmptyGrid(r.grid)) {
          return;
        } else {
          const nr = { number: rungs.length + 1, kind: 'ladder', comment: r.comment, network: r.net };
          // The lines written before it that made no statement (FANUC COME) stay before it.
          const lead = r.orig >= 0 && run && run.rungs[r.orig] ? run.rungs[r.orig].lead : null;
          if (lead) nr.lead = lead;
          rungs.push(nr);
        }
        where[p.name].push(r);
      });
      jp.rungs = rungs;
      return jp;
    });
    d.base = E.base;
    d.editor = EDITOR;
    return { json: d, where: where };
  }
  function markDiagnostics(diags, where) {
    let first = null;
    (diags || []).forEach(function (dg) {
      if (dg.severity && dg.severity !== 'error') return;
      const rs = where[dg.part], r = rs && rs[(dg.rung || 0) - 1];
      if (!r) return;
      const cell = r.cells && dg.element ? r.cells[dg.element - 1] : null;
      const e = { row: cell ? cell[0] : -1, col: cell ? cell[1] : -1, message: dg.message, element: dg.element || 0 };
      // The rung keeps its converted network: it stays refused until it is edited again.
      r.errors = r.errors.concat([e]);
      if (!first) first = r;
    });
    placeOnCells();
    return first;
  }
  // A refused rung the page did not edit (a call whose subroutine was deleted) has no statement
  // -> cell map yet: its grid goes to the grid check once for it, then its errors go on their cells.
  function placeOnCells() {
    const todo = [];
    E.parts.forEach(function (p) {
      p.rungs.forEach(function (r) {
        if (r.grid && !r.cells && r.errors.some(function (e) { return e.row < 0 && e.element > 0; })) todo.push(r);
      });
    });
    if (!todo.length) return;
    gridCheck(todo.map(function (r) { return { grid: gridJson(r.grid, r.comment) }; }), function (i, ans) {
      const r = todo[i];
      if (!ans || !ans.ok) return;
      r.cells = ans.cells;
      r.errors = r.errors.map(function (e) {
        const c = e.row < 0 && e.element > 0 ? r.cells[e.element - 1] : null;
        return c ? Object.assign({}, e, { row: c[0], col: c[1] }) : e;
      });
    }).then(render);
  }
  function goToRung(obj) {
    E.parts.forEach(function (p, pi) {
      const ri = p.rungs.indexOf(obj);
      if (ri >= 0) {
        E.p = pi;
        E.r = ri;
      }
    });
    const e = obj.errors[0];
    if (e && e.row >= 0) {
      E.row = e.row;
      E.col = e.col;
    }
    render();
  }
  function update() {
    if (!dirtyCount()) {
      say('nothing edited', true);
      return;
    }
    clearTimeout(E.checkTimer);
    convertDirty().then(function () {
      let bad = null;
      E.parts.forEach(function (p) { p.rungs.forEach(function (r) { if (!bad && r.dirty && r.errors.length) bad = r; }); });
      if (bad) {
        goToRung(bad);
        say('更新修改 refused: the marked cells are not a program the ' + E.dialect + ' dialect can express; nothing was sent', true);
        return null;
      }
      const dr = makeDraft();
      say('sending the draft...', false);
      return api('api/edit/draft', dr.json).then(function (a) {
        if (a.status !== 200) return refused('draft', a);
        E.posted = true;
        return api('api/edit/check', { editor: EDITOR }).then(function (c) {
          if (c.status === 422) {
            const first = markDiagnostics(c.body.diagnostics, dr.where);
            if (first) goToRung(first);
            const ds = (c.body.diagnostics || []).filter(function (dg) { return !dg.severity || dg.severity === 'error'; });
            say('更新修改 refused: the draft does not verify (' + ds.length + ' error(s)' +
              (ds.length ? ': ' + ds[0].message : '') + '); the running program is unchanged', true);
            return null;
          }
          if (c.status !== 200) return refused('check', c);
          confirmUpdate(c.body);
          return null;
        });
      });
    }).catch(function (e) { say('更新修改 failed: ' + e, true); });
  }
  function refused(what, a) {
    let t = what + ' refused (' + a.status + '): ' + (a.body.error || '');
    if (a.body.reason === 'stale') {
      t += ' — the running program changed since this draft was made (draft base ' + a.body.base + ', running ' +
        ((a.body.running || {}).hash || '?') + '): 放弃修改 and edit the running version';
    }
    if (a.body.reason === 'removes-parts') t += ' — it removes ' + (a.body.removes || []).join(', ');
    if (a.body.reason === 'held' && a.body.holder) t += ' — held by editor ' + a.body.holder.editor + ' (' + a.body.holder.client + ')';
    say(t, true);
    return null;
  }
  function confirmUpdate(c) {
    const init = c.init || E.init || {};
    E.removes = c.removes || [];
    const warn = (c.diagnostics || []).filter(function (d) { return d.severity !== 'error'; });
    confirmBox.innerHTML = '<h3>更新修改: put the edited program live?</h3>' +
      '<p>The draft verifies. Updating swaps it in at a tick boundary (online change), writes the program file ' +
      '(the old one kept in its history) and logs the change.</p>' +
      (init.runsOnUpdate ? '<div class="init" id="edinit"><b>The init part runs again on update</b> ' +
        '(an update is a program reload) and writes: <b>' +
        h((init.writes || []).join(', ') || 'nothing') + '</b>' + (init.rule ? '<br><small>' + h(init.rule) + '</small>' : '') + '</div>'
        : '<div class="init" id="edinit">This program has no init part: nothing runs besides the new rungs.</div>') +
      (E.removes.length ? '<div class="init" id="edremoves"><b>This update removes ' + h(E.removes.join(', ')) +
        '</b> from the running program (列表编辑: deleted or renamed).</div>' : '') +
      (warn.length ? '<p>Warnings:</p><ul>' + warn.map(function (d) { return '<li>' + h(d.message) + '</li>'; }).join('') + '</ul>' : '') +
      '<p>The change:</p><pre>' + h(c.diff || '') + '</pre>' +
      '<button id="edyes" class="go">更新修改 update now</button> <button id="edno">cancel</button>';
    confirmBox.style.display = 'block';
    document.getElementById('edno').onclick = function () {
      confirmBox.style.display = 'none';
      say('not updated: the draft stays open on the server until 放弃修改', false);
      gridBox.focus();
    };
    document.getElementById('edyes').onclick = function () {
      confirmBox.style.display = 'none';
      say('updating...', false);
      const body = { editor: EDITOR };
      if (E.removes.length) body.removeParts = E.removes;
      api('api/edit/update', body).then(function (u) {
        if (u.status === 422) {
          markDiagnostics(u.body.diagnostics, makeDraft().where);
          say('更新修改 refused: ' + (u.body.error || 'the draft does not verify') + '; the running program is unchanged', true);
          render();
          return;
        }
        if (u.status !== 200) {
          refused('update', u);
          return;
        }
        E.sent = true;
        say('更新修改: version ' + u.body.version + ' runs; the old file is kept as ' + u.body.history + '; reloading the page', false);
      });
    };
  }
  function discard() {
    const go = function () {
      E.loaded = false;
      return open(true).then(function () {
        say('放弃修改: the edits are dropped; the running program, its file and state are untouched', false);
        render();
      });
    };
    if (!E.posted) {
      go();
      return;
    }
    api('api/edit/discard', { editor: EDITOR }).then(function (a) {
      if (a.status !== 200 && a.body.reason !== 'no-draft') {
        refused('discard', a);
        return;
      }
      go();
    });
  }
  // A new program version while editing: the page reloads only when nothing edited would be
  // lost (or after our own update); otherwise the editor says the draft is stale.
  L.beforeReload = function (m) {
    if (!E.loaded || E.sent || !dirtyCount()) return true;
    say('the running program changed (version ' + m.v + ') while you edit: your edits are based on the old one; ' +
      '放弃修改 to start from the running version', true);
    return false;
  };
  L.editor = {
    state: function () { return E; },
    go: function (p, r) { select(p, r); },
    name: function () { return EDITOR; }
  };
  // The catalogue as the input's suggestions, once loaded.
  const fill = setInterval(function () {
    if (!E.loaded) return;
    dl.innerHTML = E.boxes.map(function (b) {
      return '<option value="' + h(b.instr) + '">' + h(b.instr + ': ' + b.operands.map(function (o) { return o.role; }).join(', ')) + '</option>';
    }).join('');
    clearInterval(fill);
  }, 500);
})();
