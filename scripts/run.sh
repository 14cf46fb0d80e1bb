#!/usr/bin/env bash
# The main job: builds capbridge and writes the error-against-cost report of every law
# (out/report.csv, out/report.png), printing the table.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
scripts/setup_deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)"
mkdir -p out
build/src_c/cli/capbridge report --csv out/report.csv
/usr/bin/python3 scripts/plot_report.py out/report.csv out/report.png
echo "capbridge: wrote out/report.csv and out/report.png"
