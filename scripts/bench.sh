#!/usr/bin/env bash
# Runs the benchmark harness (tools/AcShadow.Bench, `harness`): forges the scale dat, its quarter-size twin and
# the 3,000-Setup scaling dat (cached in .bench-cache/ by their parameters), measures the floor, batch at one
# job and at all cores, --incremental, doctor, dump against --version (the tool as `dotnet tool install` puts it on
# the PATH: packed by scripts/pack-tool.sh, installed into artifacts/bench/tool; by its own path and by the link),
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
# The tool as users install it (README: Install): packed into a feed (Native AOT where the ILCompiler packages
# restore and a C toolchain runs, else ReadyToRun: scripts/pack-tool.sh says which) and installed into a folder
# of its own, from a package cache of its own so no earlier package of the same version stands in for this one.
# The binary it links onto the PATH is also the one the harness runs as "the CLI": one ahead-of-time compile.
feed="$root/artifacts/bench/feed" tool_dir="$root/artifacts/bench/tool" packages="$root/artifacts/bench/packages"
rm -rf "$feed" "$tool_dir" "$packages" "$root/artifacts/bench/cli"
scripts/pack-tool.sh "$feed"
NUGET_PACKAGES="$packages" dotnet tool install acshadow --tool-path "$tool_dir" --add-source "$feed" >/dev/null
cli="$(readlink -f "$tool_dir/acshadow")"
echo "bench: dotnet tool install put $(file -b "$cli" | cut -d, -f1-2) on the PATH ($tool_dir/acshadow); measuring it as the CLI too"

dotnet build tools/AcShadow.Bench -c Release -v quiet -nologo

exec dotnet tools/AcShadow.Bench/bin/Release/net10.0/AcShadow.Bench.dll harness \
    --cli "$cli" --installed "$tool_dir/acshadow" --cache "$root/.bench-cache" --out "$root/bench.json" "$@"
