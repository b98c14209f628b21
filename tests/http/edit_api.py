#!/usr/bin/env python3
"""The ladder editor's server side (docs/ladder-edit.md, issue 30) against a real `serve --http`,
in each dialect: fetch the running program's network JSON, insert a normally closed contact into a
rung as a page would, draft, check, 更新修改 (update); the output then follows the new rung (read
with `monitor read`, the contact's input locked through the live view), the file on disk holds the
new rung and every other line byte for byte, the history holds the old file, the audit log the
change. 放弃修改 (discard) leaves version, file and outputs untouched; an invalid edit is refused
with its rung and element and the running version unchanged; a stale base is refused with both
hashes; a second editor is refused naming the holder unless it takes over. Every edit route
refuses without the token, with a foreign Origin or Host, and (POST) under --http-read-only.
Usage: edit_api.py LADDERJIT EXAMPLES OUTDIR"""
import difflib, json, os, shutil, sys, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import httputil  # noqa: E402
import serveutil  # noqa: E402
from httputil import call, check  # noqa: E402

exe, examples, out = sys.argv[1], sys.argv[2], sys.argv[3]
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)

ROUTES = ["/api/edit/draft", "/api/edit/check", "/api/edit/update", "/api/edit/discard"]


def read(srv, addr):
    return serveutil.read(exe, srv.sock, addr)


def wait_value(srv, addr, want, seconds=15):
    return serveutil.wait_value(exe, srv.sock, addr, want, seconds)


def rung_of(nets, coil):
    """The top series of the rung that writes `coil`."""
    for part in nets["parts"]:
        for rung in part["rungs"]:
            if find_series(rung.get("network"), coil) is not None:
                return rung["network"]
    raise SystemExit("no rung writes " + coil)


def find_series(node, coil):
    """The series node whose children hold the output writing `coil` (a rung's network)."""
    if isinstance(node, dict):
        kids = node.get("children")
        if node.get("type") == "series" and kids:
            for k in kids:
                if k.get("type") == "coil" and any(o.get("text") == coil or o.get("symbol") == coil
                                                   for o in k.get("operands", [])):
                    return node
        for v in node.values():
            r = find_series(v, coil)
            if r is not None:
                return r
    elif isinstance(node, list):
        for v in node:
            r = find_series(v, coil)
            if r is not None:
                return r
    return None


def edited(nets, coil, contact, where=1):
    """`nets` with a normally closed contact on `contact` inserted at `where` in the series of the
    rung that writes `coil` (the edit a page makes); (networks, part name, rung number)."""
    nets = json.loads(json.dumps(nets))
    for part in nets["parts"]:
        for i, rung in enumerate(part["rungs"]):
            if find_series(rung.get("network"), coil) is not None:
                rung["network"]["children"].insert(where, {"type": "contact", "contact": "nc",
                                                           "operands": [{"text": contact}]})
                return nets, part["name"], i + 1
    raise SystemExit("no rung writes " + coil)


def draft(srv, nets, base, editor="tab1", **extra):
    body = dict(nets)
    body.update(base=base, editor=editor, **extra)
    return call(srv, "/api/edit/draft", body)


def version(srv):
    st, _, body = httputil.get(srv, "/api/model", token=srv.token)
    try:
        return json.loads(body)["version"]
    except (ValueError, KeyError):
        return None


def served_copy(name, program, duration=150):
    """`program` copied to OUT/NAME/ and served: (its folder, path, original bytes, server)."""
    d = os.path.join(out, name)
    os.makedirs(d)
    path = os.path.join(d, os.path.basename(program))
    shutil.copy(program, path)
    original = open(path, "rb").read()
    return d, path, original, httputil.Serve(exe, path, d, "serve", duration=duration)


