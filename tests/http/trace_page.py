#!/usr/bin/python3
"""The signal trace panel of the live page as a technician uses it (docs/trace.md "Page", issue 32
scopes 2 and 4), in headless Chromium with real mouse and keyboard events (python3-selenium +
chromedriver, scripts/setup-test.sh), on examples/coolant_lube.stl served at 10 ms a tick with
examples/coolant_lube.params (lube pulse 100 ms, pause 250 ms).

The coolant key X483.5 starts a sequence (the example's rungs): each rising edge toggles the
request R10.0 (ALT); the pump Y0.3 follows the request on and runs on for 500 ms after it ends
(STMR 2 0 500, docs/dialect-notes.md "Timers": T2 counts the run-on in ms, the output drops at
the first tick with elapsed >= 500, i.e. 50 ticks of 10 ms after the request fell; the tank level
X10.0 is never set). Meanwhile PLC2's lube oscillator pulses R20.0 (= the pump Y0.4), and as the
pressure switch X10.2 is never closed, each pulse's end (R20.0 falling) raises the alarm and
counts one failure in D12 at that same tick.

The test opens the page with its token, opens 信号跟踪, types the definition into the panel (five
bits, the timer T2 and the word D12, a rising trigger on X483.5, pre 20, post 200, single), arms
it with the button, then presses the key with `ladderjit monitor write` (on, off, on again, off).
When the capture is plotted, it checks the plotted samples (read from the dygraph objects, the
bits back from their lanes) row by row against what the program makes of the key presses as
recorded: R10.0, Y0.3, T2, Y0.4 = R20.0, D12; the last row against `ladderjit monitor read`
once the sequence is over; the trigger tick drawn in the trigger's red at its x; two clicks on the
plot set cursors A and B and the panel shows B - A in ticks and in ms (ticks x 10); the values
at cursor A; a click on R10.0's name marks its first contact in the ladder (PLC1 rung 2, `LD
R10.0 / STMR ...`) with its three uses in the cross-reference. Screenshots go to OUTDIR; its trace-panel.png (the page
at the end) is docs/images/trace-panel.png. Bounded: every wait has a deadline.

Usage: trace_page.py LADDERJIT EXAMPLES OUTDIR"""
import os, re, shutil, sys, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import httputil  # noqa: E402
import serveutil  # noqa: E402
from httputil import check  # noqa: E402

from selenium.webdriver.common.action_chains import ActionChains  # noqa: E402
from selenium.webdriver.common.by import By  # noqa: E402

exe, examples, out = sys.argv[1], sys.argv[2], sys.argv[3]
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)

PERIOD_MS = 10
SIGNALS = ["X483.5", "R10.0", "Y0.3", "Y0.4", "R20.0", "T2", "D12"]
PRE, POST = 20, 200
RUN_ON_TICKS = 500 // PERIOD_MS  # STMR 2 0 500 at 10 ms a tick


def chrome():
    return httputil.chrome(1700, "ljtrace")


wait = httputil.wait


def expected(ticks, key):
    """R10.0, Y0.3, T2 per row from the key's column (the program's rungs, see the docstring)."""
    req, y03, t2 = [], [], []
    r = 0          # R10.0 before the first press: never pressed since power-up
    fell = None    # the tick R10.0 fell (STMR's start), None while it is on or never was
    out = 0        # STMR's output
    for i, t in enumerate(ticks):
        if key[i] == 1 and (i == 0 or key[i - 1] == 0) and i > 0:
            r = 1 - r  # ALT on the rising edge
        if r:
            out, tv, fell = 1, 0, None
        elif out:
            if fell is None:
                fell = t
            tv = (t - fell) * PERIOD_MS
            if tv >= 500:
                out, tv = 0, 500
        else:
            tv = t2[-1] if t2 else 0  # input off and output off: nothing changes
        req.append(r)
        y03.append(out)
        t2.append(tv)
    return req, y03, t2


