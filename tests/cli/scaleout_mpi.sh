#!/usr/bin/env bash
# MPI end to end with Open MPI's mpirun (2 ranks on this machine); each MODE
# is one ctest entry of a few seconds:
#   models     2 ranks render the bits of one process for every camera model,
#              the full lens with --diffraction on, and with --flare on for a
#              lamp in frame
#   failures   a bad scene, the ID AOVs and flow (not sent), a rank without the scene or with another copy of
#              it, a rank killed mid-render: the job fails once, no output
#   resume     checkpoints of a crop written and resumed under MPI (and
#              across, with --diffraction on too) are bit-identical to an
#              uninterrupted render
#   interrupt  SIGINT/SIGTERM to the ranks or to mpirun: a valid, resumable
#              EXR with the samples done, bit-identical to a render of that spp
#   compare    lensrt compare under MPI writes the EXRs of one process
#   frames     --frames: whole frames to the ranks, each the bits of one
#              process's render; a rank that cannot load the scene fails it
#   adaptive   adaptive sampling (--noise-threshold): 2 ranks render the bits
#              of one process for every camera model, and a checkpoint
#              written under MPI resumes to them
# Usage: scaleout_mpi.sh MODE LENSRT SOURCE_DIR
set -euo pipefail
mode=$1 lensrt=$2 src=$3
dir=$(mktemp -d) && trap 'rm -rf "$dir"' EXIT
cd "$dir"
# Each job's session directory under this test's own: ctest runs two of these
# at once, and two mpiruns creating /tmp/ompi.HOST.UID together can fail
# with "File exists" (seen once in a CI run).
mkdir -p "$dir/ompi"
mpirun=(mpirun -np 2 --oversubscribe --allow-run-as-root --mca orte_tmpdir_base "$dir/ompi")
mpi=(timeout 60 "${mpirun[@]}")

fail() {
  echo "FAIL: $*"
  exit 1
}
same() {  # A B WHAT: bit-identical pixels
  idiff -q -fail 0 -failpercent 0 -hardfail 0 -warn 0 "$1" "$2" >/dev/null || fail "$3: $1 and $2 differ"
}
meta() {  # FILE KEY: a metadata value
  iinfo -v "$1" | sed -n "s/^ *$2: \"\(.*\)\"\$/\1/p"
}
# Runs rank 1 of the job in directory $1 (a node whose file system differs).
rank1_in() {
  local where=$1
  shift
  # shellcheck disable=SC2016
  "${mpi[@]}" sh -c 'if [ "$OMPI_COMM_WORLD_RANK" = 1 ]; then cd "$0"; fi; exec "$@"' "$where" "$@"
}
# The job must fail with status $1, exactly one lensrt error line matching $2, no output.
expect_failure() {
  local status=$1 pattern=$2 what=$3 got=$4
  [[ $got == "$status" ]] || { cat err; fail "$what: status $got, expected $status"; }
  if [[ $(grep -c 'lensrt: error:' err) != 1 ]] || ! grep -q "$pattern" err; then
    cat err
    fail "$what: expected one error line matching '$pattern'"
  fi
  [[ ! -e out.exr && ! -e out.exr.sums ]] || fail "$what: an output was written"
}

case $mode in
models)
  # shellcheck disable=SC2054
  base=(render "$src/scenes/cornell.gltf" --res 24x17 --spp 3 --seed 11 -q --aov depth,normal,albedo,variance)
  # The plain full lens last: the checkpoint below is compared with its one.exr.
  for cam in "--camera pinhole" "--camera thin --fstop 2" "--camera thick --lens dgauss-50mm" \
    "--camera lens --lens dgauss-50mm --fstop 8 --blades 7 --diffraction on" "--camera lens --lens dgauss-50mm"; do
    # shellcheck disable=SC2086
    "$lensrt" "${base[@]}" $cam -o one.exr
    # shellcheck disable=SC2086
    "${mpi[@]}" "$lensrt" "${base[@]}" $cam --tile-size 4 -o two.exr
    same one.exr two.exr "$cam: 2 ranks against 1 process"
    counts='lensrt:(spp|camera_samples|blocked_camera_rays|nan_samples):'
    [[ $(iinfo -v one.exr | grep -E "$counts") == "$(iinfo -v two.exr | grep -E "$counts")" ]] ||
      fail "$cam: the sample counts differ"
  done
  # --flare on with a lamp in frame: the camera paths and the light pass
  # (which the rank writing the image adds whole) give the bits of one process.
  # shellcheck disable=SC2054
  flare=(render "$src/scenes/point_light_plane.gltf" --res 24x24 --spp 3 --seed 11 -q --camera lens
    --lens dgauss-50mm --fstop 4 --focus 1 --flare on)
  "$lensrt" "${flare[@]}" -o one.exr
  "${mpi[@]}" "$lensrt" "${flare[@]}" --tile-size 4 -o two.exr
  same one.exr two.exr "--flare on: 2 ranks against 1 process"
  ;;

