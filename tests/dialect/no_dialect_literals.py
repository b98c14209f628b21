#!/usr/bin/env python3
"""Fails when a core library source names an HNC-8 mnemonic or area letter as a code literal.

Only the HNC-8 front end (frontends/hnc8/) and the HNC-8 profile (profiles/hnc8/) may spell the
dialect; the core (ir/, verify/, interp/, lowering/, jit/) work on semantic operations and area
roles. The generators (bench/Random*) write HNC-8 STL text and are not scanned. Comments are stripped first; then
flagged are: an identifier equal to a mnemonic (`Op::LDP`, a macro argument `LDP`), a mnemonic as
a whole word inside a string literal (`"LDP"`, `"LDP needs..."`), an area letter as a char literal
(`'X'`) or as a whole string literal (`"X"`), and `Area::X`-style enumerators.

Usage: no_dialect_literals.py ROOT [DIR...]   (default DIRs: the core; exit 1 on any finding)
"""
import os
import re
import sys

AREA_LETTERS = set("XYFGRWDBPTCLS")
CORE_DIRS = ["ir", "verify", "interp", "ladder", "lowering", "jit"]
# The program generators (bench/Random*, gen/ once moved) write HNC-8 STL text for the fuzzer
# and the benchmarks, so they spell the dialect like a front end would; gen/ is scanned only for
# files that are not STL writers.
CORE_FILES = []


# Files that mirror the process image of runtime_abi/include/ladderjit/abi.h, whose field names
# (lj_image.X, lj_state.T) are the ABI's and stay as they are.
ABI_MIRRORS = {"lowering/AbiTypes.cpp", "lowering/AbiTypes.h"}
# The ladder view's drawn names: the forms a drawing needs that the front ends' spelling tables do
# not give (MOVW from the operand width, NOT vs EOR); it spells FANUC and IEC on purpose
# (docs/ladder-view.md "Dialects") until those forms move into each front end's DialectText.
DIALECT_SPELLERS = {"ladder/Spelling.cpp"}
# A line ending in this comment holds text that is rendered verbatim into the HNC-8 docs.
ALLOW = "// dialect-ok"


def mnemonics():
    names = {"WRT", "END1", "END2"}
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, "..", "catalogue", "manual-mnemonics.txt"), encoding="utf-8") as f:
        for line in f:
            line = line.strip()
            if line and not line.startswith("#"):
                names.add(line.split()[0].upper())
    return names


TOKEN = re.compile(r'''
    (?P<lcomment>//[^\n]*)
  | (?P<bcomment>/\*.*?\*/)
  | (?P<raw>R"(?P<delim>[^(\s]*)\(.*?\)(?P=delim)")
  | (?P<string>"(?:\\.|[^"\\\n])*")
  | (?P<char>'(?:\\.|[^'\\\n])+')
  | (?P<ident>[A-Za-z_][A-Za-z0-9_]*)
  | (?P<scope>::)
  | (?P<other>.)
''', re.S | re.X)


def scan(path, text, names):
    allowed = {i + 1 for i, l in enumerate(text.split("\n")) if l.rstrip().endswith(ALLOW)}
    findings = []
    prev = []  # the last two significant tokens (kind, text)
    for m in TOKEN.finditer(text):
        kind = m.lastgroup
        if kind in ("lcomment", "bcomment") or (kind == "other" and m.group().isspace()):
            continue
        if kind == "delim":
            kind = "raw"
        tok = m.group()
        line = text.count("\n", 0, m.start()) + 1
        where = f"{path}:{line}"
        if line in allowed:
            continue
        if kind == "ident":
            if tok in names:
                findings.append(f"{where}: mnemonic identifier {tok}")
            elif tok in AREA_LETTERS and len(prev) == 2 and prev[-1][1] == "::" and \
                    prev[-2][1] == "Area":
                findings.append(f"{where}: area enumerator Area::{tok}")
        elif kind in ("string", "raw"):
            body = tok[1:-1] if kind == "string" else tok
            if body in AREA_LETTERS:
                findings.append(f"{where}: area letter string {tok}")
            for w in re.findall(r"\b[A-Z0-9]+\b", body):
                if w in names:
                    findings.append(f"{where}: mnemonic {w} in string {tok[:40]}")
        elif kind == "char":
            if tok[1:-1] in AREA_LETTERS:
                findings.append(f"{where}: area letter char {tok}")
        prev = (prev + [(kind, tok)])[-2:]
    return findings


def main():
    root = sys.argv[1]
    dirs = sys.argv[2:] or CORE_DIRS
    names = mnemonics()
    files = [f for f in CORE_FILES if os.path.exists(os.path.join(root, f))] if not sys.argv[2:] else []
    for d in dirs:
        for base, _, entries in os.walk(os.path.join(root, d)):
            for e in sorted(entries):
                if e.endswith((".cpp", ".h", ".c")):
                    files.append(os.path.relpath(os.path.join(base, e), root))
    findings = []
    for rel in sorted(set(files) - ABI_MIRRORS - DIALECT_SPELLERS):
        with open(os.path.join(root, rel), encoding="utf-8") as f:
            findings += scan(rel, f.read(), names)
    for line in findings:
        print(line)
    print(f"no_dialect_literals: {len(files)} files, {len(findings)} findings")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())
