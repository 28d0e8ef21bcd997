#!/usr/bin/env bash
# Cost of one J2 update and one CPDI1 stencil (docs/paper-b.md).
set -euo pipefail
"${1:?usage: run.sh BIN_DIR}/bench_paper_b" timing
