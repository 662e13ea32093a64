#!/usr/bin/env bash
# Build the exact-theory program CONTACT (E. A. H. Vollebregt, open source, Apache-2.0) from its
# public source at a pinned revision, with gfortran, LAPACK and OpenMP, for the scripts that make
# this project's exact-theory data (scripts/contact_reference.py, contact_ellipse_table.py,
# contact_gap_rows.py: they read CONTACT_EXE).
#
#   scripts/contact_build.sh [DEST]       clone, patch, build; the program is DEST/contact
#                                         (default DEST: build/contact, which git ignores)
#   CONTACT_SRC=DIR scripts/contact_build.sh
#                                         take the sources from an existing clone DIR instead
#                                         of GitHub (it must hold the pinned revision)
#
# CONTACT is written for Intel Fortran; scripts/contact_gfortran.patch makes its sources and
# makefile build with gfortran (GNU preprocessor and module flags, no MKL: FFTs are not used
# by the solvers we run; logical/integer comparisons and a few Intel extensions written out in
# standard Fortran; no ifport directory scan in the licence module, which this build does not
# use). The patch changes no numerics; the build uses -O2 (an -O3 build gave NaN at times).
# Check: a module-1 deck of the shared kinematic sample reproduces CONTACT's printed forces to
# every digit (doc/validation.md, "Exact-theory data").
set -euo pipefail

revision=d431cdbd125084c79bd59df83b4ac4c63c570ac9   # CONTACT main, 2025-07-23
url=https://github.com/eve70a/CONTACT.git
here=$(cd "$(dirname "$0")" && pwd)
dest=${1:-build/contact}
say() { echo "contact_build: $*" >&2; }

for tool in git gfortran make patch; do
  command -v "$tool" >/dev/null 2>&1 || { say "needs $tool (scripts/setup installs gfortran)"; exit 1; }
done
mkdir -p "$dest"
dest=$(cd "$dest" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/contact-build.XXXXXX")
trap 'rm -rf "$work"' EXIT

if [ -n "${CONTACT_SRC:-}" ]; then
  say "sources: $CONTACT_SRC at $revision"
  git -C "$CONTACT_SRC" archive "$revision" src | tar -x -C "$work"
else
  say "sources: $url at $revision"
  git init -q "$work/repo"
  git -C "$work/repo" fetch -q --depth 1 "$url" "$revision"
  git -C "$work/repo" archive FETCH_HEAD src | tar -x -C "$work"
fi

say "applying scripts/contact_gfortran.patch"
(cd "$work" && patch -s -p1 < "$here/contact_gfortran.patch")

say "building (make PROD=exe_l64)"
mkdir -p "$work/src/obj/linux64_exe" "$work/bin"
make -s -C "$work/src" PROD=exe_l64 -j "$(nproc)" > "$work/build.log" 2>&1 \
  || { tail -n 30 "$work/build.log" >&2; say "build failed"; exit 1; }
cp "$work/bin/contact_linux64" "$dest/contact"
say "built $dest/contact"
echo "export CONTACT_EXE=$dest/contact"
