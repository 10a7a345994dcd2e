#!/usr/bin/env bash
# Install what RayCache needs from Debian bookworm, idempotently: a no-op when all is there.
# Usage: scripts/setup.sh [--with-web] [--with-browser] [--with-valgrind] [--with-profilers] [--with-window-tools]   (as root, or with sudo)
# --with-web: Emscripten, to build the web edition (preset web); --with-browser: chromium, to test the
# web edition and look at the docs headless; --with-valgrind: for tests/ui/valgrind_gui.sh;
# --with-profilers: perf and valgrind, to measure where a render's time goes (see docs/pages/table1.md);
# --with-window-tools: xdotool, xwd and ImageMagick, to drive a real window under xvfb-run and save what it shows
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config dpkg-dev ccache
  libglm-dev catch2 libcli11-dev nlohmann-json3-dev libstb-dev libssl-dev
  qt6-base-dev qt6-charts-dev libqt6opengl6-dev libgl-dev
  doxygen graphviz doxygen-awesome-css libjs-mathjax
  clang libclang-rt-14-dev libembree-dev
  xvfb xauth python3-matplotlib
)
for option in "$@"; do
  case "$option" in
    --with-web) packages+=(emscripten) ;;
    --with-browser) packages+=(chromium) ;;
    --with-valgrind) packages+=(valgrind) ;;
    --with-profilers) packages+=(linux-perf valgrind) ;;
    --with-window-tools) packages+=(xdotool x11-apps imagemagick) ;;
    *) echo "setup: unknown option $option" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if ((${#missing[@]} == 0)); then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
SUDO=""
if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
