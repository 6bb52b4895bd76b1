#!/usr/bin/env bash
# MPI end to end: `mpirun -np 2` renders the bits of one process for every
# camera model, and a rank that fails in its set-up fails the job once.
# Usage: scaleout_mpi.sh LENSRT SOURCE_DIR
set -euo pipefail
lensrt=$1 src=$2
dir=$(mktemp -d) && trap 'rm -rf "$dir"' EXIT
mpi=(mpirun -np 2 --oversubscribe --allow-run-as-root)
base=(render "$src/scenes/cornell.gltf" --res 24x17 --spp 3 --seed 11 -q --aov depth,normal,albedo,variance)
for cam in "--camera pinhole" "--camera thin --fstop 2" "--camera thick --lens dgauss-50mm" \
           "--camera lens --lens dgauss-50mm"; do
  # shellcheck disable=SC2086
  "$lensrt" "${base[@]}" $cam -o "$dir/one.exr"
  # shellcheck disable=SC2086
  timeout 60 "${mpi[@]}" "$lensrt" "${base[@]}" $cam --tile-size 4 -o "$dir/two.exr"
  idiff -q -fail 0 -failpercent 0 -hardfail 0 -warn 0 "$dir/one.exr" "$dir/two.exr" >/dev/null ||
    { echo "FAIL: $cam: 2 ranks differ from 1 process"; exit 1; }
done
# A bad scene: one error line, status 1, no output.
echo '{' >"$dir/bad.gltf"
if timeout 60 "${mpi[@]}" "$lensrt" render "$dir/bad.gltf" -o "$dir/bad.exr" 2>"$dir/err"; then
  echo "FAIL: a bad scene under MPI exited 0"; exit 1
fi
[[ $(grep -c 'lensrt: error:' "$dir/err") == 1 && ! -e "$dir/bad.exr" ]] ||
  { echo "FAIL: a bad scene under MPI:"; cat "$dir/err"; exit 1; }
echo PASS
