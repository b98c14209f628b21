"""Running HAL files under `halrun` for the ladderjit HAL component (tests/hal, bench/).

The component must sit in rtapi_app's module directory (/usr/lib/linuxcnc/modules: rtapi_app
refuses module names with slashes), so install_module() copies the built ladderjit.so there
(root needed; the test command runs as root). As root, rtapi_app needs a fallback user
(RTAPI_UID) and a FIFO directory that user can write. Every halrun is bounded by a timeout."""
import os
import re
import shutil
import subprocess
import tempfile

RTLIB_DIR = "/usr/lib/linuxcnc/modules"


class RigError(Exception):
    pass


def require_linuxcnc(module):
    for tool in ("halrun", "halcmd", "rtapi_app"):
        if shutil.which(tool) is None:
            raise RigError(f"'{tool}' not found: install linuxcnc-uspace (scripts/setup-test.sh)")
    if not module or not os.path.isfile(module):
        raise RigError("the HAL component was not built (no /usr/include/linuxcnc/hal.h at "
                       "configure time): install linuxcnc-uspace-dev (scripts/setup-test.sh) "
                       "and re-run cmake")


def install_module(module):
    """Copy the built component to rtapi_app's module directory (when it differs)."""
    dest = os.path.join(RTLIB_DIR, "ladderjit.so")
    with open(module, "rb") as f:
        new = f.read()
    try:
        with open(dest, "rb") as f:
            if f.read() == new:
                return dest
    except FileNotFoundError:
        pass
    tmp = dest + ".tmp"
    try:
        with open(tmp, "wb") as f:
            f.write(new)
        os.chmod(tmp, 0o644)
        os.replace(tmp, dest)
    except PermissionError as e:
        raise RigError(f"cannot install the component into {RTLIB_DIR} ({e}); run as root or "
                       "`cmake --install build --component linuxcnc`")
    return dest


class Rig:
    """A world-readable work directory, the key pair, and halrun runs."""

    def __init__(self, ladderjit, module):
        self.ladderjit = ladderjit
        self.module = module
        require_linuxcnc(module)
        install_module(module)
        self.dir = tempfile.mkdtemp(prefix="ljhal-")
        os.chmod(self.dir, 0o755)
        fifo = os.path.join(self.dir, "fifo")
        os.mkdir(fifo)
        os.chmod(fifo, 0o1777)
        self.env = dict(os.environ)
        self.env["LADDERJIT_KEY_DIR"] = os.path.join(self.dir, "keys")
        self.env["LADDERJIT_CACHE"] = "off"
        if os.geteuid() == 0:
            self.env.setdefault("RTAPI_UID", "65534")
            self.env["RTAPI_FIFO_PATH"] = os.path.join(fifo, "rtapi_fifo")
        self.halrun(["-U"], timeout=30, check=False)

    def path(self, name):
        return os.path.join(self.dir, name)

    def write(self, name, text):
        p = self.path(name)
        with open(p, "w") as f:
            f.write(text)
        os.chmod(p, 0o644)
        return p

    def run(self, args, timeout=120, check=True):
        r = subprocess.run(args, env=self.env, capture_output=True, text=True, timeout=timeout)
        if check and r.returncode != 0:
            raise RigError(f"{' '.join(args)} failed ({r.returncode}):\n{r.stdout}{r.stderr}")
        return r

    def compile(self, source, so, extra=()):
        self.run([self.ladderjit, "compile", source, "-o", so, *extra])
        os.chmod(so, 0o644)
        # rtapi_app reads files as its fallback user: the public key must be readable (the
        # private key stays 0600).
        os.chmod(os.path.join(self.dir, "keys"), 0o755)
        return so

    def trust_key(self):
        return os.path.join(self.dir, "keys", "aot-signing.pub")

    def halrun(self, args, timeout=120, check=True):
        try:
            r = subprocess.run(["halrun", *args], env=self.env, capture_output=True, text=True,
                               timeout=timeout)
        except subprocess.TimeoutExpired as e:
            subprocess.run(["halrun", "-U"], env=self.env, capture_output=True, timeout=30)
            raise RigError(f"halrun {' '.join(args)} did not finish in {timeout} s: {e}")
        if check and r.returncode != 0:
            raise RigError(f"halrun {' '.join(args)} failed ({r.returncode}):\n"
                           f"{r.stdout}{r.stderr}")
        return r

    def halfile(self, name, text, timeout=120, check=True):
        return self.halrun(["-f", self.write(name, text)], timeout=timeout, check=check)

    def cleanup(self):
        shutil.rmtree(self.dir, ignore_errors=True)


VALUE = re.compile(r"^(TRUE|FALSE|-?\d+(\.\d+)?([eE][-+]?\d+)?|0x[0-9A-Fa-f]+)$")


def gets_values(stdout):
    """The values `gets`/`getp` printed, in order: every stdout line that is a HAL value
    (bit, number, hex); informational lines of other components (classicladder) are skipped."""
    return [l.strip() for l in stdout.splitlines() if VALUE.match(l.strip())]
