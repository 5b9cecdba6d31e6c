#!/usr/bin/env bash
# mpirun -np N contactlaws replay|fit|compare|restitution against the program
# alone (--jobs 1): the same files and lines, byte for byte, and the same fit,
# whatever the ranks; more ranks than trajectories; one rank. Usage: mpi_test.sh CONTACTLAWS SOURCE_DIR
set -euo pipefail
cli="$1"
src="$2"
tmp="$(mktemp -d)"
trap '[ -n "${KEEP:-}" ] || rm -rf "$tmp"' EXIT
# as root under CI, on two cores: Open MPI refuses root and more ranks than
# cores unless told
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpi() { mpirun --oversubscribe -np "$@"; }

fail() { echo "FAIL: $*" >&2; exit 1; }
same() {  # same FILE1 FILE2: byte for byte
  cmp "$1" "$2" || fail "$2 differs from $1"
}

# the first 5 cube tosses (their cost differs ~3x), and the first 2
python3 "$src/scripts/cube_tosses_to_csv.py" "$src/data/cube_tosses/train.csv.gz" "$tmp/all.csv"
awk -F, 'NR == 1 || $1 < 5' "$tmp/all.csv" > "$tmp/five.csv"
awk -F, 'NR == 1 || $1 < 2' "$tmp/all.csv" > "$tmp/two.csv"
scene="$src/mjcf/cube_toss.xml"
replay=(replay "$scene" --start refit --timestep 6.756756756756757e-4)

# replay: -np 1, 2, 3 write the files and print the lines of --jobs 1
"$cli" "${replay[@]}" --data "$tmp/five.csv" --jobs 1 --output "$tmp/alone" > "$tmp/alone.txt"
for np in 1 2 3; do
  mpi "$np" "$cli" "${replay[@]}" --data "$tmp/five.csv" --jobs 1 --output "$tmp/np$np" \
    > "$tmp/np$np.txt"
  for f in replay.csv trajectories.csv; do same "$tmp/alone/$f" "$tmp/np$np/$f"; done
  sed "s#$tmp/np$np#$tmp/alone#g" "$tmp/np$np.txt" > "$tmp/np$np.renamed"
  same "$tmp/alone.txt" "$tmp/np$np.renamed"
  ls "$tmp/np$np" | grep -q tmp && fail "-np $np left a .tmp file"
done
# threads inside ranks: 2 ranks x 2 threads
mpi 2 "$cli" "${replay[@]}" --data "$tmp/five.csv" --jobs 2 --output "$tmp/np2j2" > /dev/null
same "$tmp/alone/replay.csv" "$tmp/np2j2/replay.csv"

# compare and restitution: -np 2 and 3 write the files and print the lines
# of --jobs 1 (rank 0 adds only its timing line on stderr)
ball="$src/mjcf/bouncing_ball.xml"
compare=(compare "$ball" --laws hertz,flores,hunt-crossley,gonthier --restitution 0.5,0.8
         --duration 0.2 --quiet --jobs 1)
restitution=(restitution "$ball" --laws flores,hunt-crossley --restitution 0.3,0.6,0.9 --quiet
             --jobs 1)
"$cli" "${compare[@]}" --output-dir "$tmp/compare_alone" > "$tmp/compare_alone.txt"
"$cli" "${restitution[@]}" --output "$tmp/restitution_alone.csv" > "$tmp/restitution_alone.txt"
for np in 2 3; do
  mpi "$np" "$cli" "${compare[@]}" --output-dir "$tmp/compare_np$np" > "$tmp/compare_np$np.txt" \
    2> "$tmp/compare_np$np.err"
  for f in trajectories.csv impacts.csv summary.csv; do
    same "$tmp/compare_alone/$f" "$tmp/compare_np$np/$f"
  done
  sed "s#$tmp/compare_np$np#$tmp/compare_alone#g" "$tmp/compare_np$np.txt" > "$tmp/compare_np$np.renamed"
  same "$tmp/compare_alone.txt" "$tmp/compare_np$np.renamed"
  grep -q "^contactlaws: timing: $np ranks x 1 thread" "$tmp/compare_np$np.err" ||
    fail "compare -np $np: no timing line: $(cat "$tmp/compare_np$np.err")"
  mpi "$np" "$cli" "${restitution[@]}" --output "$tmp/restitution_np$np.csv" \
    > "$tmp/restitution_np$np.txt"
  same "$tmp/restitution_alone.csv" "$tmp/restitution_np$np.csv"
  sed "s#restitution_np$np#restitution_alone#g" "$tmp/restitution_np$np.txt" \
    > "$tmp/restitution_np$np.renamed"
  same "$tmp/restitution_alone.txt" "$tmp/restitution_np$np.renamed"
