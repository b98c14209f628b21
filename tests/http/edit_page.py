#!/usr/bin/python3
"""The ladder editor of the live page as a technician uses it (docs/ladder-edit.md "The page
editor", issue 30 scope 5), in headless Chromium with real mouse and keyboard events
(python3-selenium + chromedriver, scripts/setup-test.sh). Each program is copied and served with
its stimulus (`serve PROGRAM --http`, the stimulus file's steps written in order with
`ladderjit monitor write`: serve has no --stimulus), an input locked through the live view:

- examples/lathe_panel.stl (after the stimulus the panel is in increment mode: R0.3 = 1, so
  `LD R0.3 / OUT G2620.3` writes 1): 编辑, a click on the rung in the view, a click on its first
  cell and the arrow key to the next, key 2 (常闭) and `X482.1` typed, checked as typed, Enter;
  更新修改 opens the confirmation, which names what the init part writes (R0.2, G2564); cancel,
  then 放弃修改: version, hash, file, history, audit log and G2620.3 untouched, no draft open.
  An output typed into the middle of the rung (an element after an output) is marked on its cell
  and 更新修改 sends nothing; undo removes it. An output written to an input (X0.5, read-only)
  passes the grid but not the verifier: the check's 422 is drawn on the output's cell, the
  running version unchanged; undo. Then the NC contact again, 更新修改, confirmed: with X482.1
  locked to 1, G2620.3 (read with `ladderjit monitor read`) goes 1 -> 0, and 1 again with X482.1
  locked to 0; the file holds `ANI X482.1` in the rung and every other line as before, the
  history folder the old file, the audit log one record with the page's editor name and the diff.
- examples/fanuc_coolant.pmc (`RD.NOT X0.0 / WRT R0.7`, X0.0 locked to 0) and
  examples/conveyor.il (`... ST %M5 / ST %Q0.0 / ST %Q0.1`, start, stop and box inputs locked):
  an NC contact (X0.1, %I0.4, locked to 1) inserted just before the output by mouse and keys,
  更新修改 confirmed, the output goes 1 -> 0, the file holds the new line (`AND.NOT X0.1`,
  `ANDN %I0.4`).
- a FANUC program with COM..COME: the rung after COME edited the same way keeps COME before it.

Screenshots of every step go to OUTDIR/*.png. Bounded: every wait has a deadline.
Usage: edit_page.py LADDERJIT EXAMPLES OUTDIR"""
import difflib, json, os, shutil, sys, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import httputil  # noqa: E402
import serveutil  # noqa: E402
from httputil import call, check  # noqa: E402

from selenium.webdriver.common.action_chains import ActionChains  # noqa: E402
from selenium.webdriver.common.by import By  # noqa: E402
from selenium.webdriver.common.keys import Keys  # noqa: E402
from selenium.common.exceptions import StaleElementReferenceException  # noqa: E402

exe, examples, out = sys.argv[1], sys.argv[2], sys.argv[3]
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)


def chrome():
    return httputil.chrome(1400, "ljedit")


wait = httputil.wait


class Page:
    def __init__(self, drv, name):
        self.d, self.name, self.shot = drv, name, 0

    def js(self, script, *args):
        return self.d.execute_script(script, *args)

    def text(self, id_):
        return self.js("var e=document.getElementById(arguments[0]);return e?e.textContent:''", id_)

    def screenshot(self, what):
        self.shot += 1
        path = os.path.join(out, "%s_%d_%s.png" % (self.name, self.shot, what))
        self.d.save_screenshot(path)
        # The editor panel (or the confirmation) alone: the small pictures of docs/ladder-edit.md.
        for part in ("edconfirm", "editor"):
            els = self.d.find_elements(By.ID, part)
            if els and els[0].is_displayed():
                els[0].screenshot(path[:-4] + "_" + part + ".png")
                break
        print("     screenshot " + path)

    def click(self, el):
        self.js("arguments[0].scrollIntoView({block:'center',inline:'center'})", el)
        ActionChains(self.d).move_to_element(el).click().perform()

    def keys(self, *k):
        ActionChains(self.d).send_keys(*k).perform()

    def ctrl(self, k):
        ActionChains(self.d).key_down(Keys.CONTROL).send_keys(k).key_up(Keys.CONTROL).perform()

    def click_cell(self, r, c):
        """A click on cell (r, c); the grid is drawn anew when a check answers, so an element found
        just before may be gone: found again."""
        for attempt in range(5):
            try:
                self.click(self.cell(r, c))
                return
            except StaleElementReferenceException:
                if attempt == 4:
                    raise
                time.sleep(0.2)

    def cell(self, r, c):
        return self.d.find_element(By.CSS_SELECTOR, '#edgridbox rect.hit[data-r="%d"][data-c="%d"]' % (r, c))

    def grid(self):
        """The grid of the rung the editor shows (what is drawn), read from the page's state."""
        return self.js("var E=window.ladder.editor.state(),r=E.parts[E.p].rungs[E.r];"
                       "return {p:E.p,r:E.r,row:E.row,col:E.col,grid:r.grid,errors:r.errors,"
                       "pending:r.pending,dirty:r.dirty,net:!!r.net}")

    def errcells(self):
        return self.js("return Array.prototype.map.call(document.querySelectorAll('#edgridbox g.errcell'),"
                       "function(g){return [+g.dataset.r,+g.dataset.c,g.textContent]})")

    def settled(self):
        """The shown rung converted (checked by the server) or refused."""
        return wait("the rung's check", lambda: (lambda g: g if not g["pending"] and (g["net"] or g["errors"] or not g["dirty"]) else None)(self.grid()), 30)


