#!/usr/bin/env python3
"""Structure lint (issue 29): the rules that keep the libraries' rooms honest, checked on the
tracked files of the tree (docs/architecture.md "Rules that keep the rooms honest").

1. The IR, the ladder stage and the verifier know no front end: no file under ir/, ladder/ or
   verify/ includes anything under frontends/.
2. The driver, the fuzzer and the benchmarks reach the dialects through the registry
   (pipeline/), never a front end's FrontEnd.h.
3. Dependencies point one way: formats/ (data files) includes no engine, JIT, lowering,
   ladder, runtime or pipeline header; jit/ includes nothing from engines/; ir/ includes only
   ir/ and runtime_abi/.
4. A clone has no ../shared: README.md, docs/ and every shipped source cite the manuals by
   name; only tests/ and bench/ may read real programs from ../shared.
5. Namespaces match folders: no `lj::io` (the old catch-all), no `lj::test` outside tests/.
6. README.md's docs list names every file in docs/ (a reader finds each one from the README).

Usage: structure_lint.py [ROOT]   (exit 0 clean, 1 with one line per violation)
       structure_lint.py --self-test  (builds a tree with one violation of each rule and checks
                                       that every one is reported)
"""
import os
import re
import subprocess
import sys
import tempfile

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^">]+)[">]')
SOURCE_EXT = ('.h', '.hpp', '.c', '.cpp', '.cc', '.inc')
TEXT_EXT = SOURCE_EXT + ('.md', '.py', '.sh', '.txt', '.cmake', '.js', '.json', '.html', '.css')


def tracked_files(root):
    try:
        out = subprocess.run(['git', 'ls-files'], cwd=root, check=True, capture_output=True,
                             text=True).stdout
        return [f for f in out.splitlines() if os.path.isfile(os.path.join(root, f))]
    except (OSError, subprocess.CalledProcessError):
        files = []
        for d, _, names in os.walk(root):
            if '/.git' in d or '/build' in d:
                continue
            files += [os.path.relpath(os.path.join(d, n), root) for n in names]
        return files


def top(path):
    return path.split('/', 1)[0]


def check(root):
    problems = []
    files = sorted(tracked_files(root))
    for f in files:
        if not f.endswith(TEXT_EXT) and os.path.basename(f) not in ('CMakeLists.txt', 'README.md'):
            continue
        try:
            with open(os.path.join(root, f), encoding='utf-8', errors='replace') as fh:
                lines = fh.read().split('\n')
        except OSError as e:
            problems.append(f'{f}: cannot read ({e})')
            continue
        folder = top(f)
        shipped = folder not in ('tests', 'bench') and f != 'tests/lint/structure_lint.py'
        for no, line in enumerate(lines, 1):
            where = f'{f}:{no}'
            if shipped and SHARED.search(line):
                problems.append(f'{where}: cites ../shared (a clone has none; cite the manual by '
                                f'name and section)')
            if folder != 'tests' and re.search(r'\blj::io\b|namespace\s+lj::io\b', line):
                problems.append(f'{where}: namespace lj::io (namespaces match folders)')
            if folder != 'tests' and re.search(r'namespace\s+lj::test\b|\blj::test::', line):
                problems.append(f'{where}: namespace lj::test outside tests/')
            if not f.endswith(SOURCE_EXT):
                continue
            m = INCLUDE.match(line)
            if not m:
                continue
            inc = m.group(1)
            inc_top = top(inc)
            if folder in ('ir', 'ladder', 'verify') and inc_top == 'frontends':
                problems.append(f'{where}: {folder}/ includes a front end ({inc})')
            if folder in ('fuzz', 'bench', 'tools') and re.match(r'frontends/[^/]+/FrontEnd\.h$',
                                                                 inc):
                problems.append(f'{where}: {folder}/ includes {inc} (use the dialect registry)')
            if folder == 'formats' and inc_top in ('engines', 'jit', 'lowering', 'ladder',
                                                   'runtime', 'pipeline', 'services', 'hosts'):
                problems.append(f'{where}: formats/ includes {inc} (formats is data files only)')
            if folder == 'jit' and inc_top == 'engines':
                problems.append(f'{where}: jit/ includes {inc} (engines/ is above jit/)')
            if folder == 'ir' and '/' in inc and inc_top not in ('ir', 'runtime_abi', 'ladderjit',
                                                               'frontends'):
                problems.append(f'{where}: ir/ includes {inc} (the IR depends on nothing above)')
    readme_path = os.path.join(root, 'README.md')
    readme = open(readme_path, encoding='utf-8', errors='replace').read() \
        if os.path.isfile(readme_path) else ''
    for f in files:
        if re.fullmatch(r'docs/[^/]+\.md', f) and f'`{f}`' not in readme:
            problems.append(f'{f}: not named in README.md\'s docs list')
    return problems


# The workspace's shared folder by any path: ../shared/... or the absolute /work/shared/...
SHARED = re.compile(r'\.\./shared\b|/work/shared\b')


def self_test():
    cases = {
        'ir/A.h': '#include "frontends/hnc8/Symbols.h"\n',
        'ladder/B.cpp': '#include "frontends/hnc8/Mnemonics.h"\n',
        'verify/C.cpp': '#include "frontends/fanuc/FrontEnd.h"\n',
        'tools/D.cpp': '#include "frontends/iec/FrontEnd.h"\n',
        'formats/E.cpp': '#include "engines/AotLoader.h"\n',
        'jit/F.cpp': '#include "engines/AotLoader.h"\n',
        'docs/g.md': 'see ../shared/reference/hnc8-core.md\n',
        'tools/J.cpp': '// exactly as /work/shared/spec/CLI.md\n',
        'docs/unlisted.md': 'a page nobody can find\n',
        'docs/ok.md': 'listed\n',
        'README.md': '- `docs/ok.md`, `docs/g.md`: listed\n',
        'hosts/H.h': 'namespace lj::test {}\n',
        'runtime/I.h': 'namespace lj::io {}\n',
        'tests/ok.py': 'open("../shared/realprograms/x")  # allowed in tests\n',
        'bench/ok.cpp': '// ../shared/realprograms is read by benchmarks\n',
        'ladder/ok.cpp': '#include "ir/Program.h"\n',
    }
    with tempfile.TemporaryDirectory() as d:
        for name, text in cases.items():
            os.makedirs(os.path.join(d, os.path.dirname(name)), exist_ok=True)
            with open(os.path.join(d, name), 'w') as fh:
                fh.write(text)
        found = check(d)
    want = [n for n in cases if '/ok.' not in n and n != 'README.md']
    missing = [n for n in want if not any(p.startswith(n + ':') for p in found)]
    extra = [p for p in found if '/ok.' in p.split(':')[0]]
    if missing or extra:
        print('self-test FAILED: missed', missing, 'false alarms', extra)
        return 1
    print(f'self-test: all {len(want)} violations reported, 0 false alarms')
    return 0


def main():
    if len(sys.argv) > 1 and sys.argv[1] == '--self-test':
        return self_test()
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), '..', '..')
    problems = check(os.path.abspath(root))
    for p in problems:
        print(p)
    print(f'structure lint: {len(problems)} violation(s)')
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
