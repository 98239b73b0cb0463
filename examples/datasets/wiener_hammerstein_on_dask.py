"""A 64-candidate H-W grid on the Wiener-Hammerstein benchmark's estimation data (samples 1-100 000),
selected twice: on the local cores (bonl.select's default executor) and on a two-worker Dask
LocalCluster (client.get_executor()). Writes both rankings and their wall times, and whether they
are identical."""

import argparse
import json
import pathlib
import time

import distributed

import bonl
from wiener_hammerstein import load


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--json", type=pathlib.Path, help="write the rankings and timings here")
    args = parser.parse_args()
    u, y = load()
    u, y = u[:100000], y[:100000]
    grid = bonl.grid(bonl.HammersteinWiener, na=[2, 4, 6, 8], nb=[1, 3, 5, 7], nk=[0, 1], r=[3], r1=[2, 3])
    assert len(grid) == 64

    def ranking(selection):
        return [{"orders": row.orders, "score": row.score, "error": row.error} for row in selection.table]

    start = time.perf_counter()
    local = bonl.select(grid, u, y)
    local_seconds = time.perf_counter() - start
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            start = time.perf_counter()
            remote = bonl.select(grid, u, y, executor=client.get_executor())
            remote_seconds = time.perf_counter() - start
    results = {
        "candidates": len(grid),
        "identical_rankings": ranking(local) == ranking(remote),
        "identical_best_theta": list(local.best.theta) == list(remote.best.theta),
        "local_seconds": round(local_seconds, 1),
        "local_cluster_seconds": round(remote_seconds, 1),
        "local": ranking(local),
        "local_cluster": ranking(remote),
    }
    print(f"64 candidates: local {local_seconds:.0f} s, LocalCluster(2) {remote_seconds:.0f} s, "
          f"identical rankings: {results['identical_rankings']}, identical best theta: {results['identical_best_theta']}")
    print(local)
    if args.json:
        args.json.parent.mkdir(parents=True, exist_ok=True)
        args.json.write_text(json.dumps(results, indent=1) + "\n")
    if not (results["identical_rankings"] and results["identical_best_theta"]):
        raise SystemExit("the rankings differ")


if __name__ == "__main__":
    main()