def find_rung(page, coil):
    """(part, rung, row, col) of the output `coil` in the editor's grids."""
    return page.js("var E=window.ladder.editor.state();for(var p=0;p<E.parts.length;p++)"
                   "for(var r=0;r<E.parts[p].rungs.length;r++){var g=E.parts[p].rungs[r].grid;if(!g)continue;"
                   "for(var i=0;i<g.cells.length;i++){var c=g.cells[i];if(c.k==='coil'&&c.op===arguments[0])"
                   "return [p,r,Math.floor(i/g.cols),i%g.cols,E.parts[p].rungs[r].orig]}}return null", coil)


def open_editor(page, url, token):
    page.d.get(url + "/?token=" + token)
    check(wait("live", lambda: page.js("return !!(window.ladder&&window.ladder.live&&window.ladder.live.last)"), 40),
          "%s: the live page is live" % page.name)
    page.click(page.d.find_element(By.ID, "edbtn"))
    ok = wait("the editor", lambda: "editing" in page.text("edstate"), 30)
    check(ok, "%s: 编辑 opens the editor: '%s'" % (page.name, page.text("edstate")))


def open_rung(page, coil):
    """A click on the rung of `coil` in the view opens it in the editor."""
    at = find_rung(page, coil)
    check(at is not None, "%s: the editor has a grid of the rung writing %s: %s" % (page.name, coil, at))
    p, r, row, col, orig = at
    tab = page.d.find_elements(By.CSS_SELECTOR, ".tab")[p]
    page.click(tab)
    div = page.d.find_element(By.CSS_SELECTOR, 'div.rg[data-p="%d"][data-r="%d"]' % (p, orig))
    page.click(div)
    g = wait("the rung selected", lambda: (lambda x: x if x["p"] == p and x["r"] == r else None)(page.grid()), 10)
    check(g is not None, "%s: a click on the rung in the view opens it in the editor: %s" % (page.name, page.text("edwhere")))
    return at


def insert_nc(page, row, col, address, via_arrow):
    """The cursor to (row, col) (a click, or a click left of it and the right arrow key), key 2
    (常闭), the address typed and checked as typed, Enter."""
    if via_arrow:
        page.click_cell(row, col - 1)
        page.keys(Keys.ARROW_RIGHT)
    else:
        page.click_cell(row, col)
    g = page.grid()
    check(g["row"] == row and g["col"] == col, "%s: the cursor at row %d column %d (%s)" %
          (page.name, row + 1, col + 1, "mouse and arrow key" if via_arrow else "mouse"))
    check(g["grid"]["cells"][row * g["grid"]["cols"] + col]["k"] == "line",
          "%s: the cell is a line (直线) to put the contact on" % page.name)
    page.keys("2")
    check(wait("the input", lambda: page.js("return document.activeElement.id") == "edin", 5),
          "%s: key 2 (常闭) asks for the address" % page.name)
    page.keys(address[:2])
    page.keys(address[2:])
    msg = wait("the typed address checked", lambda: (lambda t: t if "ok" in t else None)(page.text("edinmsg")), 10)
    check(msg is not None, "%s: %s checked as typed: '%s'" % (page.name, address, page.text("edinmsg")))
    page.keys(Keys.ENTER)
    wait("the contact in the grid", lambda: (lambda x: x["grid"]["cells"][row * x["grid"]["cols"] + col]["k"] == "nc")(page.grid()), 10)
    g = page.settled()
    cell = g["grid"]["cells"][row * g["grid"]["cols"] + col] if g else {}
    check(g and cell.get("k") == "nc" and cell.get("op") == address and not g["errors"],
          "%s: the NC contact %s in the grid, converted with no error: %s %s" %
          (page.name, address, cell, g and g["errors"]))


def update(page, confirm=True):
    """更新修改; the confirmation's text, after confirming (or cancelling)."""
    page.click(page.d.find_element(By.ID, "edupdate"))
    box = wait("the confirmation", lambda: page.d.find_element(By.ID, "edconfirm").is_displayed(), 60)
    check(box, "%s: 更新修改 verifies the draft and asks to confirm: '%s'" % (page.name, page.text("edstate")))
    text = page.text("edconfirm")
    page.screenshot("confirm")
    if box:
        page.click(page.d.find_element(By.ID, "edyes" if confirm else "edno"))
    return text


def serve(name, program, stim):
    """PROGRAM copied to OUT/NAME and served; its stimulus (an operator session: `@TICK ADDR=VALUE
    ...` lines, docs/CLI.md) played to it in order through `ladderjit monitor write`."""
    d = os.path.join(out, name)
    os.makedirs(d)
    path = os.path.join(d, os.path.basename(program))
    shutil.copy(program, path)
    srv = httputil.Serve(exe, path, d, "serve", duration=280)
    steps = 0
    for line in open(stim):
        items = line.split("#")[0].split()
        if not items or not items[0].startswith("@"):
            continue
        rc, _, err = serveutil.monitor(exe, srv.sock, "write", *items[1:])
        check(rc == 0, "%s: stimulus %s: monitor write %s: %s" % (name, items[0], " ".join(items[1:]), err.strip()))
        steps += 1
    print("     %s: %d stimulus steps played" % (name, steps))
    return srv, path


def lock(srv, name, item):
    st, a = call(srv, "/api/lock", {"item": item})
    check(st == 200, "%s: %s locked through the live view: %d %s" % (name, item, st, a.get("error", "")))


