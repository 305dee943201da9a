#!/usr/bin/env bash
# The render farm for real: installs Debian's Slurm and MUNGE (and ffmpeg for the video step),
# starts a one-node cluster on this machine (munged, slurmctld and slurmd, all on 127.0.0.1, with
# their key, configuration, state and logs in a temporary folder), submits an animation of
# 8 frames as 4 array tasks with `voxflame animate --farm slurm --submit`, waits for it, and checks
# that the frames are byte for byte those of a local `voxflame animate` of the same range and that
# the finish job made the video. Then it deletes a frame, re-runs only the task that renders it as
# `voxflame animate --status` says, and checks again. Then the same for a still split into 64 chunks
# over 4 tasks (`voxflame render --farm slurm`), with each render method. Every daemon it started is stopped on exit,
# also when a check fails. Usage: scripts/test_farm.sh [VOXFLAME_BINARY] (run as root).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
voxflame="$(realpath "${1:-$root/build/app/voxflame}")"
[ -x "$voxflame" ] || { echo "test_farm.sh: no voxflame binary at $voxflame (build it first)" >&2; exit 1; }
[ "$(id -u)" -eq 0 ] || { echo "test_farm.sh: run as root (it starts slurmd and munged)" >&2; exit 1; }
start=$SECONDS
say() { echo "test_farm.sh ($((SECONDS - start)) s): $*"; }

packages=(slurm-wlm munge ffmpeg)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  say "installing ${missing[*]}"
  apt-get update >/dev/null
  # Debian's policy-rc.d (or the lack of an init system) keeps the packaged services from starting;
  # this script starts its own daemons with its own configuration.
  DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}" >/dev/null
fi

