#!/usr/bin/env python3
"""HAL component tests of a FANUC program (docs/linuxcnc.md), each under a bounded `halrun`:

  sysbits  refresh writes the profile's system bits before every tick, as `run` and `serve` do
           (fanuc-pmc.md section 2: R9091.0 OFF = 0, R9091.1 ON = 1, R9015.0 first scan,
           R9091.6 a 1 s clock, 500 ms on then 500 ms off from now_ms = 0). In a 4 ms thread
           the clock bit sampled with the tick count around it must be the one tick n gives at
           now_ms = 4 n; ON, OFF and a SET from the first-scan bit are checked as levels.
  timer    timers follow the thread period: TMRB 1 400 (a 400 ms on-delay, fanuc-pmc.md TMRB)
           turns Y0.0 on 400 ms of *thread time* after X0.0, that is 100 ticks of a 4 ms thread
           and 400 ticks of a 1 ms thread (now_ms = ticks x period, docs/linuxcnc.md).

  reload   online change: A runs (Y0.0 follows X0.0, X0.1 SETs K0.1 shown on Y0.1); B is
           compiled over it and `ladderjit.reload` rises: B (Y0.0 = NOT X0.0) is swapped in
           at a thread boundary with the state kept (Y0.1 still shows K0.1 = 1), `reloads` = 1;
           then C, which needs another pin (X0.2), is refused: B keeps running,
           `reload-failures` = 1 and the RTAPI log says why.

Usage: hal_profile_test.py MODE LADDERJIT MODULE REPO"""
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from halrig import Rig, RigError, gets_values  # noqa: E402

SYSBITS = """; tests/hal/hal_profile_test.py sysbits
RD R9091.1
WRT Y0.0            ; ON
RD R9091.0
WRT Y0.1            ; OFF
RD R9015.0
SET Y0.2            ; latched on the first scan
RD R9091.6
WRT Y0.3            ; the 1 s clock
END1
END2
END
"""
TIMER = """; tests/hal/hal_profile_test.py timer
RD X0.0
TMRB 1 400
WRT Y0.0
END1
END2
END
"""


RELOAD_A = """; tests/hal/hal_profile_test.py reload: A
RD X0.0
WRT Y0.0
RD X0.1
SET K0.1
RD K0.1
WRT Y0.1
END1
END2
END
"""
RELOAD_B = """; tests/hal/hal_profile_test.py reload: B (the same pins)
RD.NOT X0.0
WRT Y0.0
RD X0.1
AND.NOT X0.1
WRT R0.0
RD K0.1
WRT Y0.1
END1
END2
END
"""
RELOAD_C = """; tests/hal/hal_profile_test.py reload: C (one more input pin)
RD X0.2
WRT Y0.0
RD X0.1
WRT R0.0
RD K0.1
WRT Y0.1
END1
END2
END
"""


def test_reload(rig):
    first = load(rig, "p", RELOAD_A)
    for name, text in (("b", RELOAD_B), ("c", RELOAD_C)):
        rig.write(name + ".pmc", text)

    def recompile(name):
        # halcmd has no quoting for `loadusr sh -c`: the steps go into a script file.
        script = rig.write(f"compile-{name}.sh", "set -e\n"
                           f"cp {rig.path(name + '.pmc')} {rig.path('p.pmc')}\n"
                           f"{os.path.abspath(rig.ladderjit)} compile {rig.path('p.pmc')} "
                           f"-o {rig.path('p.so')}\n"
                           f"chmod 644 {rig.path('p.so')} {rig.path('p.pmc')}\n")
        return f"loadusr -w sh {script}"

    lines = [first, "loadrt threads name1=plc period1=1000000", "addf ladderjit.refresh plc",
             "net x0 ladderjit.x0.0", "net x1 ladderjit.x0.1", "net rl ladderjit.reload",
             "start", "sets x0 1", "sets x1 1", "loadusr -w sleep 0.2", "sets x1 0",
             "loadusr -w sleep 0.1",
             "getp ladderjit.y0.0", "getp ladderjit.y0.1",      # A: TRUE TRUE
             recompile("b"), "sets rl 1", "loadusr -w sleep 3", "sets rl 0",
             "getp ladderjit.reloads", "getp ladderjit.y0.0", "getp ladderjit.y0.1",  # 1 F T
             recompile("c"), "sets rl 1", "loadusr -w sleep 3", "sets rl 0",
             "getp ladderjit.reloads", "getp ladderjit.reload-failures",
             "getp ladderjit.y0.0", "stop"]                      # 1 1 FALSE
    r = rig.halfile("reload.hal", "\n".join(lines) + "\n", timeout=180, check=False)
    vals = gets_values(r.stdout)
    want = ["TRUE", "TRUE", "1", "FALSE", "TRUE", "1", "1", "FALSE"]
    what = ["A: Y0.0 follows X0.0", "A: K0.1 set, on Y0.1", "reloads after B",
            "B: Y0.0 = NOT X0.0", "B: K0.1 kept across the change", "reloads after C",
            "reload-failures after C", "B still runs after C was refused"]
    got = [str(int(v, 0)) if v.startswith("0x") else v for v in vals]
    fails = 0
    for i, (w, name) in enumerate(zip(want, what)):
        g = got[i] if i < len(got) else None
        fails += g != w
        print(f"reload: {name}: {g} ({'ok' if g == w else 'expected ' + w})")
    out = r.stdout + r.stderr
    if "online change refused" not in out or "other pins" not in out:
        fails += 1
        print("reload: the refusal of C is not in the RTAPI log:\n" + out[-3000:])
    if len(got) != len(want) or r.returncode != 0:
        fails += 1
        print(f"reload: halrun rc {r.returncode}, values {got}\n{out[-3000:]}")
    return 1 if fails else 0


