#!/usr/bin/python3
"""Stable diagnostic codes (docs/diagnostics.md): every error and warning reported in verify/ and
frontends/iec/ passes a code `"LJnnnn"` right after its location, no code is used twice, and the
table of docs/diagnostics.md lists exactly the codes the sources use, each once.
Usage: diagnostic_codes.py SOURCE_DIR. Exit status 0 = pass."""
import os
import re
import sys

ROOT = sys.argv[1]
DIRS = ["verify", "frontends/iec"]
# A report: name.error( / name.warning( / error( / warning( as a call (not a declaration).
CALL = re.compile(r"(?<![\w:])(?:[A-Za-z_]\w*(?:\.|->))?(error|warning)\(")
DECL = re.compile(r"\b(void|bool|Status|static)\s*$")
FAILURES = []


def check(cond, what):
    print(("ok:   " if cond else "FAIL: ") + what, flush=True)
    if not cond:
        FAILURES.append(what)
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


used = {}
uncoded = []
for d in DIRS:
    for dirpath, _, names in os.walk(os.path.join(ROOT, d)):
        for name in sorted(names):
            if not name.endswith((".cpp", ".h")):
                continue
            path = os.path.join(dirpath, name)
            rel = os.path.relpath(path, ROOT)
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

check(not uncoded, "every error/warning in %s carries a code%s" %
      (", ".join(DIRS), (": missing at " + ", ".join(uncoded)) if uncoded else ""))
check(len(used) >= 100, "the sources use %d codes" % len(used))
twice = {c: s for c, s in used.items() if len(s) > 1}
check(not twice, "no code is used twice%s" % (": " + str(twice) if twice else ""))

doc = open(os.path.join(ROOT, "docs", "diagnostics.md"), encoding="utf-8").read()
rows = re.findall(r"^\| (LJ\d{4}) \| (error|warning) \|", doc, flags=re.M)
listed = [c for c, _ in rows]
check(len(listed) == len(set(listed)), "docs/diagnostics.md lists each code once")
missing = sorted(set(used) - set(listed))
extra = sorted(set(listed) - set(used))
check(not missing, "docs/diagnostics.md lists every code the sources use%s" %
      (": missing " + ", ".join(missing) if missing else ""))
check(not extra, "docs/diagnostics.md lists no code the sources do not use%s" %
      (": " + ", ".join(extra) if extra else ""))
sys.exit(1 if FAILURES else 0)
