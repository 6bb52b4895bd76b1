#!/usr/bin/env bash
# `cmake --install BUILD --prefix PREFIX`, the README's one step, gives a
# lensrt command that runs from PREFIX/bin with its plugin (a .tif needs it),
# and a Python package that Python finds in the prefix's user site
# (PYTHONUSERBASE=PREFIX stands for ~/.local) with no PYTHONPATH.
set -euo pipefail
build=$1 source=$2
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix" > /dev/null
cd "$prefix"
env -u PYTHONPATH -u LENSRT_OIIO_PLUGIN "$prefix/bin/lensrt" render "$source/scenes/dof_row.gltf" --res 16x9 --spp 1 -q -o out.tif
test -s out.tif
env -u PYTHONPATH PYTHONUSERBASE="$prefix" /usr/bin/python3 -c \
  "import lensrt, sys; assert lensrt.__file__.startswith(sys.argv[1]), lensrt.__file__; print(lensrt.Lens('dgauss-50mm').info()['efl_mm'])" "$prefix"
echo "install test: ok"