def edit_loop(name, program, coil, contact, before, after, added_line, unknown, init=None):
    """The whole loop on `program` (copied to OUT/NAME/): `coil` is `before` while `contact` is
    locked to 1; after inserting NC `contact` into its rung it is `after` (the rung's logic), and
    `added_line` is the one line the program text gains."""
    d, path, original, srv = served_copy(name, program)
    try:
        st, ans = call(srv, "/api/lock", {"item": contact + "=1"})
        check(st == 200, "%s: lock %s=1 through the live view: %d %s" % (name, contact, st, ans))
        check(wait_value(srv, coil, before), "%s: %s = %d before the edit" % (name, coil, before))
        st, g = call(srv, "/api/edit")
        check(st == 200 and g["running"]["editable"] and g["draft"]["open"] is False,
              "%s: GET /api/edit: editable, no draft: %d" % (name, st))
        base, nets = g["running"]["hash"], g["running"]["networks"]
        check(set(g["init"]) >= {"runsOnUpdate", "writes", "rule"},
              "%s: GET /api/edit says what an update does with the init part: %s" %
              (name, g.get("init")))
        if init:
            # What the init part writes, from the program (hnc8: LDT / OUT R0.2 / MOV 100 G2564).
            check(g["init"]["runsOnUpdate"] is True and g["init"]["writes"] == init["writes"],
                  "%s: the init part runs on update and writes %s: %s" % (name, init["writes"], g["init"]))
            rc, _, e = serveutil.monitor(exe, srv.sock, "write", "%s=%d" % init["word"][:2])
            check(rc == 0 and wait_value(srv, init["word"][0], init["word"][1]),
                  "%s: %s=%d written before the edit: %s" % (name, init["word"][0], init["word"][1], e))
        v0 = version(srv)
        new, part, rung = edited(nets, coil, contact)

        # 放弃修改: a draft, then discard: nothing changed.
        st, a = draft(srv, new, base)
        check(st == 200 and a["base"] == base and a["stale"] is False, "%s: draft stored: %d %s" % (name, st, a))
        st, g = call(srv, "/api/edit")
        check(g["draft"]["open"] and g["draft"]["editor"] == "tab1" and g["draft"]["base"] == base,
              "%s: a second client sees the open draft, its editor and base" % name)
        st, a = call(srv, "/api/edit/check", {"editor": "tab1"})
        check(st == 200 and ("+" + added_line) in a.get("diff", ""),
              "%s: check: verifies, the diff adds '%s': %d %s" % (name, added_line, st, a.get("diff") or a))
        time.sleep(0.3)
        check(version(srv) == v0 and read(srv, coil) == before,
              "%s: draft and check change nothing running (version %s, %s = %s)" % (name, version(srv), coil, read(srv, coil)))
        st, a = call(srv, "/api/edit/discard", {"editor": "tab1"})
        check(st == 200, "%s: discard: %d %s" % (name, st, a))
        st, g = call(srv, "/api/edit")
        check(g["draft"]["open"] is False and g["running"]["hash"] == base and version(srv) == v0,
              "%s: after discard: no draft, same hash and version" % name)
        check(open(path, "rb").read() == original and not os.path.exists(path + ".history"),
              "%s: after discard: the file untouched, no history" % name)
        check(read(srv, coil) == before, "%s: after discard: %s still %d" % (name, coil, before))
        if init:
            check(read(srv, init["word"][0]) == init["word"][1],
                  "%s: draft, check and discard ran no init: %s still %d" % (name, init["word"][0], init["word"][1]))

        # A second editor: refused naming the holder, or takes over explicitly.
        draft(srv, new, base, editor="tab1")
        st, a = draft(srv, new, base, editor="tab2")
        check(st == 409 and a.get("holder", {}).get("editor") == "tab1",
              "%s: a second editor's draft is refused naming the holder: %d %s" % (name, st, a.get("error")))
        st, a = draft(srv, new, base, editor="tab2", takeOver=True)
        check(st == 200, "%s: takeOver: the second editor holds the draft: %d" % (name, st))
        st, a = call(srv, "/api/edit/update", {"editor": "tab1"})
        check(st == 409 and a.get("holder", {}).get("editor") == "tab2",
              "%s: the first editor can no longer update: %d %s" % (name, st, a.get("error")))
        check(version(srv) == v0, "%s: still the same version" % name)

        # 更新修改.
        st, a = call(srv, "/api/edit/update", {"editor": "tab2"})
        check(st == 200 and a.get("old") == base and a.get("hash") != base,
              "%s: update: %d %s" % (name, st, {k: a.get(k) for k in ("error", "version", "hash")}))
        check(wait_value(srv, coil, after),
              "%s: %s follows the new rung: %d with %s locked to 1" % (name, coil, after, contact))
        if init:
            # An update is a reload: the new init part ran once at the swap (hnc8-core.md 2.2),
            # as for monitor load; draft, check and discard above did not run it.
            check(read(srv, init["word"][0]) == init["word"][2],
                  "%s: the update ran the init part: %s = %d again" % (name, init["word"][0], init["word"][2]))
        st, ans = call(srv, "/api/lock", {"item": contact + "=0"})
        check(wait_value(srv, coil, before),
              "%s: %s = %d again with %s locked to 0 (the new rung, not a stale value)" % (name, coil, before, contact))
        now = open(path, "rb").read()
        old_lines, new_lines = original.decode().splitlines(True), now.decode().splitlines(True)
        # The edited rung is printed anew by the dialect (spacing, an IL line number, the blank
        # line after it may change); every line outside it is the old file's byte for byte.
        ops = [o for o in difflib.SequenceMatcher(None, old_lines, new_lines, autojunk=False)
               .get_opcodes() if o[0] != "equal"]
        lo, hi = (min(o[1] for o in ops), max(o[2] for o in ops)) if ops else (0, 0)
        nlo, nhi = (min(o[3] for o in ops), max(o[4] for o in ops)) if ops else (0, 0)
        region = [" ".join(l.split()) for l in new_lines[nlo:nhi]]
        check(ops and hi - lo <= 5 and added_line in region and
              old_lines[:lo] == new_lines[:nlo] and old_lines[hi:] == new_lines[nhi:],
              "%s: the file gains '%s' in the edited rung (old lines %d-%d printed anew), every "
              "other line byte for byte: %s" % (name, added_line, lo + 1, hi, region))
        left = [f for f in os.listdir(d) if ".edit-" in f]
        check(not left, "%s: no temporary file is left beside the program: %s" % (name, left))
        hist = os.path.join(path + ".history", "0001" + os.path.splitext(path)[1])
        check(os.path.exists(hist) and open(hist, "rb").read() == original,
              "%s: the history holds the old file as %s" % (name, os.path.relpath(hist, d)))
        audit = path + ".edits.jsonl"
        recs = [json.loads(l) for l in open(audit)] if os.path.exists(audit) else []
        check(len(recs) == 1 and recs[0]["old"] == base and recs[0]["new"] == a.get("hash") and
              recs[0]["client"].startswith("127.0.0.1:") and ("+" + added_line) in recs[0]["diff"] and
              recs[0]["time"].endswith("Z"),
              "%s: the audit log has the change (time, client, old and new hash, diff)" % name)
        st, g = call(srv, "/api/edit")
        check(g["running"]["hash"] == a.get("hash") and g["draft"]["open"] is False,
              "%s: the update closed the draft; the new version is the running one" % name)
        log = srv.log().decode(errors="replace")
        check("edit: update" in log and "POST /api/edit/update" in log,
              "%s: the update is logged with its client" % name)
        newhash, v1 = a.get("hash"), version(srv)

        # An invalid edit: an output followed by a contact, and an unknown address.
        bad = json.loads(json.dumps(g["running"]["networks"]))
        find_series(bad, coil)["children"].append({"type": "contact", "contact": "no",
                                                    "operands": [{"text": contact}]})
        draft(srv, bad, newhash)
        st, a = call(srv, "/api/edit/update", {"editor": "tab1"})
        dg = (a.get("diagnostics") or [{}])[0]
        check(st == 422 and dg.get("part") == part and dg.get("rung") == rung,
              "%s: a contact after the output is refused at %s rung %d: %d %s" % (name, part, rung, st, dg))
        bad = json.loads(json.dumps(g["running"]["networks"]))
        # The contact inserted (element 2 of the rung) now names an address no area has.
        rung_of(bad, coil)["children"][1]["operands"] = [{"text": unknown}]
        draft(srv, bad, newhash)
        st, a = call(srv, "/api/edit/check", {"editor": "tab1"})
        dg = (a.get("diagnostics") or [{}])[0]
        check(st == 422 and dg.get("rung") == rung and dg.get("element") == 2 and "id" in dg and
              dg.get("severity") == "error",
              "%s: an unknown address is refused at its rung and element: %d %s" % (name, st, dg))
        st, a = call(srv, "/api/edit/update", {"editor": "tab1"})
        check(st == 422, "%s: and update refuses it too: %d" % (name, st))
        st, g = call(srv, "/api/edit")
        check(g["running"]["hash"] == newhash and version(srv) == v1 and open(path, "rb").read() == now,
              "%s: after refused edits: same hash, version and file" % name)

        # A stale base: made from the version before the update.
        st, a = draft(srv, new, base)
        check(st == 200 and a["stale"] is True, "%s: a draft on an old base is stored, marked stale" % name)
        st, a = call(srv, "/api/edit/update", {"editor": "tab1"})
        check(st == 409 and a.get("base") == base and a.get("running", {}).get("hash") == newhash and
              a["running"].get("networks", {}).get("parts"),
              "%s: a stale base is refused with both hashes and the running networks: %d %s" % (name, st, a.get("error")))
        check(version(srv) == v1 and open(path, "rb").read() == now,
              "%s: nothing merged: same version and file" % name)
        call(srv, "/api/edit/discard", {"editor": "tab1"})
    finally:
        srv.stop()


