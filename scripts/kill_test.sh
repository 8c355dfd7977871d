#!/usr/bin/env bash
# scripts/kill_test.sh [N] [BUILD_DIR]: interrupts simplify N times (default 200) at random moments
# of a run on data/cow.obj, SIGINT and SIGTERM in turn, and checks after each that the output
# is the old file or the complete new one, with no temporary file left. It is the CLI test
# Cli.InterruptedRunsLeaveTheOldOutputOrTheCompleteNewOne (40 kills in the suite), run N times.
set -euo pipefail
cd "$(dirname "$0")/.."
count=${1:-200}
build=${2:-build}
if [ ! -x "$build/bin/cli_test" ]; then
  echo "kill_test.sh: $build/bin/cli_test is missing (cmake --build $build --target cli_test)" >&2
  exit 2
fi
CGAL_POLICIES_KILLS=$count exec "$build/bin/cli_test" \
  --gtest_filter=Cli.InterruptedRunsLeaveTheOldOutputOrTheCompleteNewOne
