#!/bin/sh
# The portable package's bin/<program>: runs libexec/osgGlyphs/<program> with OSG's plugin path
# (OSG_LIBRARY_PATH) on the package's lib/ and the package's fonts on OSG's data path
# (OSG_FILE_PATH), before and after what the caller has set. Every bin/ file is this script.
set -eu
self=$(readlink -f "$0")
root=$(dirname "$(dirname "$self")")
OSG_LIBRARY_PATH="$root/lib${OSG_LIBRARY_PATH:+:$OSG_LIBRARY_PATH}${OSG_LD_LIBRARY_PATH:+:$OSG_LD_LIBRARY_PATH}"
OSG_FILE_PATH="${OSG_FILE_PATH:+$OSG_FILE_PATH:}$root/share/osgGlyphs/fonts"
export OSG_LIBRARY_PATH OSG_FILE_PATH
exec "$root/libexec/osgGlyphs/$(basename "$self")" "$@"
