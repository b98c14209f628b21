#!/usr/bin/env bash
# Packages only the tests need, on top of setup.sh: headless Chromium and CJK fonts for the
# ladder page screenshots (docs/ladder-view.md); chromedriver + python3-selenium for the live view
# test (tests/http/live_page.py); LinuxCNC (halrun, rtapi_app, classicladder_rt and the HAL
# headers the HAL component is built against: tests/hal, docs/linuxcnc.md), the openssl tool
# its tests re-sign a .so with, and sigrok-cli, which reads `run --vcd` files back
# (tests/cli/vcd_sigrok.py, docs/trace.md); eslint, which lints the live page's scripts
# (tests/lint/web_js.py). Idempotent; root or sudo.
set -euo pipefail
PACKAGES=(chromium fonts-wqy-zenhei chromium-driver python3-selenium eslint linuxcnc-uspace linuxcnc-uspace-dev openssl sigrok-cli)
missing=()
for pkg in "${PACKAGES[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$pkg")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0
if [[ $(id -u) -eq 0 ]]; then as_root=(); elif command -v sudo >/dev/null 2>&1; then as_root=(sudo); else
  echo "setup-test.sh: need root or sudo to install: ${missing[*]}" >&2
  exit 1
fi
echo "setup-test.sh: installing ${missing[*]}"
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup-test.sh: done"
