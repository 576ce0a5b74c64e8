#!/usr/bin/env bash
# Installs granrepro's build and run dependencies from Debian 12 packages (run as root).
# Skips apt entirely when everything is already installed. apt's and dpkg's progress goes to a
# log file ($SETUP_LOG, default /tmp/granrepro-setup.log), shown only if the installation fails.
set -euo pipefail
packages=(build-essential cmake pkg-config ccache git
          libeigen3-dev libfftw3-dev libgsl-dev libhdf5-dev gnuplot-nox
          libcli11-dev libtoml11-dev nlohmann-json3-dev libgtest-dev libbenchmark-dev
          python3-h5py python3-numpy python3-matplotlib python3-pytest python3-jinja2 chromium
          python3-venv python3-wheel python3-setuptools
          libopenmpi-dev openmpi-bin)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  log=${SETUP_LOG:-${TMPDIR:-/tmp}/granrepro-setup.log}
  echo "setup: installing ${missing[*]} (apt log: $log; a few minutes on a fresh machine)" >&2
  export DEBIAN_FRONTEND=noninteractive
  if ! { apt-get update -qq && apt-get install -y -qq --no-install-recommends "${missing[@]}"; } > "$log" 2>&1; then
    tail -n 40 "$log" >&2
    echo "setup: apt-get failed; the whole log is $log" >&2
    exit 1
  fi
fi
