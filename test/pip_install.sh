#!/usr/bin/env bash
# pip install from this repository into a fresh venv, offline (no package index: the distribution's setuptools,
# NumPy and cv2 through --system-site-packages), then the installed package outside the repository: its version,
# the distribution's cv2 beside it, and a closed form through the wrapped API.
#   test/pip_install.sh <work-dir>
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
work=${1:?usage: pip_install.sh <work-dir>}
# setup.py compiles through ccache when it is there: the project's cache, as scripts/build.sh uses it.
export CCACHE_DIR=${CCACHE_DIR:-${OPENCV_EVENT_CACHE:-/var/cache/opencv_event}/ccache}
export CCACHE_BASEDIR=$repo
rm -rf "$work" && mkdir -p "$work"
/usr/bin/python3 -m venv --system-site-packages "$work/venv"
(cd "$repo" && "$work/venv/bin/pip" install --no-build-isolation --no-index --quiet .)
version=$(sed -n 's/^project(opencv_event VERSION \([0-9.]*\).*/\1/p' "$repo/CMakeLists.txt")
cd "$work"
"$work/venv/bin/python" - "$version" <<'PY'
import sys
import cv2
import numpy as np
import opencv_event as ev

assert "site-packages" in ev.__file__ and ev.__version__ == sys.argv[1], (ev.__file__, ev.__version__, sys.argv[1])
assert cv2.__file__.startswith("/usr/lib/python3/"), cv2.__file__  # the distribution's cv2, beside it
# An edge sliding right at 100 px/s: lifetimes of 10 ms (the same closed form as the C++ tests).
xs, ys = np.meshgrid(np.arange(16), np.arange(8))
order = np.argsort(xs.ravel(), kind="stable")
records = ev.from_columns(1000 + 10000 * xs.ravel()[order], xs.ravel()[order], ys.ravel()[order], np.ones(128))
lifetimes = ev.LifetimeEstimator_create((16, 8)).process(records)[0].ravel()
assert (lifetimes > 0).sum() > 60 and np.allclose(lifetimes[lifetimes > 0], 10000.0, rtol=0.02)
print("pip install: opencv_event %s from %s beside cv2 %s" % (ev.__version__, ev.__file__, cv2.__version__))
PY