def load(rig, name, text):
    src = rig.write(name + ".pmc", text)
    so = rig.compile(src, rig.path(name + ".so"))
    return f"loadrt ladderjit program={so} trust={rig.trust_key()}"


def test_sysbits(rig):
    period_ns = 4000000
    samples = 60
    lines = [load(rig, "sysbits", SYSBITS), f"loadrt threads name1=plc period1={period_ns}",
             "addf ladderjit.refresh plc", "start", "loadusr -w sleep 0.1",
             "getp ladderjit.y0.0", "getp ladderjit.y0.1", "getp ladderjit.y0.2"]
    for _ in range(samples):
        lines += ["getp ladderjit.ticks", "getp ladderjit.y0.3", "getp ladderjit.ticks",
                  "loadusr -w sleep 0.05"]
    lines.append("stop")
    r = rig.halfile("sysbits.hal", "\n".join(lines) + "\n", timeout=120 + samples)
    vals = gets_values(r.stdout)
    if len(vals) != 3 + 3 * samples:
        raise RigError(f"expected {3 + 3 * samples} values, got {len(vals)}:\n{r.stdout}{r.stderr}")
    fails = 0
    for name, got, want in (("Y0.0 = R9091.1 (ON)", vals[0], "TRUE"),
                            ("Y0.1 = R9091.0 (OFF)", vals[1], "FALSE"),
                            ("Y0.2 SET by R9015.0 (first scan)", vals[2], "TRUE")):
        ok = got == want
        fails += not ok
        print(f"sysbits: {name}: {got} ({'ok' if ok else 'expected ' + want})")
    decisive = wrong = 0
    seen = set()
    for i in range(samples):
        a, y, b = int(vals[3 + 3 * i], 0), vals[4 + 3 * i], int(vals[5 + 3 * i], 0)
        # The value read came from one of the ticks a-1 .. b-1 (the pin counts ticks run);
        # tick n ran at now_ms = 4 n: the clock is 1 while (now_ms / 500) is even.
        expect = {((n * period_ns // 1000000) // 500) % 2 == 0 for n in range(max(a - 1, 0), b)}
        if a == 0 or len(expect) != 1:
            continue
        decisive += 1
        seen.add(y)
        if (y == "TRUE") != expect.pop():
            wrong += 1
            print(f"sysbits: clock sample {i}: ticks {a}..{b}, Y0.3 {y}: wrong")
    print(f"sysbits: R9091.6 clock: {decisive} decisive samples, {wrong} wrong, values {sorted(seen)}")
    if wrong or decisive < samples // 2 or len(seen) != 2:
        fails += 1
    return 1 if fails else 0


def timer_ticks(rig, period_ns):
    """Ticks from the X0.0 edge to Y0.0 on: (low, high) bounds from the sampled tick counts."""
    polls = 160
    lines = [load(rig, "timer", TIMER), f"loadrt threads name1=plc period1={period_ns}",
             "addf ladderjit.refresh plc", "net start ladderjit.x0.0", "start",
             "loadusr -w sleep 0.1", "getp ladderjit.ticks", "sets start 1",
             "getp ladderjit.ticks"]
    # poll until well past 400 ms of thread time (slow enough for a 1 ms thread under load)
    for _ in range(polls):
        lines += ["getp ladderjit.ticks", "getp ladderjit.y0.0", "getp ladderjit.ticks",
                  "loadusr -w sleep 0.01"]
    lines.append("stop")
    r = rig.halfile(f"timer{period_ns}.hal", "\n".join(lines) + "\n", timeout=120 + polls)
    vals = gets_values(r.stdout)
    if len(vals) != 2 + 3 * polls:
        raise RigError(f"expected {2 + 3 * polls} values, got {len(vals)}:\n{r.stdout}{r.stderr}")
    set_lo, set_hi = int(vals[0], 0), int(vals[1], 0)  # the edge came between these counts
    off_last, on_first = None, None
    for i in range(polls):
        a, y, b = int(vals[2 + 3 * i], 0), vals[3 + 3 * i], int(vals[4 + 3 * i], 0)
        if y == "FALSE":
            off_last = a  # at least `a` ticks ran with Y0.0 off
        elif on_first is None:
            on_first = b
    if on_first is None or off_last is None:
        raise RigError(f"period {period_ns}: Y0.0 never turned on (or was on at once)")
    # Y0.0 came on after between (off_last - set_hi) and (on_first - set_lo) ticks.
    return off_last - set_hi, on_first - set_lo


def test_timer(rig):
    fails = 0
    for period_ns in (4000000, 1000000):
        want = 400 * 1000000 // period_ns  # ticks of 400 ms
        lo, hi = timer_ticks(rig, period_ns)
        # 2 ticks of slack for the sampling of the input edge; the bounds must enclose `want`.
        ok = lo - 2 <= want <= hi + 2 and hi - lo < want // 2
        fails += not ok
        print(f"timer: period {period_ns // 1000} us: TMRB 400 ms on after {lo}..{hi} ticks, "
              f"expected {want} ({'ok' if ok else 'WRONG'})")
    return 1 if fails else 0


def main():
    if len(sys.argv) != 5:
        print(__doc__)
        return 2
    mode, ladderjit, module, _repo = sys.argv[1:]
    tests = {"sysbits": test_sysbits, "timer": test_timer, "reload": test_reload}
    try:
        rig = Rig(ladderjit, module)
    except RigError as e:
        print(f"FAIL: {e}")
        return 1
    try:
        return tests[mode](rig)
    except RigError as e:
        print(f"FAIL: {e}")
        return 1
    finally:
        rig.halrun(["-U"], timeout=30, check=False)
        rig.cleanup()


if __name__ == "__main__":
    sys.exit(main())
