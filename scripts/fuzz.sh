#!/usr/bin/env bash
# Fuzz campaign: damaged copies of the built-in sample dats through `dump` and `batch`.
# Usage: scripts/fuzz.sh [SEED] [CASES] [TIME_LIMIT_SECONDS]      (defaults: 1 50000 10)
# Prints cases/second, the failures (if any) and the slowest case; saves each kind of failure,
# minimised, under tests/AcShadow.Tests/Fuzz/Inputs/ so it becomes a regression test.
# Exit 0 when no case failed. CI runs a 2,000-case campaign as a test (FuzzCampaignTests).
set -uo pipefail
cd "$(dirname "$0")/.."
export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1
unset ACSHADOW_DAT
seed="${1:-1}"
cases="${2:-50000}"
limit="${3:-10}"
if ! build_log="$(dotnet build tools/AcShadow.Fuzz -c Release --nologo -v quiet -clp:ErrorsOnly 2>&1)"; then
  echo "$build_log" >&2
  exit 2
fi
trace="$(mktemp "${TMPDIR:-/tmp}/acshadow-fuzz-trace.XXXXXX")"
trap 'rm -f "$trace"' EXIT
dotnet tools/AcShadow.Fuzz/bin/Release/net10.0/acshadow-fuzz.dll \
  --seed "$seed" --cases "$cases" --time-limit "$limit" --save tests/AcShadow.Tests/Fuzz/Inputs --trace "$trace"
status=$?
# 0: no failure; 1: failures, listed above. Anything else: the process itself died (a crash is a failure too).
if [ "$status" -gt 1 ]; then
  echo "fuzz: the campaign process died (exit $status) during $(cat "$trace" 2>/dev/null || echo 'start-up'); rerun that case with --start" >&2
fi
exit "$status"
