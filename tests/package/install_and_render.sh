#!/usr/bin/env bash
# The .deb that cpack builds installs a raycache that renders: the package is unpacked into a
# scratch root (dpkg -x), its raycache renders cube:3, and the image is the build's own.
# Usage: install_and_render.sh BUILD_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
(cd "$scratch" && cpack --config "$build/CPackConfig.cmake" -G DEB -B "$scratch/out" >"$scratch/cpack.log" 2>&1) \
  || { cat "$scratch/cpack.log"; exit 1; }
deb=$(ls "$scratch"/out/*.deb)
echo "package: $(basename "$deb"), $(du -k "$deb" | cut -f1) KiB"
dpkg-deb --info "$deb" | grep -E "^ (Package|Version|Depends):"
# Depends names the libraries the executables link (dpkg-shlibdeps, cmake/package_depends.cmake)
depends=$(dpkg-deb -f "$deb" Depends)
[[ $depends == *libc6* && $depends == *libstdc++6* ]] || { echo "Depends lacks libc6 or libstdc++6: '$depends'"; exit 1; }
[[ ! -x $build/ui/raycache-gui || $depends == *libqt6widgets6* ]] || { echo "Depends lacks Qt: '$depends'"; exit 1; }
dpkg -x "$deb" "$scratch/root"
installed="$scratch/root/usr/bin/raycache"
[[ -x $installed ]] || { echo "no usr/bin/raycache in the package"; exit 1; }
got=$("$installed" render cube:3 --width 48 --height 32 --hash -q)
want=$("$build/src/raycache" render cube:3 --width 48 --height 32 --hash -q)
echo "installed raycache render cube:3: $got"
[[ $got == "$want" ]] || { echo "the installed raycache's image differs from the build's ($want)"; exit 1; }
"$installed" render "$scratch/root/usr/share/raycache/scenes/balls1.nff" --width 16 --height 16 -q
# What else the build made is in it too
[[ ! -x $build/ui/raycache-gui || -x $scratch/root/usr/bin/raycache-gui ]] || { echo "raycache-gui missing"; exit 1; }
[[ ! -f $build/docs/html/index.html || -f $scratch/root/usr/share/doc/raycache/html/index.html ]] \
  || { echo "docs site missing"; exit 1; }
[[ ! -f $build/web-edition/web/index.html || -f $scratch/root/usr/share/raycache/web/raycache.js ]] \
  || { echo "web edition missing"; exit 1; }
echo "installed: $(cd "$scratch/root" && find . -type f | wc -l) files"