def files_after_update(name, path, original, added):
    now = open(path, "rb").read().decode()
    old_lines, new_lines = original.decode().splitlines(True), now.splitlines(True)
    # The edited rung is printed anew by the dialect (an IL line number may go); every line
    # outside it is the old file's byte for byte.
    ops = [o for o in difflib.SequenceMatcher(None, old_lines, new_lines, autojunk=False).get_opcodes()
           if o[0] != "equal"]
    lo, hi = (min(o[1] for o in ops), max(o[2] for o in ops)) if ops else (0, 0)
    nlo, nhi = (min(o[3] for o in ops), max(o[4] for o in ops)) if ops else (0, 0)
    region = [" ".join(l.split()) for l in new_lines[nlo:nhi]]
    check(ops and hi - lo <= 10 and added in region and old_lines[:lo] == new_lines[:nlo] and
          old_lines[hi:] == new_lines[nhi:],
          "%s: the file gains '%s' in the edited rung (old lines %d-%d printed anew), every other "
          "line byte for byte: %s" % (name, added, lo + 1, hi, region))
    hist = path + ".history"
    copies = sorted(os.listdir(hist)) if os.path.isdir(hist) else []
    check(len(copies) == 1 and open(os.path.join(hist, copies[0]), "rb").read() == original,
          "%s: the history holds the old file: %s" % (name, copies))
    audit = path + ".edits.jsonl"
    recs = [json.loads(l) for l in open(audit)] if os.path.exists(audit) else []
    check(len(recs) == 1 and added.split()[-1] in recs[0].get("diff", "") and recs[0].get("editor", "").startswith("page-"),
          "%s: the audit log has the change, by the page's editor: %s" %
          (name, [{k: r.get(k) for k in ("editor", "client", "old", "new")} for r in recs]))


def enter(page):
    """Enter in the input line. Enter checks the text once more with the server before it is
    entered (the input closes): keys sent, or the grid read, before that would race it."""
    page.keys(Keys.ENTER)
    wait("entered", lambda: page.js("return document.getElementById('edin').disabled"), 10)


def typed(page, text):
    """Into the input line once it has the focus, checked as typed, Enter."""
    wait("the input", lambda: page.js("return document.activeElement.id") == "edin", 5)
    page.keys(text)
    msg = wait("checked", lambda: (lambda t: t if " ok" in t else None)(page.text("edinmsg")), 10)
    enter(page)
    return msg or page.text("edinmsg")


def toolbar(page, row):
    """The rest of the toolbar by keys on the rung, each checked by the server's grid: a row
    (r), an NO contact on it (1) joined by a vertical line (|) is a parallel branch; undo to the
    rung as it runs. A new rung (n) with a contact, lines (-) and a function box (9) from the
    catalogue, and a comment (;); then 放弃修改."""
    name = page.name
    page.click_cell(row, 0)
    page.keys("r")
    g = page.grid()
    check(g["grid"]["rows"] == 2, "%s: key r inserts a row: %d rows" % (name, g["grid"]["rows"]))
    page.click_cell(row + 1, 0)
    page.keys("1")
    typed(page, "X480.2")
    page.click_cell(row, 1)
    page.keys("|")
    wait("the parallel converted", lambda: page.grid()["net"], 20)
    g = page.settled()
    check(g and g["net"] and not g["errors"] and ["%d,1" % row] == list(g["grid"]["links"]),
          "%s: an NO contact on the new row joined by a vertical line is a parallel branch, no error: %s" %
          (name, g and g["errors"]))
    page.screenshot("parallel")
    for _ in range(3):
        page.ctrl("z")
    g = page.grid()
    check(g["grid"]["rows"] == 1 and not g["dirty"], "%s: three Ctrl+Z give the running rung back" % name)
    page.keys("n")
    g = page.grid()
    check(g["dirty"] and g["grid"]["rows"] == 1 and all(c["k"] == "empty" for c in g["grid"]["cells"]),
          "%s: key n makes a new empty rung after it: %s" % (name, page.text("edwhere")))
    cols = g["grid"]["cols"]
    page.click_cell(0, 0)
    page.keys("1")
    typed(page, "X480.2")
    for _ in range(cols - 2):
        page.keys("-", Keys.ARROW_RIGHT)
    page.keys("9")
    msg = typed(page, "MOV 100 D5")
    check("ok" in msg, "%s: the box MOV 100 D5 checked against the catalogue as typed: '%s'" % (name, msg))
    page.keys(";")
    typed(page, "set D5 | from the page")
    wait("the new rung converted", lambda: page.grid()["net"], 20)
    g = page.settled()
    last = g["grid"]["cells"][cols - 1] if g else {}
    check(g and g["net"] and not g["errors"] and last.get("k") == "box" and last.get("instr") == "MOV",
          "%s: the new rung [X480.2]--[MOV 100 D5] with its comment converts with no error: %s %s" %
          (name, last, g and g["errors"]))
    page.screenshot("new_rung")
    page.click(page.d.find_element(By.ID, "eddiscard"))
    wait("discard", lambda: "放弃修改: the edits are dropped" in page.text("edstate"), 30)
    page.click(page.d.find_element(By.CSS_SELECTOR, 'button[data-act="prev"]'))
    g = page.grid()
    check(not g["dirty"] and g["grid"]["rows"] == 1, "%s: after 放弃修改 no rung is edited" % name)


def rungs_len(page):
    return page.js("var E=window.ladder.editor.state();return E.parts[E.p].rungs.length")


def update_disabled(page):
    return page.js("return document.getElementById('edupdate').disabled")


def focus_grid(page):
    page.js("document.getElementById('edgridbox').focus()")


def go(page, p, r):
    """The editor to rung r of part p (as a link of its side lists does), the grid focused."""
    page.js("window.ladder.editor.go(arguments[0], arguments[1])", p, r)
    focus_grid(page)