work="$(mktemp -d /tmp/voxflame-farm.XXXXXX)"
chmod 755 "$work"  # munged runs as the munge user and must reach its folder
pids=()
cleanup() {
  local status=$?
  if [ -n "${SLURM_CONF:-}" ] && [ -f "$SLURM_CONF" ]; then scancel --full --quiet --user=root 2>/dev/null || true; fi
  # Newest first: slurmd, slurmctld, then munged, which they authenticate through.
  for ((i = ${#pids[@]} - 1; i >= 0; i--)); do
    kill "${pids[i]}" 2>/dev/null || true
    for _ in $(seq 50); do kill -0 "${pids[i]}" 2>/dev/null || break; sleep 0.1; done
    kill -9 "${pids[i]}" 2>/dev/null || true
    wait "${pids[i]}" 2>/dev/null || true
  done
  # munged runs under runuser; should it outlive runuser, its pid file names it.
  if [ -s "$work/munge/munged.pid" ]; then kill "$(cat "$work/munge/munged.pid")" 2>/dev/null || true; fi
  if [ "$status" -ne 0 ]; then
    for log in "$work"/*.log "$work"/job/frames/*.log "$work"/job/*.chunks/*.log; do
      [ -f "$log" ] && { echo "--- $log"; tail -n 30 "$log"; }
    done
  fi
  rm -rf "$work"
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# MUNGE with its own key and socket, so a system munged (if any) is neither used nor disturbed.
# The key folder is the munge user's alone; the socket's must be open to every client.
mkdir -p "$work/munge" "$work/munge-socket"
dd if=/dev/urandom of="$work/munge/munge.key" bs=1024 count=1 status=none
chown -R munge:munge "$work/munge" "$work/munge-socket"
chmod 700 "$work/munge"
chmod 755 "$work/munge-socket"
chmod 400 "$work/munge/munge.key"
socket="$work/munge-socket/munge.socket"
runuser -u munge -- /usr/sbin/munged --foreground --key-file="$work/munge/munge.key" --socket="$socket" \
  --pid-file="$work/munge/munged.pid" --seed-file="$work/munge/seed" --log-file="$work/munge/munged.log" \
  2>"$work/munged.log" &
pids+=($!)
for _ in $(seq 100); do [ -S "$socket" ] && break; sleep 0.1; done
munge --socket="$socket" -n | unmunge --socket="$socket" >/dev/null
say "munged is up"

# A one-node cluster; every address is this machine's loopback.
node="$(hostname -s)"
cpus="$(nproc)"
mkdir -p "$work/state" "$work/spool"
export SLURM_CONF="$work/slurm.conf"
cat >"$SLURM_CONF" <<EOF
ClusterName=voxflame-ci
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=16817
SlurmdPort=16818
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$socket
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SwitchType=switch/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
NodeName=$node NodeAddr=127.0.0.1 NodeHostname=$node CPUs=$cpus State=UNKNOWN
PartitionName=ci Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
/usr/sbin/slurmctld -D -c -f "$SLURM_CONF" 2>"$work/slurmctld-stderr.log" &
pids+=($!)
/usr/sbin/slurmd -D -f "$SLURM_CONF" -N "$node" 2>"$work/slurmd-stderr.log" &
pids+=($!)
for _ in $(seq 300); do
  state="$(sinfo -h -n "$node" -o '%t' 2>/dev/null || true)"
  [ "$state" = idle ] && break
  sleep 0.2
done
[ "$state" = idle ] || { echo "test_farm.sh: the node did not come up (state '$state')" >&2; exit 1; }
say "slurmctld and slurmd are up; node $node ($cpus CPUs) is idle"

# Waits until none of these jobs is queued or running.
waitForJobs() {
  local deadline=$((SECONDS + 600))
  while [ -n "$(squeue -h -j "$1" -o '%i' 2>/dev/null)" ]; do
    [ $SECONDS -lt $deadline ] || { echo "test_farm.sh: jobs $1 did not finish in 10 minutes" >&2; squeue; exit 1; }
    sleep 1
  done
}

mkdir -p "$work/job"
cd "$work/job"
preset="$root/presets/aizawa-breathing.json"
options=(--frames 0-7 --width 160 --height 100 --points 2000000 --threads 1)
"$voxflame" animate "$preset" -o 'frames/%04d.png' "${options[@]}" --video farm.mp4 \
  --farm slurm --tasks 4 --partition ci --submit | tee submit.txt
render_job="$(sed -n 's/^submitted job \([0-9]*\) .*/\1/p' submit.txt)"
finish_job="$(sed -n 's/^submitted job [0-9]* (.*) and job \([0-9]*\) .*/\1/p' submit.txt)"
[ -n "$render_job" ] && [ -n "$finish_job" ] || { echo "test_farm.sh: no job ids in the output" >&2; exit 1; }
waitForJobs "$render_job,$finish_job"
say "jobs $render_job (4 tasks) and $finish_job ended"
for task in 0 1 2 3; do
  [ -f "frames/farm-render-${render_job}_$task.log" ] || { echo "test_farm.sh: task $task left no log" >&2; exit 1; }
done
cat frames/farm-finish-"$finish_job".log
grep -q "all 8 frames (0-7) are there" frames/farm-finish-"$finish_job".log
[ -s farm.mp4 ] || { echo "test_farm.sh: the finish job made no video" >&2; exit 1; }

"$voxflame" animate "$preset" -o 'local/%04d.png' "${options[@]}" >/dev/null 2>&1
for frame in 0 1 2 3 4 5 6 7; do
  name="$(printf '%04d.png' "$frame")"
  cmp "frames/$name" "local/$name" || { echo "test_farm.sh: frame $frame differs from the local render" >&2; exit 1; }
done
say "the 8 frames of the farm are byte-identical to the local render; the video is $(stat -c %s farm.mp4) bytes"

# A lost frame: --status names it and the task to run again; that task alone fills the gap.
rm frames/0005.png
set +e
"$voxflame" animate --status 'frames/%04d.png' | tee status.txt
status=${PIPESTATUS[0]}
set -e
[ "$status" -eq 1 ] || { echo "test_farm.sh: --status exited $status with a frame missing" >&2; exit 1; }
grep -q "missing 1: 5" status.txt
rerun="$(sed -n 's/^render them again with: //p' status.txt)"
[ "$rerun" = "sbatch --array=2 frames/farm-render.sbatch" ] || { echo "test_farm.sh: unexpected advice '$rerun'" >&2; exit 1; }
rerun_job="$(sbatch --parsable --array=2 frames/farm-render.sbatch)"
waitForJobs "${rerun_job%%;*}"
"$voxflame" animate --status 'frames/%04d.png'
cmp frames/0005.png local/0005.png
say "task 2 re-run alone as job ${rerun_job%%;*} restored frame 5, byte-identical"

# A still split over the farm, with each method: 4 tasks render 16 chunks each into the checkpoint
# folder and the finish job sums them. The image must be byte-identical to a local render with the
# same K; after a lost chunk, the task --status names re-renders it and the image is the same again.
stillFarm() {
  local method=$1 preset=$2
  local still="still-$method.png"
  local stillOptions=(--width 200 --height 120 --points 3000000 --grid 64 --method "$method" --chunks 64)
  "$voxflame" render "$preset" -o "$still" "${stillOptions[@]}" --farm slurm --tasks 4 --partition ci --submit \
    | tee "submit-$method.txt"
  local render finish
  render="$(sed -n 's/^submitted job \([0-9]*\) .*/\1/p' "submit-$method.txt")"
  finish="$(sed -n 's/^submitted job [0-9]* (.*) and job \([0-9]*\) .*/\1/p' "submit-$method.txt")"
  [ -n "$render" ] && [ -n "$finish" ] || { echo "test_farm.sh: no job ids for the $method still" >&2; exit 1; }
  waitForJobs "$render,$finish"
  cat "$still.chunks/farm-finish-$finish.log"
  grep -q "all 64 chunks are in" "$still.chunks/farm-finish-$finish.log"
  [ -s "$still" ] || { echo "test_farm.sh: the finish job wrote no $still" >&2; exit 1; }
  "$voxflame" render "$preset" -o "local-$still" "${stillOptions[@]}" >/dev/null 2>&1
  cmp "$still" "local-$still" || { echo "test_farm.sh: the $method still differs from the local render" >&2; exit 1; }
  say "the $method still of 4 farm tasks is byte-identical to the local render"

  local extension=vdb
  [ "$method" = points ] && extension=exr
  rm "$still.chunks/chunk-0037.$extension" "$still"
  set +e
  "$voxflame" render --status "$still" | tee "status-$method.txt"
  local status=${PIPESTATUS[0]}
  set -e
  [ "$status" -eq 1 ] || { echo "test_farm.sh: render --status exited $status with a chunk missing" >&2; exit 1; }
  grep -q "missing 1: 37" "status-$method.txt"
  local advice
  advice="$(sed -n 's/^render them again with: //p' "status-$method.txt")"
  [ "$advice" = "sbatch --array=2 $still.chunks/farm-render.sbatch" ] ||
    { echo "test_farm.sh: unexpected advice '$advice'" >&2; exit 1; }
  local again
  again="$(sbatch --parsable --array=2 "$still.chunks/farm-render.sbatch")"
  waitForJobs "${again%%;*}"
  local finishAgain
  finishAgain="$(sbatch --parsable "$still.chunks/farm-finish.sbatch")"
  waitForJobs "${finishAgain%%;*}"
  cmp "$still" "local-$still" || { echo "test_farm.sh: the $method still differs after the re-run" >&2; exit 1; }
  say "task 2 re-run alone restored chunk 37 of the $method still; the image is byte-identical again"
}
stillFarm points "$root/presets/flame-silk-bunny.json"
stillFarm volume "$root/presets/aizawa-orb.json"
say "passed"
