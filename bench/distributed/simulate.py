#!/usr/bin/env python3
"""Predicts how a distributed render scales past the ranks this machine has.

Replays the per-tile costs of a real render (`zeroset render --tile-log`)
through a discrete-event model of zeroset's protocol (apps/zeroset/distributed/):

* rank 0 hands out tiles in order, keeping IN_FLIGHT per thread at every
  rank (itself included); each traced tile goes back to rank 0, which
  answers with the next tile;
* a rank's threads trace tiles at the logged cost (thread-seconds measured
  here, on ranks like this machine's);
* a message takes LATENCY plus its bytes over BANDWIDTH, and rank 0's link
  carries one message at a time (the gather);
* rank 0's loop handles one message at a time, each for SERVICE seconds
  (unpack, place the pixels, send the next tile), and looks for messages
  every POLL seconds while it waits for its own tiles; a worker likewise.

Prints, per rank count, the predicted time, the efficiency against one
rank, and what limits it: rank 0's loop or link (utilisation near 1), or
the granularity of tiles (the last tiles finishing while other ranks idle).

Usage: simulate.py TILES.csv [--threads 2] [--latency-us 0.5] [--bandwidth-mbps 5000]
                            [--service-us 3] [--poll-us 200] [--pixel-bytes 12]
                            [--ranks 1,2,4,...]
"""
import argparse
import csv
import heapq
import sys


def load_costs(path):
    """The tiles of the log in the order rank 0 hands them out (frame, then reading order)."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"{path}: no tiles")
    rows.sort(key=lambda r: (int(r["frame"]), int(r["y0"]), int(r["x0"])))
    return [(float(r["seconds"]), int(r["width"]) * int(r["height"])) for r in rows]


def simulate(tiles, ranks, threads, in_flight, latency, bandwidth, service, poll, pixel_bytes):
    """The makespan of the job, and rank 0's loop and link utilisation."""
    header = 200  # bytes of a tile result besides its pixels
    events = []  # (time, order, kind, data)
    order = 0

    def push(t, kind, data):
        nonlocal order
        heapq.heappush(events, (t, order, kind, data))
        order += 1

    queues = [[] for _ in range(ranks)]  # tiles waiting at each rank
    idle = [threads] * ranks
    outstanding = [0] * ranks
    next_tile = 0
    loop_free = 0.0  # when rank 0's loop is next free
    link_free = 0.0  # when rank 0's incoming link is next free
    loop_busy = link_busy = 0.0
    done = 0
    end = 0.0

    def hand_out(rank, now):
        """Rank 0 sends tiles until the rank has its in-flight share; returns when the loop is free."""
        nonlocal next_tile, loop_busy
        t = now
        while outstanding[rank] < in_flight * threads and next_tile < len(tiles):
            outstanding[rank] += 1
            t += service / 4  # packing and posting a work message
            loop_busy += service / 4
            arrival = t if rank == 0 else t + latency + 16 / bandwidth
            push(arrival, "work", (rank, next_tile))
            next_tile += 1
        return t

    t = 0.0
    for rank in list(range(1, ranks)) + [0]:
        t = hand_out(rank, t)
    loop_free = t
    while events:
        now, _, kind, data = heapq.heappop(events)
        if kind == "work":
            rank, tile = data
            queues[rank].append(tile)
            start_threads(rank, now, queues, idle, tiles, push)
        elif kind == "traced":
            rank, tile = data
            idle[rank] += 1
            start_threads(rank, now, queues, idle, tiles, push)
            # The worker notices the tile at its next poll, then sends it.
            sent = now + (0.0 if rank == 0 else poll / 2)
            if rank == 0:
                push(sent + poll / 2, "arrived", data)
            else:
                size = header + pixel_bytes * tiles[tile][1]
                arrival = max(sent + latency, link_free) + size / bandwidth
                link_busy += size / bandwidth
                link_free = arrival
                push(arrival, "arrived", data)
        elif kind == "arrived":
            rank, tile = data
            begin = max(now, loop_free)
            loop_free = begin + service
            loop_busy += service
            outstanding[rank] -= 1
            done += 1
            end = max(end, loop_free)
            loop_free = hand_out(rank, loop_free)
    assert done == len(tiles), (done, len(tiles))
    return end, loop_busy / end, link_busy / end


def start_threads(rank, now, queues, idle, tiles, push):
    while idle[rank] > 0 and queues[rank]:
        tile = queues[rank].pop(0)
        idle[rank] -= 1
        push(now + tiles[tile][0], "traced", (rank, tile))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("log")
    p.add_argument("--threads", type=int, default=2, help="threads per rank (default 2, as here)")
    p.add_argument("--in-flight", type=int, default=2, help="tiles in flight per thread (zeroset's: 2)")
    p.add_argument("--latency-us", type=float, default=0.5)
    p.add_argument("--bandwidth-mbps", type=float, default=5000.0)
    p.add_argument("--service-us", type=float, default=3.0)
    p.add_argument("--poll-us", type=float, default=200.0, help="zeroset's polling pause (200 µs)")
    p.add_argument("--pixel-bytes", type=int, default=12, help="per pixel sent: 12 (RGB floats), 28 with EXR layers")
    p.add_argument("--ranks", default="1,2,4,8,16,32,64,128,256,512,1024")
    a = p.parse_args()
    tiles = load_costs(a.log)
    total = sum(c for c, _ in tiles)
    print(f"{a.log}: {len(tiles)} tiles, {total:.2f} thread-s; {a.threads} threads per rank, "
          f"latency {a.latency_us} us, bandwidth {a.bandwidth_mbps} MB/s, service {a.service_us} us, poll {a.poll_us} us")
    print("| ranks | predicted s | speed-up | efficiency | tiles per thread | rank 0 loop busy | rank 0 link busy | limit |")
    print("| ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |")
    one = None
    for ranks in [int(r) for r in a.ranks.split(",")]:
        end, loop, link = simulate(tiles, ranks, a.threads, a.in_flight, a.latency_us * 1e-6,
                                   a.bandwidth_mbps * 1e6, a.service_us * 1e-6, a.poll_us * 1e-6, a.pixel_bytes)
        one = one or end
        efficiency = one / (ranks * end)
        per_thread = len(tiles) / (ranks * a.threads)
        ideal = total / (ranks * a.threads)
        if loop > 0.8:
            limit = "rank 0's loop"
        elif link > 0.8:
            limit = "rank 0's link (gather)"
        elif efficiency < 0.8 and per_thread < 20:
            limit = "tile granularity"
        elif efficiency < 0.8:
            limit = f"tail and latency (ideal {ideal:.3f} s)"
        else:
            limit = "-"
        print(f"| {ranks} | {end:.3f} | {one / end:.1f} | {efficiency:.2f} | {per_thread:.1f} | {loop:.2f} | {link:.2f} | {limit} |")


if __name__ == "__main__":
    main()