def networks(page):
    """选择/复制/剪切/粘贴/删除网络 on the rung of G2620.3 and its neighbours, all undone: a copy
    pasted after it is a new rung with the same grid, converted with no error, and makes G2620.3
    a double coil (双线圈); Ctrl+Del deletes it and nothing is left to update; a cut rung pasted
    one rung up is a move (更新修改 enabled), two Ctrl+Z give the running order back; two rungs
    selected (s, PgDn) are copied and pasted together; a marker is refused."""
    name = page.name
    p, r, row, col, orig = open_rung(page, "G2620.3")
    focus_grid(page)
    n0 = rungs_len(page)
    cells0 = page.grid()["grid"]["cells"]
    check(update_disabled(page), "%s: nothing edited: 更新修改 disabled" % name)
    page.ctrl("c")
    check("1 rung(s) copied" in page.text("edstate"), "%s: Ctrl+C copies the rung: '%s'" % (name, page.text("edstate")))
    page.ctrl("v")
    g = page.settled()
    st = page.js("var E=window.ladder.editor.state(),x=E.parts[E.p].rungs[E.r];return [E.r,x.orig]")
    check(g and g["net"] and not g["errors"] and g["grid"]["cells"] == cells0 and st == [r + 1, -1] and
          rungs_len(page) == n0 + 1,
          "%s: Ctrl+V pastes a new rung after it with the same grid, converted with no error: rung %s, %d rungs" %
          (name, st, rungs_len(page)))
    dbl = page.text("eddbl")
    check("G2620.3" in dbl and dbl.count("rung") >= 2, "%s: 双线圈 lists G2620.3 written by both: '%s'" % (name, dbl))
    check(not update_disabled(page), "%s: a pasted rung is an edit: 更新修改 enabled" % name)
    page.screenshot("pasted")
    page.ctrl(Keys.DELETE)
    check(rungs_len(page) == n0 and update_disabled(page) and "G2620.3" not in page.text("eddbl"),
          "%s: Ctrl+Del deletes the pasted rung: %d rungs, nothing to update: '%s'" % (name, rungs_len(page), page.text("edstate")))
    go(page, p, r)
    page.ctrl("x")
    check(rungs_len(page) == n0 - 1 and not update_disabled(page),
          "%s: Ctrl+X cuts the rung: %d rungs, 更新修改 enabled" % (name, rungs_len(page)))
    # Pasted after rung r-2 (r-1 is now the rung before it): it lands one place up (one down
    # when it was among the first two).
    go(page, p, r - 2 if r >= 2 else r)
    page.ctrl("v")
    order = page.js("return window.ladder.editor.state().parts[arguments[0]].rungs.map(function(x){return x.orig})", p)
    moved = (sorted(o for o in order if o >= 0) == [o for o in range(n0) if o != orig] and
             order.index(-1) == (r - 1 if r >= 2 else r + 1))
    check(rungs_len(page) == n0 and moved and not update_disabled(page),
          "%s: pasted one rung up: the rung moved (%s), 更新修改 enabled" % (name, order))
    page.settled()
    page.ctrl("z")
    page.ctrl("z")
    order = page.js("return window.ladder.editor.state().parts[arguments[0]].rungs.map(function(x){return x.orig})", p)
    check(order == list(range(n0)) and update_disabled(page),
          "%s: two Ctrl+Z give the running order back, nothing to update: %s" % (name, order))
    # Two neighbouring rungs with grids: s marks the first, PgDn selects the second.
    i = page.js("var R=window.ladder.editor.state().parts[arguments[0]].rungs;for(var i=0;i+1<R.length;i++)"
                "if(R[i].grid&&R[i+1].grid)return i;return -1", p)
    check(i >= 0, "%s: two neighbouring ladder rungs to select" % name)
    go(page, p, i)
    page.keys("s", Keys.PAGE_DOWN)
    check("rungs %d-%d selected" % (i + 1, i + 2) in page.text("edwhere"),
          "%s: s and PgDn select two rungs: '%s'" % (name, page.text("edwhere")))
    page.ctrl("c")
    page.ctrl("v")
    check("2 rung(s) pasted" in page.text("edstate") and rungs_len(page) == n0 + 2,
          "%s: the two rungs copied and pasted: %d rungs, '%s'" % (name, rungs_len(page), page.text("edstate")))
    page.screenshot("pasted_two")
    page.ctrl("z")
    check(rungs_len(page) == n0 and update_disabled(page), "%s: Ctrl+Z removes both" % name)
    m = page.js("var E=window.ladder.editor.state();for(var p=0;p<E.parts.length;p++){var R=E.running.parts[p].rungs;"
                "for(var r=0;r<R.length;r++)if(R[r].kind==='marker')return [p,r]}return null")
    if m:
        go(page, m[0], m[1])
        page.ctrl(Keys.DELETE)
        check("marker" in page.text("edstate") and update_disabled(page),
              "%s: a marker is not deleted: '%s'" % (name, page.text("edstate")))


