#!/usr/bin/env bash
# Install the Debian 12 packages ladderjit needs to build and test. Idempotent: prints nothing
# and touches nothing when all of them are present. Works as root or through sudo.
set -euo pipefail

# Build: cmake + make + g++ (ccache is picked up automatically when present).
# Engine: llvm-19-dev (libLLVM-19 and its CMake package; pulls libffi/libxml2/libz3 headers),
#   llvm-19-tools (FileCheck and lit for the golden tests, with python3).
# Libraries: CLI11, nlohmann-json, Google Benchmark, GoogleTest + GoogleMock (Debian's GTest
#   CMake package references the gmock libraries, so both are needed).
# plc.dit content hash: OpenSSL libcrypto (libssl-dev), SHA-256 through the EVP API.
# Fuzzing builds (-DLADDERJIT_FUZZERS=ON): clang-19 and its libFuzzer runtime.
# serve --modbus: libmodbus (libmodbus-dev); the Modbus tests drive it with real clients we did
#   not write: Debian's mbpoll (CTest modbus.serve_mbpoll) and python3-pymodbus (manual checks).
# serve --http (the live ladder view): libmicrohttpd (libmicrohttpd-dev), made for embedded
#   servers: per-connection memory limits, timeouts, connection limits, incremental uploads
#   (docs/security.md "The live view's HTTP port" says why it replaced cpp-httplib);
#   libjs-dygraphs, the charting library the live view's signal trace panel will plot with
#   (docs/trace.md "Page").
# zlib/zstd headers: LLVMConfig looks for them and its exported static targets name them; we
# link only the shared libLLVM (configuring without them works), but Debian's LLVM packaging has
# failed on a missing zstd target before (llvm19-orc-notes.md 1), so they are installed too.
PACKAGES=(
  cmake make g++ ccache python3 pkg-config
  llvm-19-dev llvm-19-tools clang-19 libclang-rt-19-dev
  libcli11-dev nlohmann-json3-dev libbenchmark-dev libgtest-dev libgmock-dev libssl-dev
  zlib1g-dev libzstd-dev
  libmodbus-dev mbpoll python3-pymodbus
  libmicrohttpd-dev libjs-dygraphs
)

missing=()
for pkg in "${PACKAGES[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$pkg")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

if [[ $(id -u) -eq 0 ]]; then
  as_root=()
elif command -v sudo >/dev/null 2>&1; then
  as_root=(sudo)
else
  echo "setup.sh: need root or sudo to install: ${missing[*]}" >&2
  exit 1
fi

echo "setup.sh: installing ${missing[*]}"
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup.sh: done"
