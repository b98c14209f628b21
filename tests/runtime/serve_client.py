"""Shared by the serve end-to-end tests (serve_monitor.py, serve_aot.py): the test program, the
`ladderjit` binary from argv[1], and helpers that drive `ladderjit monitor` and collect failures
(tests/support/serveutil.py, bound to that binary). Values are polled until they show up (bounded
by a generous deadline): the tests assert what the server must do, never how fast."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))

import serveutil  # noqa: E402
from serveutil import FAILURES, LINE_LD_X10, PROGRAM, check  # noqa: E402,F401

LJ = sys.argv[1]


def run(*args):
    return serveutil.run(LJ, *args, timeout=300)


def monitor(sock, *args):
    return serveutil.monitor(LJ, sock, *args, timeout=300)


def read(sock, addr):
    return serveutil.read(LJ, sock, addr, timeout=300)


def wait_value(sock, addr, want, seconds=30):
    return serveutil.wait_value(LJ, sock, addr, want, seconds)