def renamed(node, old, new):
    """`node` (networks JSON) with every operand text `old` written `new` (a subroutine's
    marker and its calls) and a part named `old` renamed: what the page's 列表编辑 rename sends."""
    if isinstance(node, dict):
        out = {k: renamed(v, old, new) for k, v in node.items()}
        if out.get("text") == old:
            out["text"] = new
        if "rungs" in out and out.get("name") == old:
            out["name"] = new
        return out
    if isinstance(node, list):
        return [renamed(v, old, new) for v in node]
    return node


def part_list(name, program, sub, new_sub, bad_names, new_lines):
    """列表编辑 (docs/ladder-edit.md "The part list") on `program`, whose subroutine `sub` is
    called: a new subroutine `new_sub` (its markers from /api/edit/grid, `new_lines` the program
    text they print as) goes live; deleting it again needs the update to name it
    (removeParts) and brings the file back byte for byte; deleting the called `sub` is refused by
    the check (its calls); renaming `sub` (marker and calls) goes live with removeParts [sub]."""
    d, path, original, srv = served_copy(name + "-parts", program)
    try:
        st, g = call(srv, "/api/edit")
        base, nets = g["running"]["hash"], g["running"]["networks"]
        st, o = call(srv, "/api/edit/grid", {"open": True})
        subs = [p["name"] for p in o.get("parts", []) if p.get("subroutine")]
        check(st == 200 and subs == [sub],
              "%s: the editor's parts mark the subroutine %s (and nothing else): %s" % (name, sub, subs))
        for bn in bad_names:
            st, a = call(srv, "/api/edit/grid", {"subroutine": bn})
            check(st == 200 and a.get("ok") is False and bn in a.get("error", ""),
                  "%s: a new subroutine named '%s' is refused with the reason: %s" % (name, bn, a.get("error")))
        st, a = call(srv, "/api/edit/grid", {"subroutine": new_sub})
        check(st == 200 and a.get("ok") and a.get("name") == new_sub.upper() and
              [r["kind"] for r in a.get("rungs", [])] == ["marker", "marker"],
              "%s: /api/edit/grid makes the markers of a new subroutine %s: %s" % (name, new_sub, a))
        added = json.loads(json.dumps(nets))
        added["parts"].append({"name": a.get("name"), "rungs": a.get("rungs", [])})
        st, r = draft(srv, added, base)
        st, c = call(srv, "/api/edit/check", {"editor": "tab1"})
        plus = [l[1:].strip() for l in c.get("diff", "").splitlines() if l.startswith("+") and not l.startswith("+++")]
        check(st == 200 and plus == new_lines and c.get("removes") == [],
              "%s: check: the draft adds exactly %s, removes nothing: %d %s" % (name, new_lines, st, plus or c))
        st, u = call(srv, "/api/edit/update", {"editor": "tab1"})
        check(st == 200, "%s: the new subroutine goes live: %d %s" % (name, st, u.get("error")))
        text = open(path).read()
        check(all(l in [" ".join(x.split()) for x in text.splitlines()] for l in new_lines),
              "%s: the file holds the new subroutine's lines" % name)
        st, g = call(srv, "/api/edit")
        h1, nets1 = g["running"]["hash"], g["running"]["networks"]
        check([p["name"] for p in nets1["parts"]][-1] == new_sub.upper(),
              "%s: the running program has the part %s" % (name, new_sub.upper()))

        # Deleting it again: the check names what goes, the update must name it too.
        gone = json.loads(json.dumps(nets1))
        gone["parts"] = [p for p in gone["parts"] if p["name"] != new_sub.upper()]
        draft(srv, gone, h1)
        st, c = call(srv, "/api/edit/check", {"editor": "tab1"})
        check(st == 200 and c.get("removes") == [new_sub.upper()],
              "%s: check says the draft removes %s: %d %s" % (name, new_sub.upper(), st, c.get("removes")))
        v1 = version(srv)
        st, u = call(srv, "/api/edit/update", {"editor": "tab1"})
        check(st == 409 and u.get("reason") == "removes-parts" and u.get("removes") == [new_sub.upper()],
              "%s: an update that does not name the removed part is refused: %d %s" % (name, st, u.get("error")))
        st, u = call(srv, "/api/edit/update", {"editor": "tab1", "removeParts": ["PLC1"]})
        check(st == 409 and version(srv) == v1,
              "%s: naming another part is refused too, nothing changed: %d" % (name, st))
        st, u = call(srv, "/api/edit/update", {"editor": "tab1", "removeParts": [new_sub.upper()]})
        check(st == 200, "%s: with removeParts [%s] the update goes live: %d %s" % (name, new_sub.upper(), st, u.get("error")))
        check(open(path, "rb").read() == original,
              "%s: added and deleted again, the file is the original byte for byte" % name)
        audit = [json.loads(l) for l in open(path + ".edits.jsonl")]
        check(len(audit) == 2 and audit[1].get("removed") == [new_sub.upper()] and "removed" not in audit[0],
              "%s: the audit record of the deletion names the removed part" % name)

        # Deleting the called subroutine: the check refuses it (its calls have no target).
        st, g = call(srv, "/api/edit")
        h2, nets2 = g["running"]["hash"], g["running"]["networks"]
        nocall = json.loads(json.dumps(nets2))
        nocall["parts"] = [p for p in nocall["parts"] if p["name"] != sub]
        draft(srv, nocall, h2)
        st, c = call(srv, "/api/edit/check", {"editor": "tab1"})
        dg = [x for x in c.get("diagnostics", []) if x.get("severity") == "error"]
        check(st == 422 and dg and dg[0].get("part") and dg[0].get("rung"),
              "%s: deleting the called %s is refused at a calling rung: %d %s" % (name, sub, st, dg[:1]))

        # Renaming it: the marker and every call (what the page sends), removeParts [sub].
        ren = renamed(nets2, sub, new_sub.upper())
        draft(srv, ren, h2)
        st, c = call(srv, "/api/edit/check", {"editor": "tab1"})
        check(st == 200 and c.get("removes") == [sub],
              "%s: renaming %s to %s verifies and removes %s: %d %s" % (name, sub, new_sub.upper(), sub, st, c.get("error") or c.get("removes")))
        st, u = call(srv, "/api/edit/update", {"editor": "tab1", "removeParts": [sub]})
        check(st == 200, "%s: the rename goes live: %d %s" % (name, st, u.get("error")))
        st, g = call(srv, "/api/edit")
        names = [p["name"] for p in g["running"]["networks"]["parts"]]
        check(new_sub.upper() in names and sub not in names,
              "%s: the running program's parts after the rename: %s" % (name, names))
    finally:
        srv.stop()


