#!/usr/bin/env python3
"""Lint of the live page's scripts (ladder/web/*.js, docs/ladder-view.md "Live view"): each must
parse (`node --check`) and pass Debian's eslint with the committed config ladder/web/.eslintrc.json
(eslint:recommended plus eqeqeq, no eval, no shadowing, strict mode per function). Fails, never
skips, when node or eslint is missing (scripts/setup-test.sh installs eslint).

Usage: web_js.py SOURCE_DIR
"""
import glob
import os
import shutil
import subprocess
import sys


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else '.'
    web = os.path.join(src, 'ladder', 'web')
    files = sorted(glob.glob(os.path.join(web, '*.js')))
    if not files:
        print(f'FAIL: no script in {web}')
        return 1
    node = shutil.which('node')
    eslint = shutil.which('eslint')
    if not node or not eslint:
        print('FAIL: node and eslint are needed (scripts/setup-test.sh installs Debian\'s eslint)')
        return 1
    env = dict(os.environ)
    # Debian's eslint lives in /usr/share/nodejs, which a node not built by Debian (NodeSource)
    # does not search.
    env['NODE_PATH'] = '/usr/share/nodejs' + (':' + env['NODE_PATH'] if env.get('NODE_PATH') else '')
    bad = 0
    for f in files:
        r = subprocess.run([node, '--check', f], capture_output=True, text=True, env=env)
        if r.returncode != 0:
            print(f'FAIL: node --check {f}:\n{r.stderr}')
            bad += 1
    # Run in the folder: eslint 6 refuses file paths outside its working directory.
    # `--format unix`: Debian 12's eslint package does not depend on node-chalk, which its
    # default formatter (stylish) needs; the unix one needs nothing (file:line:col: message).
    r = subprocess.run([eslint, '--no-eslintrc', '-c', '.eslintrc.json', '--max-warnings', '0',
                        '--format', 'unix'] +
                       [os.path.basename(f) for f in files],
                       capture_output=True, text=True, env=env, cwd=web)
    if r.returncode != 0:
        print(f'FAIL: eslint:\n{r.stdout}{r.stderr}')
        bad += 1
    names = ', '.join(os.path.basename(f) for f in files)
    print(f'{"FAIL" if bad else "ok"}: {len(files)} script(s) ({names}): node --check and eslint')
    return 1 if bad else 0


if __name__ == '__main__':
    sys.exit(main())
