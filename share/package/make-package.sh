#!/usr/bin/env bash
# Makes the portable osgGlyphs package: a relocatable .tar.gz of the osgGlyphs libraries, plugins,
# programs, shaders and data, with OpenSceneGraph's libraries and plugins and every other shared
# library they need except the system's C/C++ runtime and GL/EGL stack (see EXCLUDED below), all
# with $ORIGIN-relative run paths. Needs patchelf. Prints the archive's path and its sizes.
#   share/package/make-package.sh BUILD_DIR OUT_DIR
# BUILD_DIR is a configured and built osgGlyphs build folder; OUT_DIR receives
# osgGlyphs-<version>-linux-<arch>.tar.gz (docs/portable-package.md).
set -euo pipefail

usage() { sed -n '2,8p' "$0" >&2; exit 2; }
(($# == 2)) || usage
build=$(cd "$1" && pwd -P)
mkdir -p "$2"
out=$(cd "$2" && pwd -P)
source_dir=$(cd "$(dirname "$0")/../.." && pwd -P)
[[ -f $build/CMakeCache.txt ]] || { echo "make-package: $build is not a build folder" >&2; exit 2; }
command -v patchelf >/dev/null || { echo "make-package: needs patchelf (apt-get install patchelf)" >&2; exit 2; }

# Sonames left to the system: glibc, the GCC C++ runtime, the GL/EGL loaders (glvnd) and the X11
# libraries they need, Mesa, LLVM and libdrm. A GPU's vendor driver must meet the system's own
# loader, and a Mesa of the system must meet the libdrm it was built with.
EXCLUDED='^(ld-linux-x86-64\.so\.2|libc\.so\.6|libm\.so\.6|libdl\.so\.2|libpthread\.so\.0|librt\.so\.1'
EXCLUDED+='|libresolv\.so\.2|libutil\.so\.1|libanl\.so\.1|libmvec\.so\.1|libnsl\.so\.1|libthread_db\.so\.1'
EXCLUDED+='|libBrokenLocale\.so\.1|libnss_.*|libstdc\+\+\.so\.6|libgcc_s\.so\.1'
EXCLUDED+='|libGL\.so\.1|libEGL\.so\.1|libGLX\.so\.0|libGLdispatch\.so\.0|libOpenGL\.so\.0|libGLES.*|libGLU\.so\.1'
EXCLUDED+='|libOSMesa\.so.*|libglapi\.so.*|libgbm\.so.*|lib(EGL|GLX)_.*|libLLVM.*|libgallium.*|libdrm.*'
EXCLUDED+='|libX11\.so\.6|libxcb\.so\.1|libXau\.so\.6|libXdmcp\.so\.6)$'
# OpenSceneGraph plugins left out for the size of what they need (GDAL, COLLADA, Coin, poppler: 90 MB).
EXCLUDED_PLUGINS='^osgdb_(gdal|ogr|dae|iv|pdf)\.so$'
# Stock OSG programs that read the glyph plugins' formats.
STOCK_PROGRAMS=(osgviewer osgconv)

version=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$build/CMakeCache.txt")
name=osgGlyphs-$version-linux-$(uname -m)
stage=$out/$name
rm -rf "$stage" "$out/$name.tar.gz"

echo "make-package: installing $build into $stage"
cmake --install "$build" --prefix "$stage" --strip >/dev/null
rm -rf "$stage/include" "$stage/lib/cmake" "$stage/lib/pkgconfig"
find "$stage/lib" -maxdepth 1 -name '*.so' -type l -delete
plugins=$(echo "$stage"/lib/osgPlugins-*)
[[ -d $plugins ]] || { echo "make-package: no osgPlugins folder in the install" >&2; exit 1; }

# The ELF files: programs, libraries and plugins (share/ holds none), in one readelf call.
elf_files() {
    find "$stage/lib" "$stage/libexec" -type f -print0 | xargs -0 readelf -h 2>/dev/null | sed -n 's/^File: //p'
}
# "<file><tab><soname>" for each NEEDED soname of each given file (at least two files, so that
# readelf names them).
needed() {
    readelf -d "$@" | awk '/^File: / {file = substr($0, 7)}
        /\(NEEDED\)/ {match($0, /\[.*\]/); print file "\t" substr($0, RSTART + 1, RLENGTH - 2)}'
}

# The programs go to libexec/osgGlyphs; bin/ gets a wrapper of each (share/package/program-wrapper.sh).
mkdir -p "$stage/libexec/osgGlyphs"
mv "$stage"/bin/* "$stage/libexec/osgGlyphs/"
for program in "${STOCK_PROGRAMS[@]}"; do
    path=$(command -v "$program" || true)
    if [[ -n $path ]]; then cp "$path" "$stage/libexec/osgGlyphs/"; else echo "make-package: no $program here, left out"; fi
done
for program in "$stage"/libexec/osgGlyphs/*; do
    install -m 755 "$source_dir/share/package/program-wrapper.sh" "$stage/bin/$(basename "$program")"
done

# OpenSceneGraph's plugins, from beside the libosgDB the build links.
osgdb=$(ldd "$stage/lib/libosgGlyphs.so."*[0-9] | awk '$1 ~ /^libosgDB\.so/ {print $3}' | head -1)
osg_plugins=$(dirname "$(readlink -f "$osgdb")")/$(basename "$plugins")
[[ -d $osg_plugins ]] || { echo "make-package: no OSG plugins at $osg_plugins" >&2; exit 1; }
for plugin in "$osg_plugins"/*.so; do
    base=$(basename "$plugin")
    [[ $base =~ $EXCLUDED_PLUGINS || -e $plugins/$base ]] || cp -P "$plugin" "$plugins/"
done

echo "make-package: the libraries they need, and run paths"
# The closure: from every ELF file of the package along NEEDED, not into the excluded sonames.
# A soname is where ld.so's cache says, else where ldd of the file that needs it finds it.
case $(uname -m) in x86_64) ld_arch=x86-64 ;; aarch64) ld_arch=AArch64 ;; *) ld_arch= ;; esac
declare -A location=()
declare -A bundled=()
while read -r soname flags path; do
    if [[ -z ${location[$soname]:-} && $flags == *"$ld_arch"* ]]; then location[$soname]=$path; fi
done < <(ldconfig -p | awk '$NF ~ /^\// {print $1, $2, $NF}')
locate() { ldd "$1" | awk -v soname="$2" '$1 == soname && $3 ~ /^\// {print $3}'; }
mapfile -t roots < <(elf_files)
frontier=("${roots[@]}")
missing=()
while ((${#frontier[@]})); do
    ((${#frontier[@]} > 1)) || frontier+=("${frontier[0]}")
    next=()
    while IFS=$'\t' read -r file soname; do
        [[ $soname =~ $EXCLUDED || -n ${bundled[$soname]:-} || -e $stage/lib/$soname ]] && continue
        path=${location[$soname]:-$(locate "$file" "$soname")}
        [[ -n $path ]] || { missing+=("$soname (needed by ${file#$stage/})"); continue; }
        bundled[$soname]=$path
        cp -L "$path" "$stage/lib/$soname"
        chmod 644 "$stage/lib/$soname"
        next+=("$stage/lib/$soname")
    done < <(needed "${frontier[@]}")
    frontier=("${next[@]}")
done
if ((${#missing[@]})); then
    printf 'make-package: not found on this machine: %s\n' "${missing[@]}" >&2
    exit 1
fi

mapfile -t elves < <(elf_files)

# Run paths relative to each file's place.
for file in "${elves[@]}"; do
    case $file in
    "$stage"/libexec/osgGlyphs/*) runpath='$ORIGIN/../../lib' ;;
    "$plugins"/*) runpath='$ORIGIN/..' ;;
    *) runpath='$ORIGIN' ;;
    esac
    patchelf --set-rpath "$runpath" "$file"
done

# The font of the viewer's colour legend and time line, so that text renders as on the build machine.
font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
mkdir -p "$stage/share/osgGlyphs/fonts"
if [[ -f $font ]]; then
    cp "$font" "$stage/share/osgGlyphs/fonts/"
    cp /usr/share/doc/fonts-dejavu-core/copyright "$stage/share/osgGlyphs/fonts/DejaVuSans.copyright" 2>/dev/null || true
else
    echo "make-package: no $font (fonts-dejavu-core): the legend falls back to OSG's built-in font"
fi

# What was bundled, from which Debian package (dpkg's file lists, both sides of the /usr merge:
# dpkg -S takes seconds a library), and the licences of those packages.
docs=$stage/share/doc/osgGlyphs
mkdir -p "$docs/licenses"
declare -A package_of=()
mapfile -t sonames < <(printf '%s\n' "${!bundled[@]}" | sort)
for soname in "${sonames[@]}"; do
    real=$(readlink -f "${bundled[$soname]}")
    echo "$real"
    echo "${real#/usr}"
done > "$out/$name.paths"
while IFS= read -r line; do
    list=${line%%.list:*}
    package=${list##*/}
    package_of[${line##*/}]=${package%%:*}
done < <(grep -Fx -f "$out/$name.paths" /var/lib/dpkg/info/*.list 2>/dev/null || true)
rm -f "$out/$name.paths"
declare -A version_of=()
while read -r package package_version; do
    version_of[$package]=$package_version
done < <(dpkg-query -W -f='${Package} ${Version}\n' $(printf '%s\n' "${package_of[@]}" | sort -u) 2>/dev/null || true)
{
    echo "# soname  Debian package  version"
    for soname in "${sonames[@]}"; do
        package=${package_of[$(basename "$(readlink -f "${bundled[$soname]}")")]:-?}
        echo "$soname  $package  ${version_of[$package]:-?}"
        copyright=/usr/share/doc/$package/copyright
        if [[ -f $copyright ]]; then cp "$copyright" "$docs/licenses/$package.copyright"; fi
    done
} > "$docs/bundled-libraries.txt"
cp "$source_dir/share/package/env.sh" "$stage/env.sh"

# The newest glibc and libstdc++ symbol versions any file of the package asks for.
newest_version() {
    readelf -V "${elves[@]}" 2>/dev/null | grep -o "Name: $1_[0-9.]*" | sed "s/Name: $1_//" | sort -V | tail -1
}
glibc=$(newest_version GLIBC)
glibcxx=$(newest_version GLIBCXX)
sed -e "s/@VERSION@/$version/g" -e "s/@GLIBC@/$glibc/g" -e "s/@GLIBCXX@/$glibcxx/g" \
    "$source_dir/share/package/README.package.md" > "$stage/README.md"

# Nothing of the system's runtime or GL stack, and no run path outside the package.
for soname in $(ls "$stage/lib"); do
    if [[ $soname =~ $EXCLUDED ]]; then echo "make-package: $soname must not be bundled" >&2; exit 1; fi
done
for file in "${elves[@]}"; do
    runpath=$(patchelf --print-rpath "$file")
    [[ $runpath == '$ORIGIN'* && $runpath != *:* ]] || { echo "make-package: run path '$runpath' in $file" >&2; exit 1; }
done

echo "make-package: packing"
tar -C "$out" --sort=name --owner=0 --group=0 --numeric-owner --mtime=@0 -cf - "$name" | gzip -n -6 > "$out/$name.tar.gz"
unpacked=$(du -sb "$stage" | cut -f1)
packed=$(stat -c %s "$out/$name.tar.gz")
echo "make-package: bundled ${#bundled[@]} libraries; needs glibc >= $glibc, libstdc++ with GLIBCXX_$glibcxx"
echo "make-package: $out/$name.tar.gz: $((packed / 1048576)) MiB packed, $((unpacked / 1048576)) MiB unpacked"
rm -rf "$stage"
