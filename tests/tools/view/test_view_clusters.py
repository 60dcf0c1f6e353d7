"""ede-view's bonded-cluster colouring (?colour=clusters, tools/ede_view/clusters.hpp) over plain HTTP:

- on a square-well log the colour byte is each disk's cluster (0 alone, else 1 + (rank - 1) mod 255, rank 1
  the largest, ties by the lowest disk id), the same partition, ranks and legend (count, largest, alone) as
  a union-find computed here from ede-replay's exact positions with the nearest periodic image;
- across a periodic box's edge two disks are bonded, between walls the same two are not;
- a pair with only a shoulder never bonds, and in a mixture each pair of species has its own well;
- the same state gives the same bytes (deterministic colours);
- a log or live run without a well refuses the colouring with a reason, and says so in /api/log/info
  and /api/scene; a live square-well run is coloured by clusters.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from test_view_http import parse_frame  # noqa: E402
from viewlib import Server, check, make_log, replay_at  # noqa: E402


def clusters_here(rows, lx, ly, periodic, bond):
    """Ranks (0 alone, 1 the largest, ...) of every disk's cluster: all pairs, union-find, min image."""
    n = len(rows)
    parent = list(range(n))

    def root(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    xs = [float(r["x"]) for r in rows]
    ys = [float(r["y"]) for r in rows]
    for i in range(n):
        for j in range(i + 1, n):
            dx, dy = xs[j] - xs[i], ys[j] - ys[i]
            if periodic:
                dx -= lx * round(dx / lx)
                dy -= ly * round(dy / ly)
            if dx * dx + dy * dy < bond(rows[i]["species"], rows[j]["species"]) ** 2:
                a, b = root(i), root(j)
                parent[max(a, b)] = min(a, b)
    members = {}
    for i in range(n):
        members.setdefault(root(i), []).append(i)
    clusters = sorted((c for c in members.values() if len(c) >= 2), key=lambda c: (-len(c), c[0]))
    rank = [0] * n
    for r, c in enumerate(clusters, 1):
        for i in c:
            rank[i] = r
    return rank, clusters


def byte_of(rank):
    return 0 if rank == 0 else 1 + (rank - 1) % 255


def write_scene(path, text):
    with open(path, "w") as f:
        f.write(text)


EDGE_SCENE = """
seed = 1
[box]
size = [1.0, 1.0]
boundary = "{boundary}"
[[physics.steps]]
species = ["a", "a"]
radius = [0.03]
energy = [{energy}]
[[physics.steps]]
species = ["a", "b"]
radius = [0.05]
energy = [-1.0]
[[physics.steps]]
species = ["b", "b"]
radius = [0.025, 0.05]
energy = [0.5, -1.0]
[[species]]
name = "a"
radius = 0.01
[species.placement]
kind = "explicit"
positions = [[0.012, 0.5], [0.988, 0.5], [0.5, 0.5], [0.5, 0.2], [0.545, 0.2]]
[species.velocity]
kind = "speed"
speed = 0.001
[[species]]
name = "b"
radius = 0.01
[species.placement]
kind = "explicit"
positions = [[0.5, 0.54], [0.3, 0.8], [0.345, 0.8], [0.8, 0.8]]
[species.velocity]
kind = "speed"
speed = 0.001
[stop]
time = 0.001
"""


def frame(server, name, t):
    status, raw, _ = server.get(f"/api/log/frame?name=0:{name}&t={t}&colour=clusters&exact=1")
    check(status == 200, f"{name} at t = {t}: a clusters frame ({status}: {raw[:200]!r})")
    return raw, *parse_frame(raw)


def main():
    server = Server()
    try:
        wells = os.path.join(server.logs, "wells.ede")
        make_log(wells, scene="examples/square-well.toml",  # hot: the crystal breaks up
                 sets=["stop.time=2", "species[0].velocity.temperature=1.5", "log.keyframe_interval=20000"])
        gas = os.path.join(server.logs, "gas.ede")
        make_log(gas, sets=["species[0].count=100", "stop.time=0.5"])

        status, info = server.json("/api/log/info?name=0:wells.ede")
        check(status == 200 and info["clusters_unavailable"] == "", "a square-well log may be coloured by clusters")
        status, info = server.json("/api/log/info?name=0:gas.ede")
        check(status == 200 and "square well" in info["clusters_unavailable"],
              f"a hard-disk log says why not: {info['clusters_unavailable']!r}")
        status, answer = server.json("/api/log/frame?name=0:gas.ede&t=0&colour=clusters")
        check(status == 400 and "square well" in answer["error"], f"its frame is refused: 400, {answer['error']!r}")

        # The example's crystal at several times: the partition and ranks of a union-find over every pair.
        for t in ["0", "0.7", "end"]:
            raw, finfo, cols = frame(server, "wells.ede", t)
            rows = replay_at(wells, t)
            check(all(float(r["x"]) == cols["x"][i] and float(r["y"]) == cols["y"][i] for i, r in enumerate(rows)),
                  f"t = {t}: the exact frame is ede-replay's state")
            rank, clusters = clusters_here(rows, finfo["lx"], finfo["ly"], finfo["periodic"], lambda a, b: 0.03)
            c = finfo["colour"]
            check(c["by"] == "clusters" and list(cols["colour"]) == [byte_of(r) for r in rank],
                  f"t = {t}: every disk's byte is its cluster's rank ({len(clusters)} clusters)")
            check(c["clusters"] == len(clusters) and c["largest"] == (len(clusters[0]) if clusters else 1) and
                  c["alone"] == rank.count(0) and c["bond_radius"] == 0.03,
                  f"t = {t}: the legend: {c['clusters']} clusters, the largest {c['largest']} disks, {c['alone']} alone")
            check(frame(server, "wells.ede", t)[0] == raw, f"t = {t}: the same state, the same bytes")
        check(len(clusters) >= 3 and rank.count(0) >= 10 and len(clusters[0]) > len(clusters[-1]),
              f"at the end several clusters of different sizes and disks alone: a partition worth checking")

        # Disks 0 and 1 (a) are 0.024 apart across the edge of a periodic box: bonded by the a-a well (0.03),
        # not between walls, nor when a-a has a shoulder only; 3 and 4 (a) are 0.045 apart: not bonded;
        # 2 (a) and 5 (b), 0.04 apart, by the a-b well (0.05); 6 and 7 (b), 0.045 apart, by the b-b outer
        # well (0.05, a shoulder inside it at 0.025); 8 alone. Ranks: size, then the lowest id.
        cases = [("periodic", "-1.0", [1, 1, 2, 0, 0, 2, 3, 3, 0]),
                 ("walls", "-1.0", [0, 0, 1, 0, 0, 1, 2, 2, 0]),
                 ("periodic", "1.0", [0, 0, 1, 0, 0, 1, 2, 2, 0])]
        for k, (boundary, energy, want) in enumerate(cases):
            scene = os.path.join(server.dir, f"edge{k}.toml")
            write_scene(scene, EDGE_SCENE.format(boundary=boundary, energy=energy))
            make_log(os.path.join(server.logs, f"edge{k}.ede"), scene=scene)
            _, finfo, cols = frame(server, f"edge{k}.ede", "0")
            check(list(cols["colour"]) == want,
                  f"{boundary}, a-a step {energy}: bytes {list(cols['colour'])} (want {want})")

        # Live runs: the scene says whether its runs may be coloured by clusters; a run without a well
        # refuses the colouring, a square-well run is coloured by it.
        status, scene = server.json("/api/scene?name=0:square-well.toml")
        check(status == 200 and scene["clusters_unavailable"] == "", "/api/scene: the square-well scene has wells")
        status, scene = server.json("/api/scene?name=0:gas.toml")
        check(status == 200 and "square well" in scene["clusters_unavailable"], "/api/scene: the gas has none")
        status, st = server.json("/api/run/setup", {"scene": "0:gas.toml", "set": ["species[0].count=50"], "until": 1})
        check(status == 200 and "square well" in st["clusters_unavailable"], "a gas run: setup says why not")
        status, answer = server.json("/api/run/frame?colour=clusters")
        check(status == 400 and "square well" in answer["error"], "a gas run's clusters frame: 400 with the reason")
        status, st = server.json("/api/run/setup", {"scene": "0:square-well.toml", "until": 1})
        check(status == 200 and st["clusters_unavailable"] == "", "a square-well run: setup offers clusters")
        status, raw, _ = server.get("/api/run/frame?colour=clusters&exact=1")
        finfo, cols = parse_frame(raw)
        check(status == 200 and finfo["colour"]["by"] == "clusters" and finfo["colour"]["largest"] == 400,
              "its frame at t = 0: the crystal, one cluster of 400")
        status, answer = server.json("/api/run/frame?colour=rainbow")
        check(status == 400 and "clusters" in answer["error"], "a bad colour's message lists clusters")
    finally:
        server.close()


if __name__ == "__main__":
    main()
