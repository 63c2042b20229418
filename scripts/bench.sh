#!/usr/bin/env bash
# Runs the benchmark harness (tools/AcShadow.Bench, `harness`): forges the scale dat, its quarter-size twin and
# the 3,000-Setup scaling dat (cached in .bench-cache/ by their parameters), measures the floor, batch at one
# job and at all cores, --incremental, doctor, dump against --version (the published binary, and the tool as
# `dotnet tool install` puts it on the PATH: packed by scripts/pack-tool.sh, installed into artifacts/bench/tool),
# scene and chart of the busy landblock, a landblock batch with and without its indoor cells and the collision
# reference, writes bench.json and prints the table with the run's conditions (cores, load average at the start
# and the end). Extra arguments go to the harness: --small (CI size), --setups N,
# --gfxobjs M, --seed S, --reps R, --out FILE, --work DIR (the disk folder the write workloads use),
# --memory-work DIR|none (their second, memory-backed run; default /dev/shm when present), --only GROUP,...
# (export, scaling, chart-all, startup, landblock, cells; default all: ratios of skipped groups are left out).
#
#   scripts/bench.sh                # the full run (about 40 minutes on 2 cores, most of it chart --all and the landblocks)
#   scripts/bench.sh --only scaling,startup,landblock   # issue 30's targets only (about 12 minutes)
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

# The tool as users install it (README: Install): packed into a feed and installed into a folder of its own,
# from a package cache of its own so no earlier package of the same version stands in for this one.
feed="$root/artifacts/bench/feed" tool_dir="$root/artifacts/bench/tool" packages="$root/artifacts/bench/packages"
rm -rf "$feed" "$tool_dir" "$packages"
scripts/pack-tool.sh "$feed"
NUGET_PACKAGES="$packages" dotnet tool install acshadow --tool-path "$tool_dir" --add-source "$feed" >/dev/null
echo "bench: dotnet tool install put $(file -b "$(readlink -f "$tool_dir/acshadow")" | cut -d, -f1-2) on the PATH ($tool_dir/acshadow)"

dotnet build tools/AcShadow.Bench -c Release -v quiet -nologo

exec dotnet tools/AcShadow.Bench/bin/Release/net10.0/AcShadow.Bench.dll harness \
    --cli "$cli_dir/acshadow" --installed "$tool_dir/acshadow" --cache "$root/.bench-cache" --out "$root/bench.json" "$@"