frames)
  # --frames under MPI: whole frames go to the ranks in turn, each frame the
  # bits of one process's --frame render (not a render shared by 2 ranks);
  # a rank that cannot read the scene fails the job once, before any frame.
  # shellcheck disable=SC2054
  base=(render "$src/scenes/propeller.gltf" --res 32x24 --spp 2 --seed 5 -q --fps 12 --shutter 1/50)
  "${mpi[@]}" "$lensrt" "${base[@]}" --frames 1:5:2 -o f.##.exr
  for f in 1 3 5; do
    "$lensrt" "${base[@]}" --frame $f -o one.exr
    same one.exr "f.0$f.exr" "--frames under MPI, frame $f"
    [[ -z $(meta "f.0$f.exr" lensrt:mpi_ranks) ]] || fail "frame $f was shared between ranks"
  done
  [[ ! -e f.02.exr && ! -e f.04.exr ]] || fail "--frames 1:5:2 wrote an even frame"
  # A motion-blurred frame (the propeller turns 30 degrees during the 1/50 s
  # shutter) shared by 2 ranks, and written to 1 spp under MPI and resumed
  # to 2 in one process: the bits of one process.
  "${mpi[@]}" "$lensrt" "${base[@]}" --frame 3 --tile-size 4 -o two.exr
  same f.03.exr two.exr "a motion-blurred frame on 2 ranks"
  # shellcheck disable=SC2054
  first=(render "$src/scenes/propeller.gltf" --res 32x24 --spp 1 --seed 5 -q --fps 12 --shutter 1/50)
  "${mpi[@]}" "$lensrt" "${first[@]}" --frame 3 --checkpoint 0.001 -o ck.exr
  "$lensrt" "${base[@]}" --frame 3 --resume ck.exr -o ck.exr
  same f.03.exr ck.exr "a motion-blurred frame checkpointed under MPI and resumed"
  cp "$src/scenes/propeller.gltf" . && mkdir elsewhere
  status=0 && rank1_in elsewhere "$lensrt" render propeller.gltf --res 8x8 --spp 1 -q --frames 0:3 \
    -o out.##.exr 2>err || status=$?
  [[ $status == 1 ]] || { cat err; fail "--frames, rank 1 without the scene: status $status, expected 1"; }
  [[ $(grep -c 'lensrt: error:' err) == 1 ]] && grep -q '^lensrt: error: rank 1 of 2: propeller.gltf: ' err ||
    { cat err; fail "--frames, rank 1 without the scene: expected one error line naming rank 1"; }
  ! ls out.*.exr elsewhere/out.*.exr >/dev/null 2>&1 || fail "--frames: a frame was written after a failure"
  ;;

adaptive)
  # shellcheck disable=SC2054
  base=(render "$src/scenes/cornell.gltf" --res 24x17 --spp 48 --min-spp 4 --noise-threshold 0.05 --seed 11 -q
    --aov variance)
  # The plain full lens last: the checkpoint below is compared with its one.exr.
  for cam in "--camera pinhole" "--camera thin --fstop 2" "--camera thick --lens dgauss-50mm" \
    "--camera lens --lens dgauss-50mm --fstop 8 --blades 7 --diffraction on" "--camera lens --lens dgauss-50mm"; do
    # shellcheck disable=SC2086
    "$lensrt" "${base[@]}" $cam -o one.exr
    # shellcheck disable=SC2086
    "${mpi[@]}" "$lensrt" "${base[@]}" $cam --tile-size 4 -o two.exr
    same one.exr two.exr "$cam: adaptive, 2 ranks against 1 process"
    counts='lensrt:(spp|camera_samples|samples_done):'
    [[ $(iinfo -v one.exr | grep -E "$counts") == "$(iinfo -v two.exr | grep -E "$counts")" ]] ||
      fail "$cam: the adaptive sample counts differ"
    [[ $(meta one.exr lensrt:spp) == "adaptive min=4 "* ]] || fail "$cam: lensrt:spp is $(meta one.exr lensrt:spp)"
  done
  # A checkpoint to 12 spp under MPI, resumed to 48 in one process.
  # shellcheck disable=SC2086
  "${mpi[@]}" "$lensrt" "${base[@]/48/12}" --camera lens --lens dgauss-50mm --checkpoint 0.001 -o ck.exr
  "$lensrt" "${base[@]}" --camera lens --lens dgauss-50mm --resume ck.exr -o ck.exr
  same one.exr ck.exr "adaptive: an MPI checkpoint resumed"
  ;;