def main():
    program = os.path.join(examples, "coolant_lube.stl")
    params = os.path.join(examples, "coolant_lube.params")
    srv = httputil.Serve(exe, program, out, "serve",
                         extra=["--engine", "interp", "--period-ms", str(PERIOD_MS), "--params", params],
                         duration=150)
    drv = chrome()
    shot = [0]

    def js(script, *args):
        return drv.execute_script(script, *args)

    def screenshot(what):
        shot[0] += 1
        path = os.path.join(out, "trace_%d_%s.png" % (shot[0], what))
        drv.save_screenshot(path)
        print("     screenshot " + path)
        return path

    def mon(*args):
        rc, o, e = serveutil.monitor(exe, srv.sock, *args)
        check(rc == 0, "monitor %s: %s" % (" ".join(args), (o + e).strip()[:200]))
        return o

    try:
        drv.get(srv.url + "/?token=" + srv.token)
        check(wait("the live page", lambda: js("return document.getElementById('conn').textContent") == "live") is not None,
              "the live page is live")
        btn = drv.find_element(By.ID, "trbtn")
        check("信号跟踪" in btn.text, "the bar has the 信号跟踪 trace button: %r" % btn.text)
        ActionChains(drv).move_to_element(btn).click().perform()
        check(wait("dygraphs", lambda: js("return !!window.Dygraph")) is not None,
              "dygraphs loaded from serve (/dygraph.min.js)")
        # The definition, typed.
        drv.find_element(By.ID, "trsig").send_keys(", ".join(SIGNALS))
        drv.find_element(By.ID, "trkind").send_keys("rising")
        drv.find_element(By.ID, "traddr").send_keys("X483.5")
        for fid, v in (("trpre", PRE), ("trpost", POST)):
            f = drv.find_element(By.ID, fid)
            f.clear()
            f.send_keys(str(v))
        screenshot("form")
        ActionChains(drv).move_to_element(drv.find_element(By.ID, "trarm")).click().perform()
        armed = wait("armed", lambda: "waiting (armed)" in js("return document.getElementById('trstate').textContent"))
        check(armed is not None, "arm: the panel says waiting (armed): %r" %
              js("return document.getElementById('trstate').textContent + ' / ' + document.getElementById('trmsg').textContent"))
        st = mon("trace", "status")
        check('"rising X483.5"' in st.replace("trigger rising", '"rising') or "trigger rising X483.5" in st,
              "monitor trace status shows the page's definition: %s" % st[:300])
        # The ring fills (pre 20 ticks = 200 ms), then the key: on, off, on (request off: run-on),
        # off.
        time.sleep(0.6)
        for v, pause in ((1, 0.25), (0, 0.35), (1, 0.12), (0, 0)):
            mon("write", "X483.5=%d" % v)
            time.sleep(pause)
        cap = wait("the capture", lambda: js("var T=window.ladder.trace;return T.cap&&T.graphs.length===3?T.cap.rows:0"), 40)
        check(cap == PRE + 1 + POST, "capture of pre + 1 + post = %d rows plotted: %s" % (PRE + 1 + POST, cap))
        # Once the sequence is over (the run-on ended), the values stay: the last row is now.
        time.sleep(0.3)
        now = {a: serveutil.read(exe, srv.sock, a) for a in SIGNALS}
        # The plotted samples: the waveform plot's bits back from their lanes (1.5 apart, the
        # first on top), each word's plot's values.
        data = js("""
            var T=window.ladder.trace,c=T.cap,gb=T.graphs[0],n=gb.numRows(),bits=[],words=[],wl=['tick'];
            var lb=gb.getLabels(),nb=lb.length-1;
            for(var r=0;r<n;r++){var row=[gb.getValue(r,0)];
              for(var i=1;i<=nb;i++)row.push(Math.round(gb.getValue(r,i)-(nb-i)*1.5));bits.push(row);}
            T.graphs.slice(1).forEach(function(gw,j){wl.push(gw.getLabels()[1]);
              for(var r2=0;r2<gw.numRows();r2++){if(!j)words.push([gw.getValue(r2,0)]);
                if(words[r2][0]!==gw.getValue(r2,0))words[r2].push(null);else words[r2].push(gw.getValue(r2,1));}});
            return {bl:lb,wl:wl,bits:bits,words:words,trig:c.triggerTick,trow:c.triggerRow,period:c.periodMs};""")
        check(data["bl"] == ["tick"] + SIGNALS[:5] and data["wl"] == ["tick"] + SIGNALS[5:],
              "bits on the waveform plot, T2 and D12 on a plot each: %s %s" % (data["bl"], data["wl"]))
        check(data["period"] == PERIOD_MS, "period %s ms" % data["period"])
        rows = len(data["bits"])
        check(rows == PRE + 1 + POST and len(data["words"]) == rows, "plotted rows %d / %d" % (rows, len(data["words"])))
        ticks = [r[0] for r in data["bits"]]
        col = {name: [r[1 + i] for r in data["bits"]] for i, name in enumerate(SIGNALS[:5])}
        col.update({name: [r[1 + i] for r in data["words"]] for i, name in enumerate(SIGNALS[5:])})
        check(ticks == [r[0] for r in data["words"]], "one time axis: both plots have the same ticks")
        check(all(b > a for a, b in zip(ticks, ticks[1:])), "ticks increase")
        key = col["X483.5"]
        rises = [i for i in range(1, rows) if key[i] == 1 and key[i - 1] == 0]
        check(len(rises) == 2 and rises[0] == PRE, "two presses, the first at the trigger row %d: %s" % (PRE, rises))
        check(ticks[PRE] == data["trig"] and data["trow"] == PRE, "the trigger tick %s is row %d's (%s)" % (data["trig"], PRE, ticks[PRE]))
        check(all(v == 0 for v in key[:PRE]), "the key is off before the trigger")
        req, y03, t2 = expected(ticks, key)
        for name, want in (("R10.0", req), ("Y0.3", y03), ("T2", t2)):
            bad = [(ticks[i], col[name][i], want[i]) for i in range(rows) if col[name][i] != want[i]]
            check(not bad, "%s plotted as the program makes it from the key on all %d rows%s" %
                  (name, rows, "" if not bad else ": (tick, plotted, expected) " + str(bad[:5])))
        fall = [ticks[i] for i in range(1, rows) if req[i - 1] == 1 and req[i] == 0]
        drop = [ticks[i] for i in range(1, rows) if col["Y0.3"][i - 1] == 1 and col["Y0.3"][i] == 0]
        check(len(fall) == 1 and len(drop) == 1 and drop[0] - fall[0] >= RUN_ON_TICKS and
              drop[0] - fall[0] <= RUN_ON_TICKS + 5,
              "the pump runs on 500 ms = %d ticks after the request fell: fell %s, pump off %s" % (RUN_ON_TICKS, fall, drop))
        check(col["Y0.4"] == col["R20.0"], "the lube pump Y0.4 follows R20.0 on every row")
        lube_ends = [i for i in range(1, rows) if col["R20.0"][i - 1] == 1 and col["R20.0"][i] == 0]
        d12 = col["D12"]
        steps = [i for i in range(1, rows) if d12[i] != d12[i - 1]]
        check(steps == lube_ends and all(d12[i] == d12[i - 1] + 1 for i in steps) and len(steps) >= 3,
              "D12 counts one failure at each pulse's end (no pressure): steps at rows %s, pulse ends %s" % (steps, lube_ends))
        last = {name: col[name][-1] for name in SIGNALS}
        for name in ("X483.5", "R10.0", "Y0.3", "T2"):
            check(now[name] == last[name], "%s: monitor read %s = the last plotted row %s" % (name, now[name], last[name]))
        check(last["R10.0"] == 0 and last["Y0.3"] == 0 and last["T2"] == 500, "sequence over: request and pump off, T2 = 500 ms")
        check(now["D12"] is not None and now["D12"] >= last["D12"], "D12 read %s >= last row %s" % (now["D12"], last["D12"]))
        screenshot("capture")
        # Download: the panel's VCD, VCD with bit wires and CSV links give the files
        # `monitor trace save` writes of the same capture, byte for byte.
        got = drv.execute_async_script("""var done=arguments[arguments.length-1];
            Promise.all(['trvcd','trvcdb','trcsv'].map(function(i){var a=document.getElementById(i);
              return fetch(a.href).then(function(r){return r.text().then(function(t){
                return [a.hasAttribute('download')&&!a.closest('[hidden]'),r.status,r.headers.get('Content-Disposition')||'',t]})})}))
            .then(done,function(e){done(String(e))})""")
        for (name, opts), g in zip((("vcd", ["--vcd"]), ("vcd-bits", ["--vcd", "--bits"]), ("csv", ["--csv"])), got):
            path = os.path.join(out, "saved." + name)
            mon("trace", "save", path, *opts)
            with open(path) as f:
                want = f.read()
            check(g[0] and g[1] == 200 and "attachment" in g[2] and g[3] == want,
                  "the panel's %s download equals monitor trace save %s (%d bytes, %s)"
                  % (name, " ".join(opts), len(want), g[2]))
        # The trigger mark: the trigger's red down T2's plot (where no waveform edge covers it)
        # at the trigger tick's x, none 25 px off.
        red = js("""
            var g=window.ladder.trace.graphs[1],a=g.getArea(),x=Math.round(g.toDomXCoord(arguments[0]));
            var cv=g.hidden_,ctx=cv.getContext('2d'),k=cv.width/cv.offsetWidth;
            function count(px){var n=0;for(var y=a.y+14;y<a.y+a.h;y++){
              var p=ctx.getImageData(Math.round(px*k),Math.round(y*k),1,1).data;
              if(p[0]>180&&p[1]<60&&p[2]<60)n++;}return n;}
            return [Math.max(count(x-1),count(x)),count(x+25),a.h-14];""", data["trig"])
        check(red[0] >= red[2] * 0.5 and red[1] == 0, "the trigger tick is marked in red (%d of %d pixels at its x, %d 25 px away)" % (red[0], red[2], red[1]))
        # Cursors: two clicks on the waveform plot.
        canvas = drv.find_element(By.CSS_SELECTOR, "#trbits canvas:last-of-type")
        ta, tb = data["trig"] + 10, data["trig"] + 60

        def click_at(t):
            x, left, w = js("""var g=window.ladder.trace.graphs[0],r=arguments[1].getBoundingClientRect();
                               return [g.toDomXCoord(arguments[0]),0,r.width];""", t, canvas)
            ActionChains(drv).move_to_element_with_offset(canvas, int(round(x - w / 2)), 0).click().perform()
        click_at(ta)
        time.sleep(0.3)
        click_at(tb)
        a, b = wait("two cursors", lambda: js("var T=window.ladder.trace;return T.a!==null&&T.b!==null?[T.a,T.b]:null")) or (None, None)
        check(a is not None and abs(a - ta) <= 2 and abs(b - tb) <= 2, "clicks set cursor A near tick %d and B near %d: %s %s" % (ta, tb, a, b))
        delta = js("var e=document.getElementById('trdelta');return e?e.textContent:''")
        if a is not None:
            want = "%d ticks = %d ms" % (b - a, (b - a) * PERIOD_MS)
            check(delta == want, "B - A shown as %r: %r" % (want, delta))
            vals = js("""return Array.prototype.map.call(document.querySelectorAll('#trvals tr'),function(r){
                         return Array.prototype.map.call(r.cells,function(c){return c.textContent})})""")
            rowa = max(i for i in range(rows) if ticks[i] <= a)
            for name in ("R10.0", "Y0.3", "T2"):
                line = [v for v in vals if v[0].startswith(name)]
                w = {"R10.0": req, "Y0.3": y03, "T2": t2}[name][rowa]
                check(line and line[0][1] == str(w), "the value of %s at cursor A is %s: %s" % (name, w, line))
        drv.find_element(By.ID, "trace").screenshot(os.path.join(out, "trace-panel-only.png"))
        screenshot("cursors")
        # A click on the name R10.0 beside its lane: its first contact in the ladder.
        link = drv.find_element(By.CSS_SELECTOR, '#trbits a.trname[data-sig="R10.0"]')
        ActionChains(drv).move_to_element(link).click().perform()
        hit = wait("the contact marked", lambda: js("""var g=document.querySelector('g.hit');if(!g)return null;
              var r=g.closest('g.rung');return [g.getAttribute('class'),g.textContent,r?r.dataset.part:'',r?r.dataset.rung:'',
              document.getElementById('xref').textContent]"""))
        check(hit is not None and "contact" in hit[0] and "R10.0" in hit[1] and hit[3] == "2",
              "R10.0's name marks its first contact, PLC1 rung 2: %s" % (hit,))
        check(hit is not None and re.search(r"R10\.0 (= \d+)?: 3 use\(s\)", hit[4]) is not None,
              "the cross-reference lists its 3 uses: %s" % (hit and hit[4][:120]))
        # The page with the panel beside the ladder, the contact marked: docs/images/trace-panel.png.
        drv.save_screenshot(os.path.join(out, "trace-panel.png"))
        screenshot("find")
        # The log names the page's trace commands.
        log = srv.log().decode(errors="replace")
        check("POST /api/trace {\"action\":\"arm\"}" in log and "POST /api/trace {\"action\":\"define\"" in log,
              "serve's log has the page's define and arm")
    finally:
        drv.quit()
        srv.stop()
    httputil.finish()


main()
