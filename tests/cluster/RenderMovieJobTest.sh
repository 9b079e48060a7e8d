#!/usr/bin/env bash
# The cluster job script share/cluster/render-movie.sbatch, run as Slurm would run it with three
# tasks (a stand-in srun runs them one after another with SLURM_PROCID and SLURM_LOCALID), must
# write the same pictures as one process rendering every frame, and each task must report the
# EGL device its local rank chose:
#   RenderMovieJobTest.sh <osgglyphviewer> <trajectory> <work dir>
set -euo pipefail
viewer=$(realpath "$1") trajectory=$(realpath "$2") work=$(realpath -m "$3")
script="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)/share/cluster/render-movie.sbatch"
rm -rf "$work" && mkdir -p "$work/bin" && cd "$work"
# A copy: the viewer keeps a trajectory's frame index beside it.
cp "$trajectory" . && trajectory=$work/$(basename "$trajectory")
cat >bin/srun <<'SRUN'
#!/usr/bin/env bash
shift # --kill-on-bad-exit=1
for ((t = 0; t < SLURM_NTASKS; ++t)); do SLURM_PROCID=$t SLURM_LOCALID=$t "$@" || exit 1; done
SRUN
chmod +x bin/srun
fail() { echo "RenderMovieJobTest: $*" >&2; exit 1; }

export VIEWER=$viewer SIZE="96 72"
PATH=$work/bin:$PATH SLURM_JOB_ID=1 SLURM_NTASKS=3 bash "$script" "$trajectory" tasks.mp4 >tasks.log 2>&1 ||
    { cat tasks.log; fail "the job failed"; }
bash "$script" "$trajectory" alone.mp4 >alone.log 2>&1 || { cat alone.log; fail "the job failed in one process"; }

for task in 0 1 2; do
    grep -q "^\[task $task\] osgglyphviewer: OpenGL through EGL device 0: .*SLURM_LOCALID=$task of 1 EGL device" tasks.log ||
        { cat tasks.log; fail "task $task does not report the device it chose"; }
done
frames=$(ls alone-pictures/frame*.png | wc -l)
((frames == 6)) || fail "$frames pictures of one process, expected 6"
for picture in alone-pictures/frame*.png; do
    cmp -s "$picture" "tasks-pictures/$(basename "$picture")" || fail "$(basename "$picture") differs between 3 tasks and 1"
done
[[ -s tasks.mp4 && -s alone.mp4 ]] || fail "no movie"
echo "RenderMovieJobTest: 3 tasks and 1 process wrote the same $frames pictures"