def security(program):
    """Every edit route: no token 401, wrong token 403, foreign Origin 403, foreign Host 421;
    under --http-read-only every POST is 403 with the reason (GET still reads)."""
    d = os.path.join(out, "security")
    os.makedirs(d)
    path = os.path.join(d, os.path.basename(program))
    shutil.copy(program, path)
    srv = httputil.Serve(exe, path, d, "rw", duration=60)
    try:
        st, g = call(srv, "/api/edit")
        base = g["running"]["hash"]
        body = dict(g["running"]["networks"], base=base)
        for route in ["/api/edit"] + ROUTES:
            b = None if route == "/api/edit" else (body if route.endswith("draft") else {})
            st, _ = call(srv, route, b, token=None)
            check(st == 401, "%s without the token: %d" % (route, st))
            st, _ = call(srv, route, b, token="x" * len(srv.token))
            check(st == 403, "%s with a wrong token: %d" % (route, st))
            st, _ = call(srv, route, b, origin="http://evil.example")
            check(st == 403, "%s with a foreign Origin: %d" % (route, st))
            st, _ = call(srv, route, b, host="evil.example")
            check(st == 421, "%s with a foreign Host: %d" % (route, st))
        st, g = call(srv, "/api/edit")
        check(g["draft"]["open"] is False and g["running"]["hash"] == base,
              "refused requests opened no draft and changed nothing")
        st, a = call(srv, "/api/edit/nosuch", {})
        check(st == 404, "an unknown edit route is 404: %d" % st)
        st, a = call(srv, "/api/edit/draft", {"base": base})
        check(st == 400 and "parts" in a.get("error", ""), "a draft without networks: 400 %s" % a.get("error"))
        st, a = call(srv, "/api/edit/draft", dict(body, base="sha256:x\nforged log line"))
        check(st == 400 and "base" in a.get("error", ""), "a draft whose base is no hash: 400 %s" % a.get("error"))
        st, a = call(srv, "/api/edit/draft", dict(body, editor="a b"))
        check(st == 400 and "editor" in a.get("error", ""), "an editor name with a blank: 400 %s" % a.get("error"))
        st, a = call(srv, "/api/edit/update", {"bogus": 1})
        check(st == 400 and "bogus" in a.get("error", ""), "an unknown field: 400 %s" % a.get("error"))
        st, a = call(srv, "/api/edit/update", {})
        check(st == 409 and a.get("reason") == "no-draft", "update without a draft: 409 %s" % a.get("error"))
        # A draft body over the bound (16 MiB): refused from its Content-Length, before any of
        # it is read (so the body is not sent).
        head = "\r\n".join(["POST /api/edit/draft HTTP/1.1", "Host: 127.0.0.1:%d" % srv.port,
                             "Authorization: Bearer " + srv.token, "Connection: close",
                             "Content-Type: application/json",
                             "Content-Length: %d" % ((16 << 20) + 1)])
        st, _, rest = httputil.request(srv.port, head, b"", timeout=10)
        check(st == 413, "a draft body over the bound is refused: %s %s" % (st, rest[:120]))
        # Within the bound but over the command bound (64 KiB): a draft may be large.
        st, a = call(srv, "/api/edit/draft", dict(body, trailing_comments=["x" * 100] * 1000))
        check(st == 200, "a 100 KiB draft is taken: %d %s" % (st, a.get("error")))
        st, a = call(srv, "/api/edit/discard", {})
        check(st == 200, "and discarded: %d" % st)
    finally:
        srv.stop()
    # A plc.dit container is not written back: refused with the reason, nothing opened.
    dit = os.path.join(d, "lathe_panel.dit")
    shutil.copy(os.path.join(examples, "lathe_panel.dit"), dit)
    srv = httputil.Serve(exe, dit, d, "dit", duration=60)
    try:
        st, g = call(srv, "/api/edit")
        check(st == 200 and g["running"]["editable"] is False and "plc.dit" in g["running"]["why"],
              "plc.dit: GET /api/edit says it cannot be edited and why: %s" % g["running"].get("why"))
        st, a = call(srv, "/api/edit/draft", dict(g["running"]["networks"], base=g["running"]["hash"]))
        check(st == 409 and a.get("reason") == "not-editable" and "plc.dit" in a.get("error", ""),
              "plc.dit: a draft is refused: %d %s" % (st, a.get("error")))
    finally:
        srv.stop()
    # An AOT server: a compiled .so cannot be edited live (compile's default key pair, made in
    # OUT, never ~/.config; docs/aot.md "Trust").
    os.environ["LADDERJIT_KEY_DIR"] = os.path.join(d, "keys")
    so = os.path.join(d, "lathe_panel.so")
    rc, _, e = serveutil.run(exe, "compile", path, "-o", so, timeout=120)
    check(rc == 0, "aot: ladderjit compile: %s" % e)
    srv = httputil.Serve(exe, path, d, "aot", extra=["--engine", "aot:" + so], duration=60)
    try:
        st, g = call(srv, "/api/edit")
        check(st == 200 and g["running"]["editable"] is False and "AOT" in g["running"]["why"],
              "aot: GET /api/edit says a compiled .so cannot be edited live: %s" % g["running"].get("why"))
        st, a = call(srv, "/api/edit/draft", dict(g["running"]["networks"], base=g["running"]["hash"]))
        check(st == 409 and a.get("reason") == "not-editable" and "AOT" in a.get("error", ""),
              "aot: a draft is refused: %d %s" % (st, a.get("error")))
    finally:
        srv.stop()
    srv = httputil.Serve(exe, path, d, "ro", extra=["--http-read-only"], duration=60)
    try:
        st, g = call(srv, "/api/edit")
        check(st == 200 and g["running"]["hash"], "read-only: GET /api/edit reads: %d" % st)
        body = dict(g["running"]["networks"], base=g["running"]["hash"])
        for route in ROUTES:
            st, a = call(srv, route, body if route.endswith("draft") else {})
            check(st == 403 and "read-only" in a.get("error", ""),
                  "read-only: %s refused with the reason: %d %s" % (route, st, a.get("error")))
        st, g = call(srv, "/api/edit")
        check(g["draft"]["open"] is False, "read-only: no draft was opened")
    finally:
        srv.stop()