def hnc8():
    name = "hnc8"
    srv, path = serve(name, os.path.join(examples, "lathe_panel.stl"), os.path.join(examples, "lathe_panel.stim"))
    original = open(path, "rb").read()
    drv = chrome()
    page = Page(drv, name)
    try:
        lock(srv, name, "X482.1=1")
        check(serveutil.wait_value(exe, srv.sock, "G2620.3", 1, 20),
              "%s: G2620.3 = 1 after the stimulus (increment mode)" % name)
        st, g0 = call(srv, "/api/edit")
        v0, h0 = g0["running"]["version"], g0["running"]["hash"]
        # Bad bodies of the grid route: a clear 400 or a located refusal, never a crash.
        for body, want in [({"open": "yes"}, 400), ({"bogus": 1}, 400), ({"rungs": "x"}, 400),
                           ({"operand": 5}, 400), ({"rungs": [{"grid": {"rows": 100000, "cols": 1}}]}, 200),
                           ({"rungs": [{"grid": {"rows": 1, "cols": 2, "cells": [{"k": "weird"}, {}]}}]}, 200)]:
            st, a = call(srv, "/api/edit/grid", body)
            errs = [e["message"] for r in a.get("rungs", []) for e in r.get("errors", [])]
            check(st == want and (a.get("error") or errs),
                  "%s: /api/edit/grid %s: %d %s" % (name, json.dumps(body)[:60], st, a.get("error") or errs))
        open_editor(page, srv.url, srv.token)
        p, r, row, col, orig = open_rung(page, "G2620.3")
        page.screenshot("opened")

        # The NC contact, 更新修改, cancel, 放弃修改: nothing changes.
        insert_nc(page, row, 1, "X482.1", True)
        page.screenshot("inserted")
        text = update(page, confirm=False)
        check("init part runs again" in text and "R0.2" in text and "G2564" in text and "+ANI X482.1" in text,
              "%s: the confirmation says the init part runs again, what it writes (R0.2, G2564) and the diff" % name)
        st, g = call(srv, "/api/edit")
        check(g["draft"]["open"] and g["draft"]["editor"].startswith("page-"),
              "%s: the draft is open on the server, held by the page: %s" % (name, g["draft"].get("editor")))
        page.click(drv.find_element(By.ID, "eddiscard"))
        ok = wait("discard", lambda: "放弃修改: the edits are dropped" in page.text("edstate"), 30)
        check(ok, "%s: 放弃修改: '%s'" % (name, page.text("edstate")))
        st, g = call(srv, "/api/edit")
        check(not g["draft"]["open"] and g["running"]["version"] == v0 and g["running"]["hash"] == h0,
              "%s: after 放弃修改: no draft, the same version and hash" % name)
        check(open(path, "rb").read() == original and not os.path.exists(path + ".history") and
              not os.path.exists(path + ".edits.jsonl"),
              "%s: after 放弃修改: the file untouched, no history, no audit record" % name)
        check(serveutil.read(exe, srv.sock, "G2620.3") == 1, "%s: after 放弃修改: G2620.3 still 1" % name)
        g = page.settled()
        check(g and g["p"] == p and g["r"] == r and
              g["grid"]["cells"][row * g["grid"]["cols"] + 1]["k"] == "line" and not g["dirty"],
              "%s: after 放弃修改 the editor shows the running rung again: %s" %
              (name, g and {k: g[k] for k in ("p", "r", "dirty")}))
        page.screenshot("discarded")

        toolbar(page, row)
        networks(page)
        p, r, row, col, orig = open_rung(page, "G2620.3")

        # An element after an output: marked on its cell, nothing sent; undo.
        page.click_cell(row, 3)
        page.keys("5")
        wait("the input", lambda: page.js("return document.activeElement.id") == "edin", 5)
        page.keys("Y0.2")
        wait("checked", lambda: "ok" in page.text("edinmsg"), 10)
        enter(page)
        g = page.settled()
        marks = page.errcells()
        check(g and g["errors"] and any(c > 3 and "after an output" in t for _, c, t in marks),
              "%s: a line after an output is marked on its cell: %s" % (name, marks))
        check("Y0.2" in page.text("eddbl"),
              "%s: 双线圈 lists Y0.2, now written by two outputs: '%s'" % (name, page.text("eddbl")))
        page.screenshot("invalid")
        page.click(drv.find_element(By.ID, "edupdate"))
        ok = wait("refused", lambda: "nothing was sent" in page.text("edstate"), 20)
        st, g = call(srv, "/api/edit")
        check(ok and not g["draft"]["open"] and g["running"]["version"] == v0,
              "%s: 更新修改 refused before sending: '%s'; no draft, version %s" % (name, page.text("edstate"), g["running"]["version"]))
        page.click_cell(row, 3)
        page.ctrl("z")
        g = page.grid()
        check(g["grid"]["cells"][row * g["grid"]["cols"] + 3]["k"] == "line" and not page.errcells(),
              "%s: Ctrl+Z undoes it: the line is back, no mark" % name)

        # An output to an input: the grid takes it, the verifier does not (422 on the cell).
        page.click_cell(row, col)
        page.keys(Keys.ENTER)
        wait("the input", lambda: page.js("return document.activeElement.id") == "edin", 5)
        page.ctrl("a")
        page.keys("X0.5")
        wait("checked", lambda: "ok" in page.text("edinmsg"), 10)
        enter(page)
        page.settled()
        page.click(drv.find_element(By.ID, "edupdate"))
        ok = wait("the check's refusal", lambda: "does not verify" in page.text("edstate"), 60)
        marks = page.errcells()
        check(ok and any(c == col for _, c, _t in marks),
              "%s: the verifier's error is drawn on the output's cell: %s" % (name, marks))
        page.screenshot("refused")
        st, g = call(srv, "/api/edit")
        check(g["running"]["version"] == v0 and open(path, "rb").read() == original,
              "%s: the running program and the file unchanged" % name)
        page.click_cell(row, 0)
        page.ctrl("z")
        g = page.grid()
        check(g["grid"]["cells"][row * g["grid"]["cols"] + col].get("op") == "G2620.3",
              "%s: Ctrl+Z gives the output G2620.3 back" % name)

        # The NC contact again, 更新修改 confirmed.
        insert_nc(page, row, 1, "X482.1", True)
        t0 = time.time()
        update(page, confirm=True)
        ok = wait("the new version", lambda: call(srv, "/api/edit")[1]["running"]["version"] > v0, 60)
        check(ok, "%s: 更新修改: a new version runs (%.1f s after the click)" % (name, time.time() - t0))
        check(serveutil.wait_value(exe, srv.sock, "G2620.3", 0, 20),
              "%s: G2620.3 follows the new rung: 0 with X482.1 locked to 1" % name)
        lock(srv, name, "X482.1=0")
        check(serveutil.wait_value(exe, srv.sock, "G2620.3", 1, 20),
              "%s: G2620.3 = 1 again with X482.1 locked to 0" % name)
        files_after_update(name, path, original, "ANI X482.1")
        wait("the page reloaded", lambda: page.js("return document.readyState") == "complete" and
             page.js("return !!(window.ladder&&window.ladder.live&&window.ladder.live.last)"), 30)
        time.sleep(1)
        page.screenshot("updated")
        drawn = page.js("return Array.prototype.map.call(document.querySelectorAll('g.el.contact-nc title'),"
                        "function(t){return t.textContent}).join(' | ')")
        check("X482.1" in (drawn or ""), "%s: the reloaded page draws the new contact" % name)
    finally:
        drv.quit()
        srv.stop()


