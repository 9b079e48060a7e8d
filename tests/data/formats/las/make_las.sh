#!/bin/sh
# Writes the LAS test files (tests/formats/LasTest.cpp) into this folder. Debian has no program
# that writes LAS, so write_las.py writes them from the specification; see its header comment.
set -e
cd "$(dirname "$0")"
/usr/bin/python3 write_las.py .
