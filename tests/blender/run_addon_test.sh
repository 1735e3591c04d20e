#!/bin/bash
# ctest's door to tests/blender/addon_test.py: run_addon_test.sh CASE ZIP HILIGHT WORKDIR
# A fresh user folder each time (the add-on is installed into it); skipped
# where Blender is not installed.
set -u
case_name=$1 zip=$2 hilight=$3 work=$4
if ! command -v blender > /dev/null; then
  echo "SKIPPED: blender is not installed (setup.sh installs it)"
  exit 0
fi
rm -rf "$work" && mkdir -p "$work/user"
# A fresh light cache too: each run measures a cold solve, as a first Solve is.
export BLENDER_USER_SCRIPTS="$work/user" BLENDER_USER_CONFIG="$work/user/config" XDG_CACHE_HOME="$work/cache"
exec blender -b --factory-startup --python-exit-code 1 --python "$(dirname "$0")/addon_test.py" -- \
  --case "$case_name" --zip "$zip" --hilight "$hilight" --work "$work"
