#!/usr/bin/env bash
# Installs the Debian packages the project needs (Debian 12 "bookworm"): compiler, CMake,
# CGAL 5.5 with Eigen, Boost, GMP, MPFR and TBB, doxygen, python3 (test scripts), rsvg-convert and
# pngquant (PNG pictures of the benchmark results), OpenMesh (a third FaceGraph model), pybind11,
# NumPy and pytest (the Python module), GNU parallel (the sharded batch recipe), Slurm and munge
# (the test slurm_batch: scripts/slurm_batch.sh runs the README's job array on a one-node Slurm;
# slurmctld and slurmd do not start on installation: they need /etc/slurm/slurm.conf), CHOLMOD
# (libsuitesparse-dev: the solver of large Tutte systems) with the single-threaded OpenBLAS
# (libopenblas0-serial: the supernodal factorization runs on BLAS, the reference BLAS is 1.5-2.4 times
# slower there, and a threaded BLAS loses several times over beside other busy processes, as in batch
# runs), and libcgal-demo for its real meshes (without its recommended packages: it would pull in Qt).
# Runs apt-get only when a package is missing; as a non-root user it uses sudo.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive

packages=(libcgal-dev libeigen3-dev libboost-dev libgmp-dev libmpfr-dev libtbb-dev doxygen cmake make g++ python3 librsvg2-bin pngquant
          libopenmesh-dev pybind11-dev python3-dev python3-numpy python3-pytest parallel slurm-wlm munge
          libsuitesparse-dev libopenblas0-serial)
demo_packages=(libcgal-demo)

missing=()
for p in "${packages[@]}" "${demo_packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all Debian packages are installed"
  exit 0
fi
echo "setup: installing ${missing[*]}"

sudo=()
if [ "$(id -u)" -ne 0 ]; then sudo=(sudo env DEBIAN_FRONTEND=noninteractive); fi
"${sudo[@]}" apt-get update
"${sudo[@]}" apt-get install -y --no-install-recommends "${packages[@]}"
"${sudo[@]}" apt-get install -y --no-install-recommends "${demo_packages[@]}"
