#!/usr/bin/env bash
# Writes the osgDB fixtures of this folder: the scenes of tests/osgdb/SerializerFixtures.h as .osgt
# and .osgb files (make_osgdb_fixtures), and a tile archive of 120 random glyphs in three tiles
# (osgglyphconvert). The committed files were written by the release before the wrappers had a
# version (the wrappers of commit 7366b3a, without an osgGlyphs domain), for the tests to read as
# files from the wild; written again by a later release they are no longer that.
#   make-fixtures.sh <build folder>
set -euo pipefail
build=$(realpath "$1")
cd "$(dirname "$0")"
cmake --build "$build" --target make_osgdb_fixtures osgglyphconvert osgdb_serializers_osgglyphs \
    osgdb_serializers_osgglyphspaper osgdb_serializers_osgglyphstiles
export OSG_LIBRARY_PATH="$build/lib"
"$build/tests/make_osgdb_fixtures" .
rm -f tiles.osga
"$build/applications/osgglyphconvert/osgglyphconvert" --random 120 --seed 7 --tile-glyphs 30 --tile-cells 2 \
    --threads 1 --glyph-budget 12345 tiles.osga
ls -l ./*.osgt ./*.osgb ./*.osga