done

# more ranks than trajectories: the idle rank says nothing, the same files
"$cli" "${replay[@]}" --data "$tmp/two.csv" --jobs 1 --output "$tmp/two_alone" > /dev/null
mpi 3 "$cli" "${replay[@]}" --data "$tmp/two.csv" --jobs 1 --output "$tmp/two_np3" \
  > /dev/null 2> "$tmp/two_np3.err"
same "$tmp/two_alone/replay.csv" "$tmp/two_np3/replay.csv"
grep -v "^contactlaws: timing: " "$tmp/two_np3.err" &&
  fail "idle ranks wrote: $(cat "$tmp/two_np3.err")"

# fit: 2 and 3 ranks give the fit of 1, to the bit (every file it writes),
# the trajectories of the first evaluation handed out by their durations,
# of every later one by the last one's seconds (five tosses on 3 ranks: with
# costs as their samples, 109 108 101 104 99, longest first puts 0 | 1,4 |
# 2,3 against k mod 3's 0,3 | 1,4 | 2); and the winner's profile
fit=(fit "$scene" --data "$tmp/five.csv" --start refit --timestep 6.756756756756757e-4
     --params restitution=0.3:0.9 --budget 4 --profile all --profile-points 3 --quiet)
"$cli" "${fit[@]}" --jobs 1 --output "$tmp/fit1" > /dev/null
# ranking.csv but its wall_seconds column, a time that differs run to run
without_wall() {
  awk -F, -v OFS=, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "wall_seconds") w = i }
    { out = ""; for (i = 1; i <= NF; ++i) if (i != w) out = out (out == "" && i == 1 ? "" : ",") $i; print out }' "$1"
}
without_wall "$tmp/fit1/ranking.csv" > "$tmp/ranking1.csv"
for np in 2 3; do
  mpi "$np" "$cli" "${fit[@]}" --jobs 1 --output "$tmp/fit_np$np" > /dev/null
  for f in errors.csv best_trajectories.csv best_tag.txt profile.csv; do
    same "$tmp/fit1/$f" "$tmp/fit_np$np/$f"
  done
  without_wall "$tmp/fit_np$np/ranking.csv" > "$tmp/ranking_np$np.csv"
  same "$tmp/ranking1.csv" "$tmp/ranking_np$np.csv"
done
# Ctrl-C (SIGINT to mpirun) during a fit: every rank stops at the same
# evaluation and rank 0 writes the best so far, as the program alone does
# (job control on: a background job of a script would ignore SIGINT)
set -m
# (three parameters on five tosses: a one-parameter fit of two tosses
# converges within a second, before the signal)
mpirun --oversubscribe -np 2 "$cli" fit "$scene" --data "$tmp/five.csv" --start refit --timestep 6.756756756756757e-4 \
  --params restitution=0.3:0.9,mu=0.1:0.9,stiffness=1e4:1e6:log --budget 1000 --jobs 1 --output "$tmp/fit_int" \
  > /dev/null 2> "$tmp/fit_int.err" &
launcher=$!
set +m
# once rank 0 reports its 10th evaluation (without --quiet)
for _ in $(seq 300); do grep -q "evaluation 10/" "$tmp/fit_int.err" && break; sleep 0.1; done
kill -INT "$launcher"
status=0
wait "$launcher" || status=$?
[ "$status" -ne 0 ] || fail "an interrupted fit left exit status 0: $(cat "$tmp/fit_int.err")"
grep -q "^contactlaws: interrupted: the best result so far is written" "$tmp/fit_int.err" ||
  fail "the interrupted fit did not write the best so far: $(cat "$tmp/fit_int.err")"
