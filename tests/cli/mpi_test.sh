#!/usr/bin/env bash
# mpirun -np N contactlaws replay|fit against the program alone (--jobs 1):
# the same files, byte for byte, and the same fit, whatever the ranks; more
# ranks than trajectories; one rank. Usage: mpi_test.sh CONTACTLAWS SOURCE_DIR
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

# more ranks than trajectories: the idle rank says nothing, the same files
"$cli" "${replay[@]}" --data "$tmp/two.csv" --jobs 1 --output "$tmp/two_alone" > /dev/null
mpi 3 "$cli" "${replay[@]}" --data "$tmp/two.csv" --jobs 1 --output "$tmp/two_np3" \
  > /dev/null 2> "$tmp/two_np3.err"
same "$tmp/two_alone/replay.csv" "$tmp/two_np3/replay.csv"
[ -s "$tmp/two_np3.err" ] && fail "idle ranks wrote: $(cat "$tmp/two_np3.err")"

# fit: 2 ranks give the fit of 1, to the bit (every file it writes)
fit=(fit "$scene" --data "$tmp/two.csv" --start refit --timestep 6.756756756756757e-4
     --params restitution=0.3:0.9 --budget 4 --quiet)
"$cli" "${fit[@]}" --jobs 1 --output "$tmp/fit1" > /dev/null
mpi 2 "$cli" "${fit[@]}" --jobs 1 --output "$tmp/fit2" > /dev/null
for f in errors.csv best_trajectories.csv best_tag.txt; do same "$tmp/fit1/$f" "$tmp/fit2/$f"; done
# ranking.csv but its wall_seconds column (the 11th), a time that differs run to run
for n in 1 2; do cut -d, -f1-10,12- "$tmp/fit$n/ranking.csv" > "$tmp/ranking$n.csv"; done
same "$tmp/ranking1.csv" "$tmp/ranking2.csv"
# a rank killed mid-run: the job ends non-zero, mpirun names the rank, and no
# output file appears (rank 0 writes only by renaming a finished PATH.tmp)
awk -F, 'NR == 1 || $1 < 40' "$tmp/all.csv" > "$tmp/forty.csv"
status=0
mpirun --oversubscribe -np 2 "$cli" "${replay[@]}" --data "$tmp/forty.csv" --jobs 1 --output "$tmp/killed" \
  > /dev/null 2> "$tmp/killed.err" &
launcher=$!
# once both ranks run: the one started last
for _ in $(seq 50); do [ "$(pgrep -P "$launcher" -f "$cli" | wc -l)" -ge 2 ] && break; sleep 0.1; done
pgrep -a -P "$launcher" >&2
kill -9 "$(pgrep -P "$launcher" -f "$cli" | tail -1)"
wait "$launcher" || status=$?
[ "$status" -ne 0 ] || fail "a killed rank left exit status 0"
grep -q "rank 1" "$tmp/killed.err" || fail "no line names rank 1: $(cat "$tmp/killed.err")"
[ -e "$tmp/killed/replay.csv" ] && fail "a killed job wrote replay.csv"
echo "mpi_test: ok"