def json_program():
    """A `.json` ladder PROGRAM (`ladderjit ladder --format json` of lathe_panel.stl) is written
    back as such a JSON: the inserted contact in it, the old JSON in the history."""
    d = os.path.join(out, "json")
    os.makedirs(d)
    path = os.path.join(d, "lathe_panel.json")
    rc, _, e = serveutil.run(exe, "ladder", "--format", "json", "-o", path,
                             os.path.join(examples, "lathe_panel.stl"))
    check(rc == 0, "json: ladder --format json: %s" % e)
    original = open(path, "rb").read()
    srv = httputil.Serve(exe, path, d, "serve", duration=60)
    try:
        call(srv, "/api/lock", {"item": "X482.1=1"})
        check(wait_value(srv, "G2620.2", 1), "json: G2620.2 = 1 before the edit")
        st, g = call(srv, "/api/edit")
        new, _, _ = edited(g["running"]["networks"], "G2620.2", "X482.1")
        st, a = draft(srv, new, g["running"]["hash"])
        st, a = call(srv, "/api/edit/update", {"editor": "tab1"})
        check(st == 200, "json: update: %d %s" % (st, a.get("error")))
        check(wait_value(srv, "G2620.2", 0), "json: G2620.2 follows the new rung: 0")
        now = json.loads(open(path).read())
        check(find_series(now, "G2620.2") is not None and
              any(c.get("contact") == "nc" and c["operands"][0]["text"] == "X482.1"
                  for c in rung_of(now, "G2620.2")["children"]),
              "json: the file is a ladder JSON holding the new contact")
        hist = os.path.join(path + ".history", "0001.json")
        check(os.path.exists(hist) and open(hist, "rb").read() == original,
              "json: the history holds the old JSON")
    finally:
        srv.stop()


