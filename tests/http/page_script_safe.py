#!/usr/bin/python3
"""Issue 28 finding 6: program data embedded in the ladder page can never end or open a script
element. For each dialect (STL, FANUC PMC, IL) a program whose comments, symbol comments and file
name hold "<!--<script>", "</script>", "<script" and U+2028 / U+2029: the static page
(`ladder --format html`) holds no "<!--" and no more "<script" / "</script" than the page of the
same program without them, and runs its scripts in headless Chromium (window.ladder, with the
hostile text read back intact); the live page of `serve --http` runs and receives live values.
Usage: page_script_safe.py LADDERJIT EXAMPLES OUTDIR"""
import json, os, re, shutil, subprocess, sys, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liveutil  # noqa: E402

exe, examples, out = sys.argv[1], sys.argv[2], sys.argv[3]
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)
check = liveutil.check
EVIL = "<!--<script> \u2028 \u2029"  # unclosed: the HTML parser's double-escaped script state
EVIL2 = "</script> <script>"
here = os.path.dirname(os.path.abspath(__file__))


def stl(text):
    return "; " + EVIL2 + "\n" + text.replace("OUT Y0.0", "OUT Y0.0 ; " + EVIL, 1)


def pmc(text):
    text = text.replace("COOL_KEY,X0000.1,COOLANT KEY,", "COOL_KEY,X0000.1," + EVIL + "," + EVIL2, 1)
    return text.replace("RD.NOT ESP_OK", "; " + EVIL + "\nRD.NOT ESP_OK", 1)


def il(text):
    return text.replace("000 LD %S1", "(* " + EVIL + " *)\n000 LD %S1", 1).replace(
        "002 LD %I0.0", "(* " + EVIL2 + " *)\n002 LD %I0.0", 1)


cases = [("stl", os.path.join(here, "live.stl"), stl), ("pmc", os.path.join(examples, "fanuc_coolant.pmc"), pmc),
         ("il", os.path.join(examples, "conveyor.il"), il)]
driver = liveutil.chrome()
driver.set_script_timeout(10)
try:
    for ext, src, evil in cases:
        text = open(src, encoding="utf-8").read()
        plain = os.path.join(out, "plain." + ext)
        bad = os.path.join(out, "evil<!--<script>\u2028." + ext)
        open(plain, "w", encoding="utf-8").write(text)
        open(bad, "w", encoding="utf-8").write(evil(text))
        pages = {}
        for name, prog in (("plain", plain), ("evil", bad)):
            html = os.path.join(out, "%s-%s.html" % (name, ext))
            r = subprocess.run([exe, "ladder", prog, "--format", "html", "-o", html], capture_output=True,
                               text=True, timeout=60)
            check(r.returncode == 0, "%s: ladder --format html of the %s program: %s" % (ext, name, r.stderr.strip()[:200]))
            pages[name] = open(html, encoding="utf-8").read() if r.returncode == 0 else ""
        p, e = pages["plain"], pages["evil"]
        check(EVIL.split()[0] not in p, "%s: the plain page has no '<!--'" % ext)
        check("<!--" not in e, "%s: no '<!--' in the page of the hostile program" % ext)
        for tag in ("<script", "</script"):
            check(e.count(tag) == p.count(tag), "%s: '%s' %d times, as in the plain page (%d)" %
                  (ext, tag, e.count(tag), p.count(tag)))
        check("\u2028" not in e and "\u2029" not in e, "%s: no raw U+2028 / U+2029 in the page" % ext)
        # The static page runs its scripts, and the hostile text is data, read back intact.
        driver.get("file://" + os.path.join(out, "evil-%s.html" % ext))
        got = driver.execute_script("return window.ladder?JSON.stringify(window.ladder.layout):null")
        check(got is not None and "<!--<script>" in got and ("</script>" in got or ext == "pmc"),
              "%s: the static page's script ran and holds the comment text" % ext)
        # The live page of serve --http: runs and receives live values.
        sock = os.path.join(out, "serve-%s.sock" % ext)
        serve, url, token, _ = liveutil.start_serve(exe, bad, sock, os.path.join(out, "serve-%s.err" % ext), 60,
                                                   modbus=False)
        try:
            driver.get(url + "?token=" + token)
            t0, live = time.time(), None
            while time.time() - t0 < 15 and not live:
                live = driver.execute_script(
                    "return window.ladder&&window.ladder.live&&window.ladder.live.last?"
                    "window.ladder.live.last.tick:null")
                time.sleep(0.1)
            check(live is not None, "%s: the live page's scripts run and receive live values (tick %s)" % (ext, live))
            if ext == "stl":
                driver.save_screenshot(os.path.join(out, "live-stl.png"))
        finally:
            serve.terminate()
            try:
                serve.wait(timeout=15)
            except subprocess.TimeoutExpired:
                serve.kill()
finally:
    driver.quit()
print("%d failed" % len(liveutil.failures))
sys.exit(1 if liveutil.failures else 0)
