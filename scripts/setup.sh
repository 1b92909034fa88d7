#!/usr/bin/env bash
# Installs everything opencv_event needs on Debian bookworm (as root, or through sudo) and fetches the
# OpenCV source of the installed version (for the ts test framework and the contrib-mode build) into a
# cache outside the clone. Idempotent: a second run installs nothing and downloads nothing.
#
# Prints nothing but progress; the OpenCV source dir is written to $OPENCV_EVENT_CACHE/opencv-source-dir.
set -euo pipefail

cache=${OPENCV_EVENT_CACHE:-/var/cache/opencv_event}
packages=(build-essential cmake ninja-build ccache pkg-config git xz-utils dpkg-dev
          libopencv-dev libeigen3-dev libgtest-dev libusb-1.0-0-dev liblz4-dev libzstd-dev libbz2-dev libsqlite3-dev libhdf5-dev
          libpng-dev libjpeg-dev zlib1g-dev python3-dev python3-numpy python3-pytest python3-opencv python3-matplotlib python3-venv python3-pip python3-setuptools python3-wheel
          clang libclang-rt-14-dev)  # libFuzzer + sanitizer runtimes for test/fuzz

sudo=()
if [ "$(id -u)" != 0 ]; then
  command -v sudo >/dev/null || { echo "setup.sh: run as root (or install sudo)" >&2; exit 1; }
  sudo=(sudo)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "== setup: installing ${missing[*]}"
  "${sudo[@]}" apt-get update -q
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

"${sudo[@]}" mkdir -p "$cache/src" "$cache/ccache"
"${sudo[@]}" chown "$(id -u):$(id -g)" "$cache" "$cache/src" "$cache/ccache"

# OpenCV source of exactly the installed version (Debian keeps ts and opencv_contrib in it).
version=$(dpkg-query -W -f='${source:Version}' libopencv-dev)
upstream=${version%%-*}; upstream=${upstream#*:}; upstream=${upstream%%+*}
srcdir="$cache/src/opencv-$version"
if [ ! -f "$srcdir/.complete" ]; then
  if ! apt-get source --print-uris -q "opencv=$version" >/dev/null 2>&1; then
    echo "== setup: adding a deb-src entry for Debian's source packages"
    . /etc/os-release
    "${sudo[@]}" tee /etc/apt/sources.list.d/opencv-event-deb-src.sources >/dev/null <<SRC
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: ${VERSION_CODENAME} ${VERSION_CODENAME}-updates
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
    "${sudo[@]}" apt-get update -q
  fi
  echo "== setup: fetching the OpenCV $version source into $srcdir"
  rm -rf "$srcdir.tmp" && mkdir -p "$srcdir.tmp"
  (cd "$srcdir.tmp" && apt-get source -q "opencv=$version" >/dev/null)
  unpacked=$(find "$srcdir.tmp" -mindepth 1 -maxdepth 1 -type d -name "opencv-*" | head -1)
  [ -f "$unpacked/modules/ts/src/ts.cpp" ] || { echo "setup.sh: no modules/ts in the OpenCV source" >&2; exit 1; }
  rm -rf "$srcdir" && mv "$unpacked" "$srcdir" && rm -rf "$srcdir.tmp"
  touch "$srcdir/.complete"
fi
echo "$srcdir" > "$cache/opencv-source-dir"
echo "== setup: OpenCV $upstream ($version) installed, source at $srcdir"
