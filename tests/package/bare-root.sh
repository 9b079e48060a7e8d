#!/usr/bin/env bash
# The portable package on a bare system: a minimal Debian root (debootstrap --variant=minbase) with
# only the GL/EGL loader and Mesa's EGL driver, standing in for a GPU node's driver, and no
# OpenSceneGraph. As an unprivileged user, the packaged programs must find every library they
# need, render the default scene byte for byte as the build tree does, and convert a trajectory.
#   bare-root.sh <build dir> <work dir>        (as root; the Debian mirror must be reachable)
# The root is kept in <work dir>/root and reused; delete it to start over.
set -euo pipefail
build=$(realpath "$1") work=$(realpath -m "$2")
source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
fail() { echo "bare-root: $*" >&2; exit 1; }
skip() { echo "bare-root: skipped: $*"; exit 77; }
((EUID == 0)) || skip "needs root (debootstrap, chroot)"
for tool in debootstrap patchelf; do
    command -v $tool >/dev/null || skip "needs $tool (apt-get install $tool; .ci/bootstrap installs it)"
done
mkdir -p "$work"
root=$work/root

# Nothing mounted in the root outlives a run, not even one cut short (debootstrap mounts /proc).
release_root() { umount -l "$root/proc" 2>/dev/null || true; }
trap release_root EXIT
trap 'release_root; exit 143' TERM INT

if [[ ! -e $root/.osgglyphs-ready ]]; then
    release_root
    rm -rf --one-file-system "$root"
    mirror=$(sed -n 's/^URIs: *//p; s/^deb \(http[^ ]*\) .*/\1/p' /etc/apt/sources.list.d/*.sources /etc/apt/sources.list 2>/dev/null | head -n 1 || true)
    mirror=${mirror:-http://deb.debian.org/debian}
    host=${mirror#*://} && host=${host%%/*}
    timeout 20 bash -c "</dev/tcp/$host/80" 2>/dev/null || skip "the Debian mirror $host cannot be reached"
    debootstrap --variant=minbase bookworm "$root" "$mirror" >"$work/debootstrap.log" 2>&1 ||
        { tail -20 "$work/debootstrap.log"; fail "debootstrap failed"; }
    chroot "$root" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
        libegl1 libgl1 libegl-mesa0 libgl1-mesa-dri >"$work/apt.log" 2>&1 || { tail -20 "$work/apt.log"; fail "apt-get failed"; }
    chroot "$root" apt-get clean
    touch "$root/.osgglyphs-ready"
fi
if chroot "$root" dpkg-query -W -f '${Package}\n' | grep -qi openscenegraph; then
    fail "the bare root has OpenSceneGraph packages"
fi

bash "$source_dir/share/package/make-package.sh" "$build" "$work/package"
rm -rf "$root/opt/osgGlyphs" && mkdir -p "$root/opt/osgGlyphs"
tar -C "$root/opt/osgGlyphs" --strip-components=1 -xzf "$work"/package/osgGlyphs-*.tar.gz
scratch=$root/tmp/osgglyphs && rm -rf "$scratch" && mkdir -p "$scratch" && chmod 1777 "$scratch"
cp "$source_dir/tests/data/formats/melt.lammpstrj" "$scratch/" && chmod a+r "$scratch/melt.lammpstrj"

# A real system has /proc: the loader reads /proc/self/exe to expand the programs' $ORIGIN.
mountpoint -q "$root/proc" || mount -t proc proc "$root/proc"
as_user() { chroot --userspec=nobody:nogroup "$root" env -i PATH=/usr/bin:/bin HOME=/tmp/osgglyphs "$@"; }

# Every packaged ELF file finds its libraries in the bare root.
missing=$(chroot "$root" sh -c 'find /opt/osgGlyphs -type f -name "*.so*" -o -type f -path "*/libexec/*" |
    xargs ldd 2>/dev/null | grep "not found" | sort -u' || true)
[[ -z $missing ]] || fail "libraries not found in the bare root:"$'\n'"$missing"

as_user /opt/osgGlyphs/bin/osgglyphviewer --output /tmp/osgglyphs/default.png --size 320 240 >"$work/viewer.log" 2>&1 ||
    { cat "$work/viewer.log"; fail "the packaged viewer failed"; }
grep -q "OpenGL through EGL device" "$work/viewer.log" || { cat "$work/viewer.log"; fail "no EGL device used"; }
"$build/applications/osgglyphviewer/osgglyphviewer" --output "$work/build-tree.png" --size 320 240 >/dev/null
cmp "$work/build-tree.png" "$scratch/default.png" || fail "the package's picture differs from the build tree's"

as_user /opt/osgGlyphs/bin/osgglyphconvert /tmp/osgglyphs/melt.lammpstrj /tmp/osgglyphs/melt.osga >"$work/convert.log" 2>&1 ||
    { cat "$work/convert.log"; fail "the packaged converter failed"; }
as_user /opt/osgGlyphs/bin/osgglyphviewer /tmp/osgglyphs/melt.osga --output /tmp/osgglyphs/melt.png --size 160 120 \
    >>"$work/viewer.log" 2>&1 || { cat "$work/viewer.log"; fail "the packaged viewer cannot show the archive"; }
[[ -s $scratch/melt.png ]] || fail "no picture of the archive"
echo "bare-root: the package ($(du -h "$work"/package/osgGlyphs-*.tar.gz | cut -f1)) runs as nobody in a bare" \
    "Debian root, and its picture equals the build tree's byte for byte"
