# Cluster prediction for docs/cluster.md (issue 21): a model from measured figures, not a measurement.
import math
rate = 8.6e6            # particle-updates per CPU second and core (docs/experiments.md: T2P30 at 0.64 mm, 1 thread)
# bytes per process and step across one whole cut of T2P30 5x5x5 at paper resolution, 0.64 mm (measured, 2 processes,
# rigid plates: 532,817 points, 21,550 halo nodes; docs/cluster.md "Strong scaling")
halo_cut_064 = 1.638e6
node_cores = 32         # cores per node, one process per core
nic = 12.5e9            # bytes/s per node: InfiniBand HDR100 (100 Gb/s)
node_mem = 100e9        # bytes/s of a node's memory for intra-node MPI copies (shared memory)
latency = 2e-6          # s per message round over InfiniBand (published MPI latency 1-2 us)
rounds = 20             # halo and collective rounds per step (8 halo colours, ~12 collectives)
row_bytes = 8 + 4 * 3 * 8   # per grid block: key + reaction rows of 3 bodies, gathered by every process each step
sort_ns = 3e-9          # per key and comparison level: every process sorts every block key each step

def faces(parts):       # a cube-like part's faces shared with other parts, in units of its own face
    return 6 * (1 - parts ** (-1 / 3))

def case(name, points, steps, cell, cross):
    cut = halo_cut_064 * (0.64e-3 / cell) ** 2 * cross   # bytes across one whole cut
    blocks = points / 8 / 64 * 2.5                      # 8 points a cell, 64 nodes a block, x2.5 for the stencils' reach
    t1 = points / rate
    print(f"{name}: {points/1e6:.1f} M points, {steps} steps, ~{blocks/1e3:.0f}k blocks; one core {t1*steps/3600:.0f} h ({t1*1e3:.0f} ms/step)")
    for P in (8, 64, 512):
        comp = t1 / P
        halo = cut * faces(P) / P ** (2 / 3)            # per process and step
        nodes = max(1, P // node_cores)
        on_node = min(P, node_cores)
        halo_t = on_node * halo / node_mem + (cut * faces(nodes) / nodes ** (2 / 3) / nic if nodes > 1 else 0)
        lat = rounds * latency * math.log2(P)
        gather = blocks * row_bytes * (1 / nic if nodes > 1 else 0) + on_node * blocks * row_bytes / node_mem
        sort = blocks * math.log2(blocks) * sort_ns
        now = comp + halo_t + lat + gather + sort
        fix = comp + halo_t + lat
        print(f"| {name} | {P} | {comp*1e3:.1f} | {halo/1e6:.1f} | {halo_t*1e3:.1f} | {(gather+sort)*1e3:.1f} | {lat*1e3:.2f} | "
              f"{now*1e3:.0f} ms, {comp/now:.0%}, {now*steps/3600:.1f} h | {fix*1e3:.0f} ms, {comp/fix:.0%}, {fix*steps/3600:.1f} h |")

case("T2P30, cell 0.2 mm", 1.231e6 * (0.64 / 0.2) ** 3, int(60700 * 3.2), 0.2e-3, 1)
case("T2P30 10x10x10, cell 0.64 mm", 8 * 1.231e6, 2 * 60700, 0.64e-3, 4)
