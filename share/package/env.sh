# Source this file from bash or zsh (". /path/to/osgGlyphs-<version>/env.sh") to run the package's
# programs by name, or other OSG programs with its plugins: it puts bin/ on PATH and sets what the
# wrappers in bin/ set (OSG_LIBRARY_PATH, OSG_FILE_PATH).
osgglyphs_root=$(cd "$(dirname "${BASH_SOURCE:-$0}")" && pwd -P)
export PATH="$osgglyphs_root/bin${PATH:+:$PATH}"
export OSG_LIBRARY_PATH="$osgglyphs_root/lib${OSG_LIBRARY_PATH:+:$OSG_LIBRARY_PATH}"
export OSG_FILE_PATH="${OSG_FILE_PATH:+$OSG_FILE_PATH:}$osgglyphs_root/share/osgGlyphs/fonts"
unset osgglyphs_root