for f in ranking.csv errors.csv best_trajectories.csv best_tag.txt; do
  [ -s "$tmp/fit_int/$f" ] || fail "the interrupted fit left no $f"
done
grep -q interrupted "$tmp/fit_int/ranking.csv" || fail "ranking.csv does not say interrupted"

# a rank killed mid-run: the job ends non-zero, rank 0 names the rank and
# the trajectories it held in one line, and no output file appears (rank 0
# writes only by renaming a finished PATH.tmp, and removes it on the error).
# The 300 tosses are handed out before any is replayed by their measured
# durations (--start first: from the first sample to the last), longest
# first, each to the rank with the least so far: rank 1 holds the items
# this computes (in turn, k mod 2, it would hold 1,3,5,...)
held="$(python3 - "$tmp/all.csv" <<'PLAN'
import csv, sys
times = {}
for row in csv.DictReader(open(sys.argv[1])):
    times.setdefault(row["trajectory"], []).append(float(row["time"]))
cost = [t[-1] - t[0] for t in times.values()]
load, owner = [0.0, 0.0], [0] * len(cost)
for k in sorted(range(len(cost)), key=lambda k: -cost[k]):
    owner[k] = min(range(2), key=load.__getitem__)
    load[owner[k]] += cost[k]
held = [str(k) for k in range(len(cost)) if owner[k] == 1]
print(",".join(held[:20]) + (",..." if len(held) > 20 else ""))
PLAN
)"
catches_sigterm() {  # PID: bit 15 of its caught-signal mask
  local mask
  mask="$(awk '/^SigCgt:/ {print $2}' "/proc/$1/status" 2> /dev/null)"
  [ -n "$mask" ] && (( (16#$mask >> 14) & 1 ))
}
# killed at once (most likely while MPI_Init runs beside the reading: rank 0
# names every other rank) and 0.8 s later (computing: rank 0 names the
# rank that did not arrive); the 300 tosses take each rank over a second
for delay in 0 0.8; do
  status=0
  mpirun --oversubscribe -np 2 "$cli" replay "$scene" --start first \
    --timestep 6.756756756756757e-4 --data "$tmp/all.csv" --jobs 1 --output "$tmp/killed" \
    > /dev/null 2> "$tmp/killed.err" &
  launcher=$!
  # once both ranks run and catch SIGTERM (their stop handler is set): the
  # one started last
  for _ in $(seq 300); do
    ranks=($(pgrep -P "$launcher" -f "$cli" || true))
    if [ "${#ranks[@]}" -ge 2 ] && catches_sigterm "${ranks[0]}" && catches_sigterm "${ranks[1]}"; then
      break
    fi
    sleep 0.05
  done
  sleep "$delay"
  kill -9 "$(pgrep -P "$launcher" -f "$cli" | tail -1)"
  wait "$launcher" || status=$?
  [ "$status" -ne 0 ] || fail "a rank killed after ${delay} s left exit status 0"
  [ "$(grep -cF "contactlaws: exchange 1: rank 1 (items $held of 300) did not arrive" \
       "$tmp/killed.err")" = 1 ] ||
    fail "killed after ${delay} s: not one line names rank 1 and its items: $(cat "$tmp/killed.err")"
  [ -e "$tmp/killed/replay.csv" ] && fail "a killed job wrote replay.csv"
  ls "$tmp/killed" | grep -q tmp && fail "a killed job left a .tmp file"
done

# the launcher's count of ranks (read before MPI_Init returns) against MPI's:
# one line, the job ended
status=0
mpi 2 env OMPI_COMM_WORLD_SIZE=3 "$cli" "${replay[@]}" --data "$tmp/two.csv" --jobs 1 \
  > /dev/null 2> "$tmp/size.err" || status=$?
[ "$status" -ne 0 ] || fail "a wrong OMPI_COMM_WORLD_SIZE left exit status 0"
[ "$(grep -c "^contactlaws: the launcher gives" "$tmp/size.err")" = 1 ] &&
  grep -q "^contactlaws: the launcher gives rank 0 of 3 (OMPI_COMM_WORLD_RANK), MPI rank 0 of 2$" \
  "$tmp/size.err" || fail "no line for a wrong OMPI_COMM_WORLD_SIZE: $(cat "$tmp/size.err")"
echo "mpi_test: ok"