failures)
  cp "$src/scenes/cornell.gltf" scene.gltf
  mkdir empty other
  # Another copy of the scene on rank 1's node: one light 1% brighter.
  sed 's/"emissiveStrength": 18.387/"emissiveStrength": 18.571/' scene.gltf >other/scene.gltf
  cmp -s scene.gltf other/scene.gltf && fail "the test's altered scene is not altered"
  job=(render scene.gltf --res 24x17 --spp 3 -q -o out.exr)

  # Every rank fails alike (a broken scene): its error once, as without MPI.
  echo '{' >broken.gltf
  status=0 && "${mpi[@]}" "$lensrt" render broken.gltf --res 24x17 -q -o out.exr 2>err || status=$?
  expect_failure 1 '^lensrt: error: broken.gltf: ' "a broken scene on every rank" $status

  # The ID AOVs' counts are not sent between ranks: refused once, before rendering.
  status=0 && "${mpi[@]}" "$lensrt" "${job[@]}" --aov crypto_object 2>err || status=$?
  expect_failure 2 '^lensrt: error: --aov: .*across 2 MPI ranks' "ID AOVs under MPI" $status
  # Nor are flow's sums.
  status=0 && "${mpi[@]}" "$lensrt" "${job[@]}" --aov flow 2>err || status=$?
  expect_failure 2 '^lensrt: error: --aov: flow .*across 2 MPI ranks' "flow under MPI" $status

  # Rank 1 cannot read the scene (its node does not have the file).
  status=0 && rank1_in empty "$lensrt" "${job[@]}" 2>err || status=$?
  expect_failure 1 '^lensrt: error: rank 1 of 2: scene.gltf: ' "rank 1 without the scene" $status

  # Rank 1 reads another scene under the same name: refused, never mixed in.
  status=0 && rank1_in other "$lensrt" "${job[@]}" 2>err || status=$?
  expect_failure 1 "^lensrt: error: rank 1 of 2: scene.gltf: this rank's render differs from rank 0's: the scene file differs" \
    "rank 1 with another scene" $status

  # Rank 1 is killed mid-render (the kernel's out-of-memory killer, a node
  # lost): the launcher names the rank and the signal, and nothing is written.
  status=0
  # shellcheck disable=SC2016
  "${mpi[@]}" sh -c 'if [ "$OMPI_COMM_WORLD_RANK" = 1 ]; then (sleep 2; kill -KILL $$) & fi; exec "$@"' \
    sh "$lensrt" render scene.gltf --res 64x48 --spp 1000000 -q -o out.exr 2>err || status=$?
  [[ $status != 0 && $status != 124 ]] || { cat err; fail "a killed rank: status $status"; }
  grep -q 'rank 1 .*signal 9' err || { cat err; fail "a killed rank: the rank and signal are not named"; }
  ! grep -q 'lensrt:' err || { cat err; fail "a killed rank: lensrt printed something"; }
  [[ ! -e out.exr && ! -e out.exr.sums ]] || fail "a killed rank: an output was written"
  ;;

resume)
  # shellcheck disable=SC2054
  # A crop, so that the region goes through the ranks and the checkpoints too.
  scene=(render "$src/scenes/cornell.gltf" --res 24x17 --crop 2,21,1,16 -q --aov depth,variance --camera lens
    --lens dgauss-50mm --tile-size 4)
  base=("${scene[@]}" --seed 5)
  "$lensrt" "${base[@]}" --spp 7 -o one.exr
  # Checkpointed under MPI (one checkpoint after each pass but the last).
  "${mpi[@]}" "$lensrt" "${base[@]}" --spp 3 --checkpoint 0.001 -o a.exr
  [[ $(meta a.exr lensrt:spp) == 3 && -e a.exr.sums ]] || fail "the MPI checkpoint has no 3 spp and sums"
  # Resuming with another seed is refused once, and the checkpoint is left as it was.
  cp a.exr a.before
  status=0 && "${mpi[@]}" "$lensrt" "${scene[@]}" --seed 6 --spp 7 --resume a.exr -o a.exr 2>err || status=$?
  if [[ $status != 1 || $(grep -c 'lensrt: error:' err) != 1 ]] || ! grep -q 'the seed differs' err; then
    cat err
    fail "resuming another seed under MPI: status $status"
  fi
  cmp -s a.exr a.before || fail "a refused resume touched the checkpoint"
  # Resumed under MPI.
  "${mpi[@]}" "$lensrt" "${base[@]}" --spp 7 --resume a.exr -o a.exr
  same one.exr a.exr "an MPI checkpoint resumed under MPI"
  [[ $(meta a.exr lensrt:spp) == 7 ]] || fail "the resumed render has not 7 spp"
  # A one-process checkpoint resumed under MPI.
  "$lensrt" "${base[@]}" --spp 2 --checkpoint 1000 -o b.exr
  "${mpi[@]}" "$lensrt" "${base[@]}" --spp 7 --resume b.exr -o b.exr
  same one.exr b.exr "a one-process checkpoint resumed under MPI"
  # --diffraction on (a bend and a wavelength per sample): checkpointed under
  # MPI, resumed in one process.
  diffraction=("${base[@]}" --fstop 8 --blades 7 --diffraction on)
  "$lensrt" "${diffraction[@]}" --spp 5 -o one.exr
  "${mpi[@]}" "$lensrt" "${diffraction[@]}" --spp 2 --checkpoint 0.001 -o c.exr
  "$lensrt" "${diffraction[@]}" --spp 5 --resume c.exr -o c.exr
  same one.exr c.exr "--diffraction on: an MPI checkpoint resumed"
  ;;

