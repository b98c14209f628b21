#!/usr/bin/env bash
# Configure, build and run the whole test suite: what CI runs (.ci/run). Build directory:
# $BUILD_DIR (default build/), Release, ccache when installed, 2 parallel jobs.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build}
jobs=${JOBS:-2}

cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build_dir" -j"$jobs"
ctest --test-dir "$build_dir" --output-on-failure -j"$jobs"