which = os.environ.get("EDIT_API_ONLY", "")
if which in ("", "hnc8"):
    # HNC-8: LD R0.2 / OUT G2620.2 (R0.2 = 1 from init: manual mode) gains ANI X482.1 (-X key).
    edit_loop("hnc8", os.path.join(examples, "lathe_panel.stl"), "G2620.2", "X482.1", 1, 0,
              "ANI X482.1", "Q9999.9",
              init={"writes": ["R0.2", "G2564"], "word": ("G2564", 50, 100)})
if which in ("", "fanuc"):
    # FANUC: RD.NOT ESP_OK / WRT ESTOP (X0.0 = 0: E-stop active) gains AND.NOT X0.1.
    edit_loop("fanuc", os.path.join(examples, "fanuc_coolant.pmc"), "R0.7", "X0.1", 1, 0,
              "AND.NOT X0.1", "Q9999.9")
if which in ("", "iec"):
    # IEC: LD [%MW0 >= %KW0] / ST %M6 / ST %Q0.2 (0 >= 0) gains ANDN %I0.4.
    edit_loop("iec", os.path.join(examples, "conveyor.il"), "%Q0.2", "%I0.4", 1, 0,
              "ANDN %I0.4", "%Z9.9")
if which in ("", "parts"):
    # 列表编辑 in each dialect: a new subroutine, deleted again, the called one renamed.
    part_list("hnc8", os.path.join(examples, "lathe_panel.stl"), "S1", "s7", ["S", "X7", "S9999", "S-1"],
              ["SP S7", "SPE"])
    part_list("fanuc", os.path.join(examples, "fanuc_magazine.pmc"), "P10", "P7", ["P", "S7", "P99999", "P0"],
              ["SP P7", "SPE"])
    # IL: a subroutine ends at the next SRi: or the end of the text (RET is a return, which
    # an empty subroutine does not need): the new part prints as its label alone.
    part_list("iec", os.path.join(examples, "pump_station.il"), "SR0", "SR7", ["SR", "%SR7", "SR64"],
              ["SR7:"])
if which in ("", "json"):
    json_program()
if which in ("", "security"):
    security(os.path.join(examples, "lathe_panel.stl"))
httputil.finish()