def delete_update(page, srv, path, coil, symbol, on, off):
    """删除网络 put live: the rung of `coil` (written as `symbol`) deleted with Ctrl+Del and
    更新修改 confirmed. Before, the writes `on` make `coil` 1 and `off` 0 again; after, no rung
    writes it and `on` leaves it 0. The file loses exactly the rung's lines (its statements and
    the comment lines before it), the history holds both older files, the audit log two records."""
    name = page.name
    for w, want in ((on, 1), (off, 0)):
        rc, _, err = serveutil.monitor(exe, srv.sock, "write", *w)
        check(rc == 0 and serveutil.wait_value(exe, srv.sock, coil, want, 20),
              "%s: before the deletion, %s gives %s = %d" % (name, " ".join(w), coil, want))
    before = open(path, "rb").read().decode()
    st, g = call(srv, "/api/edit")
    v1 = g["running"]["version"]
    open_editor(page, srv.url, srv.token)
    open_rung(page, coil)
    focus_grid(page)
    n = rungs_len(page)
    page.ctrl(Keys.DELETE)
    check(rungs_len(page) == n - 1 and "删除网络" in page.text("edstate"),
          "%s: Ctrl+Del deletes the rung of %s: '%s'" % (name, coil, page.text("edstate")))
    text = update(page, confirm=True)
    ok = wait("the new version", lambda: call(srv, "/api/edit")[1]["running"]["version"] > v1, 60)
    check(ok and ("-WRT " + symbol) in text,
          "%s: 更新修改 of the deletion: a new version runs (%s); the confirmation's diff has -WRT %s" %
          (name, page.text("edstate"), symbol))
    rc, _, err = serveutil.monitor(exe, srv.sock, "write", *on)
    check(rc == 0 and not serveutil.wait_value(exe, srv.sock, coil, 1, 3),
          "%s: %s is written by no rung: %s leaves it 0" % (name, coil, " ".join(on)))
    now = open(path, "rb").read().decode()
    old_lines, new_lines = before.splitlines(True), now.splitlines(True)
    ops = [o for o in difflib.SequenceMatcher(None, old_lines, new_lines, autojunk=False).get_opcodes()
           if o[0] != "equal"]
    gone = [" ".join(l.split()) for o in ops for l in old_lines[o[1]:o[2]]]
    stmts = [l for l in gone if not l.startswith(";")]
    check(ops and all(o[0] == "delete" for o in ops) and len(stmts) <= 4 and
          any(l.startswith("WRT " + symbol) for l in stmts),
          "%s: the file loses the rung's lines and nothing else: %s" % (name, gone))
    hist = path + ".history"
    recs = [json.loads(l) for l in open(path + ".edits.jsonl")]
    check(len(os.listdir(hist)) == 2 and len(recs) == 2,
          "%s: the history holds both older files, the audit log two records: %s, %d" %
          (name, sorted(os.listdir(hist)), len(recs)))
    page.screenshot("deleted")


def other(name, program, stim, locks, coil, address, added, delete=False):
    srv, path = serve(name, os.path.join(examples, program), os.path.join(examples, stim))
    original = open(path, "rb").read()
    drv = chrome()
    page = Page(drv, name)
    try:
        for item in locks:
            lock(srv, name, item)
        check(serveutil.wait_value(exe, srv.sock, coil, 1, 20), "%s: %s = 1 before the edit" % (name, coil))
        st, g0 = call(srv, "/api/edit")
        v0 = g0["running"]["version"]
        open_editor(page, srv.url, srv.token)
        p, r, row, col, orig = open_rung(page, coil)
        insert_nc(page, row, col - 1, address, False)
        page.screenshot("inserted")
        update(page, confirm=True)
        ok = wait("the new version", lambda: call(srv, "/api/edit")[1]["running"]["version"] > v0, 60)
        check(ok, "%s: 更新修改: a new version runs" % name)
        check(serveutil.wait_value(exe, srv.sock, coil, 0, 20),
              "%s: %s follows the new rung: 0 with %s locked to 1" % (name, coil, address))
        files_after_update(name, path, original, added)
        wait("the page reloaded", lambda: page.js("return !!(window.ladder&&window.ladder.live&&window.ladder.live.last)"), 30)
        time.sleep(1)
        page.screenshot("updated")
        if delete:
            delete_update(page, srv, path, *delete)
    finally:
        drv.quit()
        srv.stop()


