#!/usr/bin/env bash
# Runs the benchmark harness (tools/AcShadow.Bench, `harness`): forges the scale dat and its quarter-size
# twin (cached in .bench-cache/ by their parameters), measures the floor, the naive exporter, batch at one
# job and at all cores, --incremental, doctor, dump against --version, a landblock batch with and without its
# indoor cells and the collision reference, writes
# bench.json and prints the table. Extra arguments go to the harness: --small (CI size), --setups N,
# --gfxobjs M, --seed S, --reps R, --out FILE, --work DIR (the disk folder the write workloads use),
# --memory-work DIR|none (their second, memory-backed run; default /dev/shm when present).
#
#   scripts/bench.sh                # the full run (about 10-15 minutes on 2 cores, the first time)
#   scripts/bench.sh --small        # a quick check that everything runs
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
cli_dir="$root/artifacts/bench/cli"
rm -rf "$cli_dir"

# The CLI as a user would ship it (README: Install, "a native binary"): Native AOT when the ILCompiler
# packages restore, else self-contained composite ReadyToRun, else the plain Release build.
rid=$(dotnet --info | awk '/^ *RID:/ {print $2; exit}')
if [ -n "$rid" ] && dotnet publish src/AcShadow.Cli -c Release -r "$rid" -p:PublishAot=true -o "$cli_dir" -v quiet -nologo; then
    echo "bench: measuring the Native AOT publish of acshadow ($rid)"
elif [ -n "$rid" ] && dotnet publish src/AcShadow.Cli -c Release -r "$rid" -p:SelfContained=true -p:PublishReadyToRun=true -p:PublishReadyToRunComposite=true -o "$cli_dir" -v quiet -nologo; then
    echo "bench: Native AOT unavailable; measuring the self-contained composite ReadyToRun publish of acshadow ($rid)"
else
    echo "bench: ahead-of-time publishes unavailable; measuring the plain Release build"
    dotnet publish src/AcShadow.Cli -c Release -o "$cli_dir" -v quiet -nologo
fi
dotnet build tools/AcShadow.Bench -c Release -v quiet -nologo

exec dotnet tools/AcShadow.Bench/bin/Release/net10.0/AcShadow.Bench.dll harness \
    --cli "$cli_dir/acshadow" --cache "$root/.bench-cache" --out "$root/bench.json" "$@"
