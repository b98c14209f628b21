#!/usr/bin/python3
"""Stable diagnostic codes (docs/diagnostics.md): every error and warning reported in pipeline/,
verify/ and the front ends frontends/{iec,hnc8,fanuc}/ passes a code `"LJnnnn"` right after its location, no
code is used twice, and the table of docs/diagnostics.md lists exactly the codes the sources use,
each once.
Usage: diagnostic_codes.py SOURCE_DIR | --self-test. Exit status 0 = pass. The self-test runs
the checks on small made-up trees and proves each failure (a report without a code, in every
folder of DIRS; a code used twice; a code the table misses or lists too much) is reported."""
import os
import re
import sys

DIRS = ["pipeline", "verify", "frontends/iec", "frontends/hnc8", "frontends/fanuc"]
# A report: name.error( / name.warning( / error( / warning( as a call (not a declaration).
CALL = re.compile(r"(?<![\w:])(?:[A-Za-z_]\w*(?:\.|->))?(error|warning)\(")
DECL = re.compile(r"\b(void|bool|Status|static)\s*$")


def check(failures, cond, what, quiet=False):
    if not quiet:
        print(("ok:   " if cond else "FAIL: ") + what, flush=True)
    if not cond:
        failures.append(what)
    return cond


def first_arg_end(text, i):
    """The index of the top-level ',' or ')' that ends the argument starting at `i`."""
    depth, quote, j = 0, None, i
    while j < len(text):
        c = text[j]
        if quote:
            if c == "\\":
                j += 2
                continue
            if c == quote:
                quote = None
        elif c in "\"'":
            quote = c
        elif c in "([{":
            depth += 1
        elif c in ")]}":
            if depth == 0:
                return j
            depth -= 1
        elif c == "," and depth == 0:
            return j
        j += 1
    return len(text)


def strip_comments(text):
    # Line comments only (the sources use //); strings containing // are kept intact enough for
    # this check because a report's text never starts a line.
    return re.sub(r"^\s*//.*$", "", text, flags=re.M)


def run(root, min_codes=100, quiet=False):
    """The failed checks of the tree at `root` (printed unless `quiet`)."""
    failures = []

    def ok(cond, what):
        return check(failures, cond, what, quiet)

    used = {}
    uncoded = []
    for d in DIRS:
        for dirpath, _, names in os.walk(os.path.join(root, d)):
            for name in sorted(names):
                if not name.endswith((".cpp", ".h")):
                    continue
                path = os.path.join(dirpath, name)
                rel = os.path.relpath(path, root)
                text = strip_comments(open(path, encoding="utf-8").read())
                for m in CALL.finditer(text):
                    line_start = text.rfind("\n", 0, m.start()) + 1
                    if DECL.search(text[line_start:m.start()]):
                        continue
                    end = first_arg_end(text, m.end())
                    if end >= len(text) or text[end] != ",":
                        continue  # error() with one argument: not a diagnostic report
                    rest = text[end + 1:]
                    line = text.count("\n", 0, m.start()) + 1
                    code = re.match(r'\s*"(LJ\d{4})"', rest)
                    if code:
                        used.setdefault(code.group(1), []).append(f"{rel}:{line}")
                    elif not re.match(r"\s*code\s*,", rest):  # the wrappers pass their `code` on
                        uncoded.append(f"{rel}:{line}")

    ok(not uncoded, "every error/warning in %s carries a code%s" %
          (", ".join(DIRS), (": missing at " + ", ".join(uncoded)) if uncoded else ""))
    ok(len(used) >= min_codes, "the sources use %d codes" % len(used))
    twice = {c: s for c, s in used.items() if len(s) > 1}
    ok(not twice, "no code is used twice%s" % (": " + str(twice) if twice else ""))

    doc = open(os.path.join(root, "docs", "diagnostics.md"), encoding="utf-8").read()
    rows = re.findall(r"^\| (LJ\d{4}) \| (error|warning) \|", doc, flags=re.M)
    listed = [c for c, _ in rows]
    ok(len(listed) == len(set(listed)), "docs/diagnostics.md lists each code once")
    missing = sorted(set(used) - set(listed))
    extra = sorted(set(listed) - set(used))
    ok(not missing, "docs/diagnostics.md lists every code the sources use%s" %
          (": missing " + ", ".join(missing) if missing else ""))
    ok(not extra, "docs/diagnostics.md lists no code the sources do not use%s" %
          (": " + ", ".join(extra) if extra else ""))
    return failures


def self_test():
    import tempfile

    def tree(files):
        root = tempfile.mkdtemp(prefix="diagcodes")
        for rel, text in files.items():
            path = os.path.join(root, rel)
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)
        return root

    def doc(*codes):
        return "".join(f"| {c} | error | text | `x.cpp` |\n" for c in codes)

    good = {
        "verify/A.cpp": 'void f() { diags.error(loc, "LJ1001", "a " + x); }\n',
        # A wrapper that passes its code on, and its declaration, are not reports.
        "frontends/hnc8/B.cpp": 'void error(SourceLoc at, const char *code, std::string m) {\n'
                                '  diags_.error(at, code, std::move(m));\n}\n'
                                'void g() { error(t, "LJ3001", "b"); }\n',
        "docs/diagnostics.md": doc("LJ1001", "LJ3001"),
    }
    failures = []
    check(failures, not run(tree(good), 2, True), "self-test: a coded tree passes")
    for d in DIRS:
        bad = dict(good)
        bad[d + "/C.cpp"] = 'void h() {\n  e.error(t.loc,\n          "no code " + x);\n}\n'
        got = run(tree(bad), 2, True)
        check(failures, any("missing at " + d + "/C.cpp:2" in f for f in got),
              "self-test: a report without a code in %s/ is found (%s)" % (d, got))
    twice = dict(good, **{"frontends/fanuc/D.cpp": 'void k() { e.error(at, "LJ1001", "c"); }\n'})
    check(failures, any("used twice" in f for f in run(tree(twice), 2, True)),
          "self-test: a code used twice is found")
    unlisted = dict(good, **{"docs/diagnostics.md": doc("LJ1001")})
    check(failures, any("missing LJ3001" in f for f in run(tree(unlisted), 2, True)),
          "self-test: a code the table does not list is found")
    extra = dict(good, **{"docs/diagnostics.md": doc("LJ1001", "LJ3001", "LJ4001")})
    check(failures, any("do not use: LJ4001" in f for f in run(tree(extra), 2, True)),
          "self-test: a listed code no source uses is found")
    return failures


if __name__ == "__main__":
    if sys.argv[1:] == ["--self-test"]:
        sys.exit(1 if self_test() else 0)
    sys.exit(1 if run(sys.argv[1]) else 0)
