#!/usr/bin/python3
"""Projects the parallel efficiency of one evaluation of a fit on N nodes (docs/performance.md)
from a replay's per-trajectory costs and a measured exchange time.

    PYTHONPATH=build/python bench/mpi_projection.py REPLAY_CSV --seconds S --exchange E
        [--threads 16] [--copies 1]

REPLAY_CSV: `contactlaws replay ... --output DIR`'s DIR/replay.csv; a trajectory's cost is taken
proportional to its `samples` (a fixed timestep: steps per sample are alike), scaled so that the
costs sum to S, the measured CPU seconds of one evaluation (1 rank x 1 thread). E: the measured
seconds of one exchange (barrier + allgathers) per evaluation. --copies repeats the trajectories
(a larger data set of the same costs).

Each node is one rank with --threads threads; items go to ranks by k mod N (the first
evaluation) or longest first onto the least-loaded rank (the next ones: docs/cluster.md; the
library's own planner, `internal::LongestFirst`, through the Python module), and a
rank's threads take its items in index order, the next free thread the next item (as
Replay::Run does). Efficiency = total cost / (nodes x threads x (slowest rank + E)). The costs are
assumed to repeat exactly from one evaluation to the next (the plan's best case).
"""
import argparse
import csv
import heapq

from contactlaws._contactlaws import _longest_first  # the cluster's own plan


def rank_time(costs, threads):
    """Wall time of one rank: its items in order, each to the thread free first."""
    free = [0.0] * threads
    for c in costs:
        heapq.heappush(free, heapq.heappop(free) + c)
    return max(free)


def efficiency(costs, nodes, threads, exchange, owner):
    shares = [[c for k, c in enumerate(costs) if owner[k] == r] for r in range(nodes)]
    slowest = max(rank_time(s, threads) for s in shares)
    return sum(costs) / (nodes * threads * (slowest + (exchange if nodes > 1 else 0.0)))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("replay_csv")
    parser.add_argument("--seconds", type=float, required=True)
    parser.add_argument("--exchange", type=float, required=True)
    parser.add_argument("--threads", type=int, default=16)
    parser.add_argument("--copies", type=int, default=1)
    args = parser.parse_args()
    with open(args.replay_csv) as f:
        samples = [float(row["samples"]) for row in csv.DictReader(f)]
    scale = args.seconds / sum(samples)
    costs = [s * scale for s in samples] * args.copies
    print(f"{len(costs)} trajectories, {sum(costs):.3f} CPU s per evaluation, "
          f"exchange {args.exchange:.6f} s, {args.threads} threads per node")
    print("| nodes | k mod N | longest first |")
    print("|-------|---------|---------------|")
    for nodes in (1, 2, 16, 64):
        modulo = [k % nodes for k in range(len(costs))]
        planned = _longest_first(costs, nodes)
        print(f"| {nodes} | {efficiency(costs, nodes, args.threads, args.exchange, modulo):.2f} | "
              f"{efficiency(costs, nodes, args.threads, args.exchange, planned):.2f} |")


if __name__ == "__main__":
    main()
