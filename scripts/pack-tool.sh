#!/usr/bin/env bash
# Packs the acshadow .NET tool into a folder (the "feed") as `dotnet tool install` takes it (README: Install):
#   acshadow.<version>.nupkg        names the packages below; `dotnet tool install` picks one for the machine
#   acshadow.<rid>.<version>.nupkg  this machine's runtime (e.g. linux-x64): a Native AOT binary, so a `dump`
#                                   starts at once; ReadyToRun (precompiled, on the installed .NET) where the
#                                   AOT compiler cannot run here (no ILCompiler package, no C linker)
#   acshadow.any.<version>.nupkg    framework-dependent, for every other platform (the JIT starts it)
# Usage: scripts/pack-tool.sh [FEED]      (default ~/acshadow-packages)
set -euo pipefail
feed="${1:-$HOME/acshadow-packages}"
cd "$(dirname "$0")/.."
export DOTNET_CLI_TELEMETRY_OPTOUT=1 DOTNET_NOLOGO=1
mkdir -p "$feed"
feed="$(cd "$feed" && pwd)"
# The runtime the SDK runs on: the RID the project's ToolPackageRuntimeIdentifiers names beside `any`.
rid=$(dotnet --info | awk '/^ *RID:/ {print $2; exit}')
pack() { dotnet pack src/AcShadow.Cli -c Release -o "$feed" --nologo -v quiet -clp:ErrorsOnly "$@"; }

pack
if pack -r "$rid"; then
    echo "pack-tool: acshadow.$rid is Native AOT"
else
    echo "pack-tool: Native AOT could not be built here; acshadow.$rid is ReadyToRun on the installed .NET instead" >&2
    pack -r "$rid" -p:PublishAot=false
fi
pack -r any -p:PublishAot=false
ls "$feed"/acshadow.*nupkg
