#!/usr/bin/env python3
"""Design 2 of issue 21's cost (exploratory): is an effect that acts in the pour and the push
the sum of its push part (paired on the baseline's beds) and its preparation part (the packing
effect's signature at the matching pour friction)?  Per speed, with G of
../shared/formats/gap-metric.md (bin means, 0.25 cm, standard errors subtracted):
  direct     D: the effect's own knot (beds poured and pushed with it)
  superposed S_i = P_i + w (K_i - B_i): P the push part on baseline bed i, B the baseline's
             push on bed i, K the packing knot's push on its bed i, w = a / packing knot
  G(D, S) against G(D, B) (the signature's size) and G(D, P) (the push part alone).
usage: superpose.py CACHE PUSHPART_DIR MAGNITUDE PACKING_KNOT [W]   (W: the packing weight, default MAGNITUDE / PACKING_KNOT)
Exploratory (docs/gap.md, "Knots that earn their cost"): run after bench/gap_cost.sh, with the
sweep friction_push.sweep run into PUSHPART_DIR with the cache's baseline beds linked into its beds/.
"""
import glob, math, os, sys

cache, pdir, a, kpack = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
WOVR = float(sys.argv[5]) if len(sys.argv) > 5 else None
W = 0.25

def trace(path):
    z, F = [], []
    with open(path) as f:
        cols = None
        for line in f:
            if line.startswith('#') or not line.strip():
                continue
            p = line.strip().split(',')
            if cols is None:
                cols = p
                iz, iF = cols.index('z'), cols.index('F')
                continue
            z.append(float(p[iz])); F.append(float(p[iF]))
    return z, F

def bins(path, zmax):
    z, F = trace(path)
    n = int(round(zmax / W))
    s, c = [0.0] * n, [0] * n
    for zi, Fi in zip(z, F):
        if 0 < zi <= zmax:
            b = min(n - 1, int(zi / W))
            s[b] += Fi; c[b] += 1
    return [s[b] / c[b] if c[b] else float('nan') for b in range(n)]

def ens(rows):
    n = len(rows)
    m = [sum(r[b] for r in rows) / n for b in range(len(rows[0]))]
    e = [sum((r[b] - m[b]) ** 2 for r in rows) / (n - 1) / n if n > 1 else 0.0 for b in range(len(m))]
    return m, e

def G(A, B):
    (ma, ea), (mb, eb) = A, B
    num = sum((x - y) ** 2 - u - v for x, y, u, v in zip(ma, mb, ea, eb))
    return math.sqrt(max(0.0, num) / sum(x * x for x in ma))

def sweep_traces(d, v0):
    return sorted(p for p in glob.glob(os.path.join(d, 'traces', '*_v%s*.csv' % v0)) if not p.endswith('.done'))

mag = '%g' % a
direct_dir = os.path.join(cache, 'friction_%s' % mag)
print('speed  G(D,B) signature  G(D,P) push part alone  G(D,S) superposed   (2 beds a side)')
for v0 in ('50', '100', '200'):
    zmax = 4.0
    D = [bins(p, zmax) for p in sweep_traces(direct_dir, v0)]
    B = [bins(p, zmax) for p in sweep_traces(os.path.join(cache, 'baseline'), v0)]
    P = [bins(p, zmax) for p in sweep_traces(pdir, v0)]
    K = [bins(p, zmax) for p in sweep_traces(os.path.join(cache, 'packing_%g' % kpack), v0)]
    w = WOVR if WOVR is not None else a / kpack
    S = [[p + w * (k - b) for p, k, b in zip(Pi, Ki, Bi)] for Pi, Ki, Bi in zip(P, K, B)]
    print('%5s  %8.3f            %8.3f                %8.3f' % (v0, G(ens(D), ens(B)), G(ens(D), ens(P)), G(ens(D), ens(S))))
print('speed  G(P,B) push part  G(Kw,B) prep part (packing at w)  G(S,B)')
for v0 in ('50', '100', '200'):
    zmax = 4.0
    B = [bins(p, zmax) for p in sweep_traces(os.path.join(cache, 'baseline'), v0)]
    P = [bins(p, zmax) for p in sweep_traces(pdir, v0)]
    K = [bins(p, zmax) for p in sweep_traces(os.path.join(cache, 'packing_%g' % kpack), v0)]
    w = WOVR if WOVR is not None else a / kpack
    Kw = [[b + w * (k - b) for k, b in zip(Ki, Bi)] for Ki, Bi in zip(K, B)]
    S = [[p + w * (k - b) for p, k, b in zip(Pi, Ki, Bi)] for Pi, Ki, Bi in zip(P, K, B)]
    mB = ens(B)
    # paired: P - B per bed has bed noise cancelled; G against B's mean with B's error
    print('%5s  %8.3f          %8.3f                            %8.3f' % (v0, G(mB, ens(P)), G(mB, ens(Kw)), G(mB, ens(S))))
    Fm = [sum(x) / len(x) for x in zip(*[ens(X)[0] for X in (B, P, [bins(p, zmax) for p in sweep_traces(os.path.join(cache, 'friction_0.15'), v0)])])]
    print('       mean F over 0-4 cm: B %.4g  P %.4g  D %.4g  S %.4g  K %.4g' % tuple(sum(ens(X)[0]) / 16 for X in (B, P, [bins(p, zmax) for p in sweep_traces(os.path.join(cache, 'friction_0.15'), v0)], S, K)))