def part_names(page):
    return page.js("return window.ladder.editor.state().parts.map(function(p){return p.name})")


def new_rung_with(page, contact, last_key, last_text):
    """In the shown (new, empty) rung: NO contact `contact` in column 1, lines, and at the last
    column the element of key `last_key` (5 output, 9 box) with `last_text`."""
    g = page.grid()
    cols = g["grid"]["cols"]
    page.click_cell(0, 0)
    page.keys("1")
    typed(page, contact)
    for _ in range(cols - 2):
        page.keys("-", Keys.ARROW_RIGHT)
    page.keys(last_key)
    msg = typed(page, last_text)
    wait("the rung converted", lambda: page.grid()["net"], 20)
    return msg, page.settled()


def reopen_at(page, srv, part):
    """After an update the page reloads: the editor opened again at `part`; (running version,
    the part names)."""
    wait("the page reloaded", lambda: page.js("return !!(window.ladder&&window.ladder.live&&window.ladder.live.last)"), 30)
    time.sleep(1)
    v = call(srv, "/api/edit")[1]["running"]["version"]
    open_editor(page, srv.url, srv.token)
    names = part_names(page)
    page.click(page.d.find_element(By.CSS_SELECTOR, '#edparts a[data-part="%d"]' % names.index(part)))
    return v, names


def parts():
    """列表编辑 on lathe_panel.stl: key p adds a subroutine S7 (its markers from the server, an
    empty rung between them) filled with [X480.2]--(R7.0); a new PLC1 rung [X480.3]--[CALL S7];
    更新修改 puts both live (R7.0 follows X480.2 while X480.3 calls S7, keeps its value when not
    called; the file has SP S7 ... SPE and CALL S7). Shift+P renames S7
    to S8 (its marker and the call): the confirmation says S7 is removed, the file then has S8
    only. 删除子程序 of S8, still called: the check's refusal is drawn on the CALL box of the
    calling rung; Ctrl+Z gives it back."""
    name = "parts"
    d = os.path.join(out, name)
    os.makedirs(d)
    path = os.path.join(d, "lathe_panel.stl")
    shutil.copy(os.path.join(examples, "lathe_panel.stl"), path)
    srv = httputil.Serve(exe, path, d, "serve", duration=200)
    drv = chrome()
    page = Page(drv, name)
    try:
        lock(srv, name, "X480.2=1")
        lock(srv, name, "X480.3=1")
        st, g0 = call(srv, "/api/edit")
        v0 = g0["running"]["version"]
        open_editor(page, srv.url, srv.token)
        focus_grid(page)
        before = part_names(page)
        page.keys("p")
        wait("the input", lambda: page.js("return document.activeElement.id") == "edin", 5)
        check("新子程序" in page.text("edinlab") and page.js("return document.getElementById('edin').value") == "S0",
              "%s: key p asks for the new subroutine, suggesting the first free number: '%s'" %
              (name, page.js("return document.getElementById('edin').value")))
        page.ctrl("a")
        msg = typed(page, "S7")
        # Enter checks the name once more with the server, then adds the part.
        wait("the new part", lambda: "S7" in part_names(page), 10)
        names = part_names(page)
        g = page.grid()
        check(names == before + ["S7"] and g["r"] == 1 and g["dirty"] and "S7" in page.text("edparts"),
              "%s: S7 is added after the last part and shown at its empty rung: %s '%s' ('%s')" %
              (name, names, page.text("edwhere"), msg))
        msg, g = new_rung_with(page, "X480.2", "5", "R7.0")
        check(g and g["net"] and not g["errors"], "%s: S7's rung [X480.2]--(R7.0) converts: %s" % (name, g and g["errors"]))
        page.screenshot("new_subroutine")
        # A PLC1 rung calling it, after PLC1's first rung.
        page.click(page.d.find_element(By.CSS_SELECTOR, '#edparts a[data-part="%d"]' % names.index("PLC1")))
        focus_grid(page)
        page.keys("n")
        msg, g = new_rung_with(page, "X480.3", "9", "CALL S7")
        check(g and g["net"] and not g["errors"], "%s: a PLC1 rung [X480.3]--[CALL S7] converts: %s %s" % (name, msg, g and g["errors"]))
        text = update(page, confirm=True)
        ok = wait("the new version", lambda: call(srv, "/api/edit")[1]["running"]["version"] > v0, 60)
        check(ok and "+SP S7" in text and "+CALL S7" in text and "removes" not in text,
              "%s: 更新修改 puts S7 and its call live (the diff adds SP S7 and CALL S7)" % name)
        check(serveutil.wait_value(exe, srv.sock, "R7.0", 1, 20), "%s: R7.0 = 1: S7 runs, called from PLC1" % name)
        lock(srv, name, "X480.2=0")
        check(serveutil.wait_value(exe, srv.sock, "R7.0", 0, 20), "%s: R7.0 follows X480.2 to 0" % name)
        # Not called (X480.3 = 0), S7 does not run: R7.0 keeps its value (DIALECT.md 3).
        lock(srv, name, "X480.3=0")
        lock(srv, name, "X480.2=1")
        check(not serveutil.wait_value(exe, srv.sock, "R7.0", 1, 2),
              "%s: with the call's contact X480.3 at 0, S7 does not run: R7.0 stays 0" % name)
        text1 = open(path).read()
        lines = [" ".join(l.split()) for l in text1.splitlines()]
        check("SP S7" in lines and "OUT R7.0" in lines and "CALL S7" in lines and lines.index("SP S7") > lines.index("2END"),
              "%s: the file has the subroutine after 2END and the call" % name)

        # Rename S7 -> S8: the marker and the call; the update names S7 as removed.
        v1, names = reopen_at(page, srv, "S7")
        focus_grid(page)
        page.keys("P")
        wait("the input", lambda: page.js("return document.activeElement.id") == "edin", 5)
        page.ctrl("a")
        typed(page, "S8")
        wait("the rename", lambda: part_names(page)[-1] == "S8", 10)
        check(part_names(page)[-1] == "S8" and "renamed from S7" in page.text("edparts"),
              "%s: Shift+P renames S7 to S8: '%s'" % (name, page.text("edparts")))
        page.screenshot("renamed")
        text = update(page, confirm=True)
        ok = wait("the new version", lambda: call(srv, "/api/edit")[1]["running"]["version"] > v1, 60)
        check(ok and "removes S7" in text and "+CALL S8" in text and "-CALL S7" in text,
              "%s: the confirmation says the update removes S7; the call is renamed too" % name)
        text2 = open(path).read()
        check("SP S8" in text2 and "CALL S8" in text2 and "S7" not in text2,
              "%s: the file has S8 and no S7" % name)
        recs = [json.loads(l) for l in open(path + ".edits.jsonl")]
        check(len(recs) == 2 and recs[1].get("removed") == ["S7"],
              "%s: the audit record of the rename names S7 as removed" % name)

        # 删除子程序 of the called S8: refused by the check on the call; Ctrl+Z.
        v2, names = reopen_at(page, srv, "S8")
        page.click(page.d.find_element(By.CSS_SELECTOR, 'button[data-act="delsub"]'))
        check(part_names(page) == names[:-1] and "still called from PLC1" in page.text("edstate") and
              "S8 removed" in page.text("edparts"),
              "%s: 删除子程序 takes S8 out and says where it is still called: '%s'" % (name, page.text("edstate")))
        page.click(page.d.find_element(By.ID, "edupdate"))
        ok = wait("the check's refusal", lambda: "does not verify" in page.text("edstate"), 60)
        marks = wait("the mark on the call", lambda: page.errcells() or None, 10) or []
        g = page.grid()
        cols = g["grid"]["cols"] if g and g["grid"] else 0
        check(ok and "PLC1 rung" in page.text("edbad") and
              any("S8" in t and g["grid"]["cells"][r * cols + c]["k"] in ("box", "box-part") for r, c, t in marks) and
              call(srv, "/api/edit")[1]["running"]["version"] == v2,
              "%s: the update is refused, drawn on the CALL box of the calling rung (listed under rungs "
              "with errors), nothing changed: %s '%s'" % (name, marks, page.text("edbad")))
        page.screenshot("delete_refused")
        focus_grid(page)
        page.ctrl("z")
        check(part_names(page) == names, "%s: Ctrl+Z gives S8 back: %s" % (name, part_names(page)))
    finally:
        drv.quit()
        srv.stop()