interrupt)
  base=(render "$src/scenes/cornell.gltf" --res 32x24 --seed 3 -q)
  # Starts a long render with checkpoints after every pass, waits for the
  # first (the render is under way), sends signal $2 to $1 (ranks, rank1 or
  # mpirun) and waits; sets $status.
  interrupt() {
    local who=$1 sig=$2 pid ranks
    shift 2
    rm -f i.exr i.exr.sums
    "${mpirun[@]}" "$@" "$lensrt" "${base[@]}" --spp 1000000 --checkpoint 0.001 -o i.exr 2>err &
    pid=$!
    for _ in $(seq 600); do [[ -e i.exr ]] && break; sleep 0.05; done
    [[ -e i.exr ]] || { kill -KILL $pid; fail "no checkpoint after 30 s"; }
    ranks=$(pgrep -P $pid)
    # shellcheck disable=SC2086
    case $who in
    ranks) kill -s "$sig" $ranks ;;
    rank1)
      for p in $ranks; do
        tr '\0' '\n' </proc/"$p"/environ | grep -qx OMPI_COMM_WORLD_RANK=1 && kill -s "$sig" "$p"
      done
      ;;
    mpirun) kill -s "$sig" $pid ;;
    esac
    status=0 && wait $pid || status=$?
  }
  # The image has the spp it says, and the bits of a render of that spp.
  check() {
    local what=$1 spp
    spp=$(meta i.exr lensrt:spp)
    [[ -e i.exr.sums && $spp -ge 1 && $spp -lt 1000000 ]] || fail "$what: spp '$spp' or no sums"
    [[ $(meta i.exr lensrt:camera_samples) == $((spp * 32 * 24)) ]] || fail "$what: camera_samples"
    "$lensrt" "${base[@]}" --spp "$spp" -o ref.exr
    same ref.exr i.exr "$what ($spp spp)"
  }
  # A scheduler's signal reaches every rank (Slurm's scancel, pre-emption).
  interrupt ranks INT
  [[ $status == 130 ]] || { cat err; fail "SIGINT to every rank: status $status"; }
  check "SIGINT to every rank"
  # A signal to one rank stops the whole job just as well.
  interrupt rank1 TERM
  [[ $status == 143 ]] || { cat err; fail "SIGTERM to rank 1: status $status"; }
  check "SIGTERM to rank 1"
  # Ctrl-C on mpirun: Open MPI sends the ranks SIGTERM after
  # odls_base_sigkill_timeout seconds and SIGKILL as long after that; mpirun
  # itself exits 1.
  interrupt mpirun INT --mca odls_base_sigkill_timeout 2
  [[ $status != 0 ]] || fail "SIGINT to mpirun: status 0"
  check "SIGINT to mpirun"
  ;;

compare)
  args=("$src/scenes/cornell.gltf" --lens dgauss-50mm --fstop 2.8 --res 24x17 --spp 3 --seed 2 -q)
  "$lensrt" compare "${args[@]}" -o one
  "${mpi[@]}" "$lensrt" compare "${args[@]}" --tile-size 4 -o two
  for model in pinhole thin thick lens; do
    same one/$model.exr two/$model.exr "compare's $model under MPI"
  done
  for file in contact-sheet.png report.json report.html diff-thin-vs-lens.png; do
    [[ -s two/$file ]] || fail "compare under MPI wrote no $file"
  done
  ;;

*) fail "unknown mode $mode" ;;
esac
echo PASS
