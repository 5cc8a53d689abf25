#!/usr/bin/env bash
# Regenerates docs/accuracy-and-speed.md and its figure: builds, runs the accuracy benchmarks,
# writes the report.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --tests build >/dev/null
command -v python3 >/dev/null || { echo "needs python3 (apt-get install python3)" >&2; exit 2; }
bench/accuracy_report.py build
