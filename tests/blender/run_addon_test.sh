#!/bin/sh
# blender_addon: tests/blender/test_addon.py in Blender, headless, in a folder of its own under the
# system temp directory, which also holds Blender's configuration and cache (HOME and the XDG
# folders point into it, so nothing is written to the user's home; PYTHONPATH is unset, so the
# package comes through the add-on's preference). The folder is removed when every check holds
# and kept, and named, when one fails.
#   run_addon_test.sh BLENDER --package BUILD/python --addons bindings/blender [test options]
set -u
blender=$1
shift
dir=$(mktemp -d "${TMPDIR:-/tmp}/ocean-blender-addon-XXXXXX") || exit 1
env -u PYTHONPATH HOME="$dir" XDG_CONFIG_HOME="$dir/config" XDG_CACHE_HOME="$dir/cache" \
  "$blender" -b --factory-startup --python-exit-code 1 \
  --python "$(dirname "$0")/test_addon.py" -- "$@" --out "$dir/out"
rc=$?
if [ "$rc" -eq 0 ]; then
  rm -rf "$dir"
else
  echo "blender_addon: failed with status $rc; its files are in $dir"
fi
exit "$rc"