def read_only():
    """Under --http-read-only the page has no editor and the grid route is refused."""
    name = "read-only"
    d = os.path.join(out, name)
    os.makedirs(d)
    path = os.path.join(d, "lathe_panel.stl")
    shutil.copy(os.path.join(examples, "lathe_panel.stl"), path)
    srv = httputil.Serve(exe, path, d, "serve", extra=["--http-read-only"], duration=120)
    drv = chrome()
    page = Page(drv, name)
    try:
        page.d.get(srv.url + "/?token=" + srv.token)
        live = wait("live", lambda: page.js("return !!(window.ladder&&window.ladder.live&&window.ladder.live.last)"), 40)
        check(live and not page.js("return !!document.getElementById('edbtn') || !!document.getElementById('editor')"),
              "%s: the live page has no editor (no 编辑 button, no panel)" % name)
        st, a = call(srv, "/api/edit/grid", {"open": True})
        check(st == 403, "%s: POST /api/edit/grid refused: %d %s" % (name, st, a.get("error", "")))
        page.screenshot("page")
    finally:
        drv.quit()
        srv.stop()


t_start = time.time()
read_only()
hnc8()
parts()
other("fanuc", "fanuc_coolant.pmc", "fanuc_coolant.stim", ["X0.0=0", "X0.1=1"], "R0.7", "X0.1", "AND.NOT X0.1",
      delete=("R1.0", "M08_ON", ["F10=8", "F7.0=1"], ["F7.0=0"]))
# FANUC COM..COME (fanuc-pmc.md 6.1): COME makes no statement and is drawn before the rung after
# it; that rung edited in the page (its converted grid carries no written text) keeps COME
# before it through the rung's "lead", else the update would be refused ("COM on line 2 has no
# COME before END1").
come = os.path.join(out, "come-src")
os.makedirs(come)
with open(os.path.join(come, "come.pmc"), "w") as f:
    f.write("RD X0.0\nCOM\nRD X0.1\nWRT R0.0\nCOME\nRD X0.2\nWRT R1.0\nEND1\nEND2\nEND\n")
with open(os.path.join(come, "come.stim"), "w") as f:
    f.write("@0 X0.2=1\n")
other("fanuc-come", os.path.join(come, "come.pmc"), os.path.join(come, "come.stim"), ["X0.3=1"], "R1.0",
      "X0.3", "AND.NOT X0.3")
other("iec", "conveyor.il", "conveyor.stim", ["%I0.0=1", "%I0.1=1", "%I0.3=1", "%I0.4=1"], "%Q0.0", "%I0.4", "ANDN %I0.4")
print("%.0f s" % (time.time() - t_start))
httputil.finish()
