#!/bin/bash
# usage: check_core_links.sh CONTROL BINARY...
# Fails unless CONTROL (linked to the PETSc library) depends on libpetsc and libmpi, and no
# BINARY (linked to gradfric_core only) depends on libpetsc, libmpi or any other MPI library.
set -u
forbidden='libpetsc|libmpi|libopen-pal|libopen-rte|libhdf5'
control=$1
shift
deps=$(ldd "$control") || { echo "ldd failed on $control"; exit 1; }
for lib in libpetsc libmpi; do
  grep -q "$lib" <<<"$deps" || { echo "control $control does not show $lib: the check would be blind"; exit 1; }
done
status=0
for binary in "$@"; do
  deps=$(ldd "$binary") || { echo "ldd failed on $binary"; exit 1; }
  if found=$(grep -E "$forbidden" <<<"$deps"); then
    echo "$binary links PETSc/MPI:"
    echo "$found"
    status=1
  else
    echo "$binary: no PETSc, no MPI"
  fi
done
exit $status
